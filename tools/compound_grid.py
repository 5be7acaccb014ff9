#!/usr/bin/env python3
"""Two objects made of N unit-box parts each, on a grid 32 boxes wide with spacing 3, for
measuring certify-fp on compounds (docs/performance.md, "Claims on objects made of parts").

    tools/compound_grid.py N far|interleaved SCENE CLAIMS

far: P2 lies 200 along x from P1 (every claim is decided by one block). interleaved: P2's boxes
sit between P1's (shifted by 3/2 in x and 1/2 in z), so pairs are near each other everywhere.
CLAIMS gets a verdict and a distance claim at (r, r) for ten r (1 to 1.9 far, 1/2 to 0.95
interleaved), each a floating-point program's output (a JSON number: the double it reads as).
"""
import json
import sys


def box(x, y, z):
    return {"vertices": [[x + a, y + b, z + c] for a in (0, 1) for b in (0, 1) for c in (0, 1)]}


def main():
    if len(sys.argv) != 5 or sys.argv[2] not in ("far", "interleaved") or not sys.argv[1].isdigit() or not 1 <= int(sys.argv[1]) <= 10000:
        sys.exit("usage: compound_grid.py N far|interleaved SCENE CLAIMS  (1 <= N <= 10000)")
    n, layout = int(sys.argv[1]), sys.argv[2]
    dx, dz = (200, 0) if layout == "far" else (1.5, 0.5)

    def obj(ox, oz):
        return {"parts": [box(ox + (k % 32) * 3, (k // 32) * 3, oz) for k in range(n)], "seed": [ox + 48, 48, oz]}

    scene = {"P1": obj(0, 0), "P2": obj(dx, dz), "I1": [1, 2], "I2": [1, 2]}
    start, step = (1.0, 0.1) if layout == "far" else (0.5, 0.05)
    claims = []
    for k in range(10):
        r = start + k * step
        claims.append({"kind": "verdict", "rho1": r, "rho2": r, "verdict": "separated"})
        claims.append({"kind": "distance", "rho1": r, "rho2": r, "value": 1})
    with open(sys.argv[3], "w") as f:
        json.dump(scene, f)
    with open(sys.argv[4], "w") as f:
        json.dump({"format": "scalecert-claims-1", "claims": claims}, f)


if __name__ == "__main__":
    main()
