#!/usr/bin/env python3
"""A robot of 1,000 spheres along a 7-link arm against a 1,000-point hull, as a scene file, and 200
claims at 100 poses of the hull (a verdict and a distance each, as a planner would state them):
the inputs of docs/performance.md's certificate figures for parts with radii. Deterministic.

    tools/robot_scene.py OUT_DIR     # writes OUT_DIR/robot.json and OUT_DIR/robot_claims.json
"""
import json
import math
import os
import random
import sys


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: tools/robot_scene.py OUT_DIR")
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    rng = random.Random(5)
    joints = [(0.0, 0.0, 0.0)]
    for _ in range(7):
        d = (rng.uniform(-1, 1), rng.uniform(-1, 1), 0.5 + abs(rng.uniform(-1, 1)))
        n = math.sqrt(sum(x * x for x in d))
        joints.append(tuple(joints[-1][i] + 0.4 * d[i] / n for i in range(3)))
    centres, radii = [], []
    for k in range(1000):
        s = 7.0 * k / 1000
        link = int(s)
        a, b = joints[link], joints[link + 1]
        centres.append([a[i] + (s - link) * (b[i] - a[i]) for i in range(3)])
        radii.append(rng.uniform(0.03, 0.06))
    hull = []
    for _ in range(1000):
        x, y, z = (rng.gauss(0, 1) for _ in range(3))
        n = math.sqrt(x * x + y * y + z * z)
        hull.append([0.3 * x / n, 0.2 * y / n, 0.15 * z / n])
    scene = {"P1": {"spheres": {"centres": centres, "radii": radii}}, "P2": {"vertices": hull, "seed": [0, 0, 0]}}
    claims = []
    for _ in range(100):
        c = rng.choice(centres)
        t = [c[i] + 0.35 * rng.uniform(-1, 1) for i in range(3)]
        pose = [[1, 0, 0, t[0]], [0, 1, 0, t[1]], [0, 0, 1, t[2]]]
        claims.append({"kind": "verdict", "rho1": 1, "rho2": 1, "verdict": "separated", "pose2": pose})
        claims.append({"kind": "distance", "rho1": 1, "rho2": 1, "value": 0.01, "pose2": pose})
    with open(os.path.join(out, "robot.json"), "w") as f:
        json.dump(scene, f)
    with open(os.path.join(out, "robot_claims.json"), "w") as f:
        json.dump({"format": "scalecert-claims-1", "claims": claims}, f)


if __name__ == "__main__":
    main()
