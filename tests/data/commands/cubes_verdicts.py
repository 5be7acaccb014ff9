#!/usr/bin/env python3
"""A user's program for `scalecert audit --command` (tests/test_cli.cpp): verdicts on the stacked
cubes (certificates/scenes/stacked_cubes.json), which touch where rho1 + rho2 = 3.

Usage: cubes_verdicts.py MODE SCENE.json PAIRS.json CLAIMS.json, MODE "exact" (the sum of the two
doubles taken exactly) or "float32" (each rounded to float32 and summed in float32, as a careless
program might). With PAIRS_COPY set, it copies the pairs asked there, for the test's own count.
"""
import json
import os
import struct
import sys
from fractions import Fraction


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


mode, scene, pairs_path, out = sys.argv[1:5]
pairs = json.load(open(pairs_path))["pairs"]
claims = []
for r1, r2 in pairs:
    if mode == "exact":
        s = Fraction(r1) + Fraction(r2)
    else:
        s = Fraction(f32(f32(r1) + f32(r2)))
    v = "separated" if s < 3 else "touching" if s == 3 else "overlapping"
    claims.append({"kind": "verdict", "rho1": r1, "rho2": r2, "verdict": v})
json.dump({"format": "scalecert-claims-1", "claims": claims}, open(out, "w"))
if os.environ.get("PAIRS_COPY"):
    json.dump(pairs, open(os.environ["PAIRS_COPY"], "w"))
