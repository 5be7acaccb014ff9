#!/usr/bin/env python3
"""Claims of a naive floating-point program on a scene of parts, for `scalecert certify-fp`
(docs/audits.md, "Real meshes as compounds").

    tools/real_compound_claims.py SCENE REGION CLAIMS

REGION is `scalecert region SCENE`'s output: its growth set's first `from` (the least ρ on
ρ1 = ρ2 where the objects meet), read as the double nearest it, is the program's "growth distance"
ρc. On the diagonal at ρc·(1 + t) for t = ±2^-4, ±2^-16, ±2^-30, ±2^-50 and 0 (in doubles) the
program claims separated below ρc, touching at it, overlapping above it. At the separated points
of t ≤ -2^-4 and at ρ1 = ρ2 = 1/2 it claims a distance: the least distance between the scaled
vertices of the two objects (in doubles, numpy), with those two vertices as closest points. That is
only right when the closest features are vertices: certify-fp says which claims are wrong."""
import json
import sys
from fractions import Fraction as F

import numpy as np


def obj_vertices(o):
    parts = o["parts"] if "parts" in o else [o]
    return np.array([[float(F(str(x))) for x in v] for p in parts for v in p["vertices"]]), \
        np.array([float(F(str(x))) for x in o["seed"]])


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    scene, region = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
    growth = region["growth_set"]
    if not growth:
        sys.exit("real_compound_claims.py: the objects never meet on the diagonal")
    rc = float(F(growth[0]["from"]))
    (v1, s1), (v2, s2) = obj_vertices(scene["P1"]), obj_vertices(scene["P2"])
    claims = []
    for t in (-2.0**-4, -2.0**-16, -2.0**-30, -2.0**-50, 0.0, 2.0**-50, 2.0**-30, 2.0**-16, 2.0**-4):
        r = rc * (1 + t)
        verdict = "separated" if r < rc else "touching" if r == rc else "overlapping"
        claims.append({"kind": "verdict", "rho1": r, "rho2": r, "verdict": verdict})
    for r in (0.5, rc * (1 - 2.0**-4)):
        a, b = s1 + r * (v1 - s1), s2 + r * (v2 - s2)
        d = np.sqrt(((a[:, None, :] - b[None, :, :]) ** 2).sum(axis=2))
        i, j = np.unravel_index(np.argmin(d), d.shape)
        claims.append({"kind": "distance", "rho1": r, "rho2": r, "value": float(d[i, j]),
                       "closest": [a[i].tolist(), b[j].tolist()]})
    with open(sys.argv[3], "w") as f:
        json.dump({"format": "scalecert-claims-1", "claims": claims}, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
