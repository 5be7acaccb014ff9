#!/usr/bin/env python3
"""Writes scenes built from collision failures reported in libccd's and FCL's issue trackers.

Each box's vertices are computed in double precision exactly as those libraries do (R·v + t),
then written as the exact rationals of those doubles, so scalecert certifies the very
configuration the library saw. The scaling ranges bracket ρ = 1 (the reported configuration).

usage: tools/reported_scenes.py OUTDIR
"""
import json
import os
import sys
from fractions import Fraction


def exact(x):
    f = Fraction(x)  # the double's exact value
    return str(f.numerator) if f.denominator == 1 else f"{f.numerator}/{f.denominator}"


def box(size, R, t):
    hx, hy, hz = (s / 2 for s in size)  # FCL's Box takes full side lengths
    pts = []
    for sx in (-1, 1):
        for sy in (-1, 1):
            for sz in (-1, 1):
                v = (sx * hx, sy * hy, sz * hz)
                pts.append([exact(R[i][0] * v[0] + R[i][1] * v[1] + R[i][2] * v[2] + t[i]) for i in range(3)])
    seed = [exact(t[i]) for i in range(3)]
    return {"vertices": pts, "seed": seed}


I = ((1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0))

SCENES = {
    # libccd issue #25: two cubes of side 2 at z = 0 and z = 1.9 (overlapping by 0.1); GJK
    # penetration returned NaN directions while MPR was right.
    "reported_libccd25_stacked_cubes": (box((2, 2, 2), I, (0, 0, 0)), box((2, 2, 2), I, (0, 0, 1.9)), ["9/10", "11/10"]),
    # FCL issue #495 (also #493): two 0.25 boxes with the same rotation, in kissing contact with
    # sub-epsilon separation; GJK said touching, EPA said separated.
    "reported_fcl495_kissing_boxes": (
        box((0.25, 0.25, 0.25),
            ((0.94096063217417758029, 0.29296840037289501035, 0.16959541586174811667),
             (-0.23569836841299879326, 0.92661523595848427348, -0.29296840037289506586),
             (-0.2429801799032638987, 0.23569836841299884878, 0.94096063217417758029)),
            (0.073242100093223821977, 0.2316538089896212349, 1.3089245921032497399)),
        box((0.25, 0.25, 0.25),
            ((0.94096063217417758029, 0.29296840037289501035, 0.16959541586174811667),
             (-0.23569836841299879326, 0.92661523595848427348, -0.29296840037289506586),
             (-0.2429801799032638987, 0.23569836841299884878, 0.94096063217417758029)),
            (0.0, 0.0, 1.25)),
        ["99/100", "101/100"]),
    # FCL issue #399: box-box collision that FCL wrongly sent to EPA (origin outside the polytope).
    "reported_fcl399_thin_boxes": (
        box((0.23768037557601928711, 0.15702305734157562256, 0.25),
            ((-0.099432387353076273628, 0.99504432079443971837, 0.0),
             (-0.99504432079443971837, -0.099432387353076273628, 0.0), (0.0, 0.0, 1.0)),
            (0.29526406526565551758, -0.013230856508016586304, 0.0)),
        box((0.010000000000000000208, 0.78165709972381591797, 0.25),
            ((0.99506598442099225554, 0.099215354901756730444, 0.0),
             (-0.099215354901756730444, 0.99506598442099225554, 0.0), (0.0, 0.0, 1.0)),
            (0.22759585694545214629, 0.14974093549228112421, 0.0)),
        ["9/10", "11/10"]),
}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "certificates/scenes"
    os.makedirs(out, exist_ok=True)
    for name, (p1, p2, rng) in SCENES.items():
        scene = {"P1": p1, "P2": p2, "I1": rng, "I2": rng}
        with open(os.path.join(out, name + ".json"), "w") as f:
            json.dump(scene, f, indent=1)
            f.write("\n")


if __name__ == "__main__":
    main()
