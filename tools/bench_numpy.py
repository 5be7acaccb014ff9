#!/usr/bin/env python3
"""The typed claim API from numpy against the same claims as a claims file's text, in one run.

    PYTHONPATH=build/python /usr/bin/python3 tools/bench_numpy.py [--reps N]

Two 1,000-point near-spheres (integer points within a ball of radius 10^6, the second offset by
3·10^6 along x); 1,000 claims at random pairs of doubles in [1/2, 2]: 250 verdicts, 250
separating planes, 250 distances and 250 penetration depths. The same claims are judged twice on
the same Scene, after one warm-up call (the engine's models are built once, in neither time):
  - typed: Scene.certify(kind, rho1, rho2, ...) with numpy arrays, one call a kind;
  - text:  Scene.certify_fp(TEXT), TEXT the scalecert-claims-1 file of the same claims (floats
           written with repr, so each is the same double).
Prints the best of --reps runs of each and the ratio typed / text (target: <= 1).
"""
import argparse
import json
import sys
import time

import numpy as np
import scalecert


def near_sphere(rng, n, radius, offset):
    v = rng.normal(size=(n, 3))
    v = np.rint(v / np.linalg.norm(v, axis=1)[:, None] * radius).astype(np.int64)
    return (v + np.array(offset, dtype=np.int64)).tolist()


def best(f, reps):
    t = float("inf")
    for _ in range(reps):
        t0 = time.perf_counter()
        f()
        t = min(t, time.perf_counter() - t0)
    return t


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--reps", type=int, default=3)
    args = ap.parse_args()
    rng = np.random.default_rng(7)
    R = 10**6
    s = scalecert.Scene(near_sphere(rng, 1000, R, (0, 0, 0)), near_sphere(rng, 1000, R, (3 * R, R // 10, 0)),
                        ("1/2", "2"), ("1/2", "2"))
    n = 250
    r = {k: (rng.uniform(0.5, 2, n), rng.uniform(0.5, 2, n)) for k in ("verdict", "plane", "distance", "depth")}
    normals = np.column_stack([np.ones(n), rng.uniform(-0.2, 0.2, n), np.zeros(n)])
    values = rng.uniform(0, 2 * R, n)

    def typed():
        s.certify("verdict", *r["verdict"], verdict="separated")
        s.certify("separating_plane", *r["plane"], normal=normals)
        s.certify("distance", *r["distance"], value=values)
        s.certify("penetration_depth", *r["depth"], value=values)

    claims = []
    for i in range(n):
        claims.append({"kind": "verdict", "rho1": r["verdict"][0][i], "rho2": r["verdict"][1][i],
                       "verdict": "separated"})
    for i in range(n):
        claims.append({"kind": "separating_plane", "rho1": r["plane"][0][i], "rho2": r["plane"][1][i],
                       "normal": [float(x) for x in normals[i]]})
    for kind, key in (("distance", "distance"), ("penetration_depth", "depth")):
        for i in range(n):
            claims.append({"kind": kind, "rho1": r[key][0][i], "rho2": r[key][1][i], "value": values[i]})
    text = json.dumps({"format": "scalecert-claims-1", "claims": claims}, default=float)

    def as_text():
        s.certify_fp(text)

    typed()  # the models, built once: in neither time
    t_typed = best(typed, args.reps)
    t_text = best(as_text, args.reps)
    print("| 1,000 claims on two 1,000-point near-spheres | time (best of %d) |" % args.reps)
    print("|---|---|")
    print("| Scene.certify, numpy arrays (typed) | %.3f s |" % t_typed)
    print("| Scene.certify_fp, the same claims as a file's text | %.3f s |" % t_text)
    print("| typed / text (target <= 1) | %.2fx |" % (t_typed / t_text))
    return 0


if __name__ == "__main__":
    sys.exit(main())
