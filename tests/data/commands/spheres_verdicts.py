#!/usr/bin/env python3
"""A user's program for `scalecert audit --command` (tests/test_audit.cpp): verdicts on
examples/spheres.json (a sphere of radius 1 at the origin, one of radius 2 at (5, 0, 0), each
scaled about its centre), derived by hand: the centres stay 5 apart and the radii are rho1 and
2 rho2, so the spheres touch where rho1 + 2 rho2 = 5, are apart below and overlap above. The sum
is taken exactly (fractions of the doubles asked).

Usage: spheres_verdicts.py SCENE.json PAIRS.json CLAIMS.json
"""
import json
import sys
from fractions import Fraction

scene, pairs_path, out = sys.argv[1:4]
claims = []
for r1, r2 in json.load(open(pairs_path))["pairs"]:
    s = Fraction(r1) + 2 * Fraction(r2)
    v = "separated" if s < 5 else "touching" if s == 5 else "overlapping"
    claims.append({"kind": "verdict", "rho1": r1, "rho2": r2, "verdict": v})
json.dump({"format": "scalecert-claims-1", "claims": claims}, open(out, "w"))
