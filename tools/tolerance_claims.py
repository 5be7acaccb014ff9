#!/usr/bin/env python3
# tools/tolerance_claims.py SCALECERT DIR: in DIR, scene.json (two 1,000-vertex near-spheres) and
# claims.json, 1,000 distance claims with closest points as a floating-point program writes them:
# the exact closest points (from SCALECERT certify-fp's report) rounded to doubles, and their
# distance in doubles. docs/performance.md, "Tolerances", times certify-fp on them.
import json, math, os, random, subprocess, sys
from fractions import Fraction as F
random.seed(7)
scalecert = os.path.abspath(sys.argv[1])
os.chdir(sys.argv[2])
def sphere(c, r, n):
    pts = []
    for _ in range(n):
        z = random.uniform(-1, 1); t = random.uniform(0, 2 * math.pi); s = math.sqrt(1 - z * z)
        pts.append([round(c[0] + r * s * math.cos(t), 6), round(c[1] + r * s * math.sin(t), 6), round(c[2] + r * z, 6)])
    return pts
scene = {"P1": {"vertices": [[str(F(x).limit_denominator(10**6)) for x in p] for p in sphere((0, 0, 0), 1, 1000)], "seed": [0, 0, 0]},
         "P2": {"vertices": [[str(F(x).limit_denominator(10**6)) for x in p] for p in sphere((3, 0.5, 0.2), 1, 1000)], "seed": [3, "1/2", "1/5"]},
         "I1": ["1/2", 2], "I2": ["1/2", 2]}
json.dump(scene, open("scene.json", "w"))
pairs = [(random.uniform(0.5, 1.3), random.uniform(0.5, 1.3)) for _ in range(1000)]
claims = [{"kind": "distance", "rho1": a, "rho2": b, "value": 1.0} for a, b in pairs]
json.dump({"format": "scalecert-claims-1", "claims": claims}, open("probe.json", "w"))
r = json.loads(subprocess.run([scalecert, "certify-fp", "scene.json", "probe.json", "--json"], capture_output=True, text=True).stdout)
out = []
for (a, b), c in zip(pairs, r["claims"]):
    p = [float(F(x)) for x in c["exact_closest_P1"]]; q = [float(F(x)) for x in c["exact_closest_P2"]]
    d = math.dist(p, q)
    out.append({"kind": "distance", "rho1": a, "rho2": b, "value": d, "closest": [p, q]})
json.dump({"format": "scalecert-claims-1", "claims": out}, open("claims.json", "w"))
