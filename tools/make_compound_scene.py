#!/usr/bin/python3
"""Writes a scene of two objects made of many convex parts (scalecert audit, region).

usage: tools/make_compound_scene.py OUT [--parts K] [--gap G] [--seed S]

Each object is K x K parts on a grid 4 apart in x and y, each part 8 integer points within 2 of
its grid point in x and y and in [0, 5] in z (redrawn while flat); object 2 is object 1's grid
moved by G along x, with its own points. Seeds are left out (each object's is then the mean of its
points); I1 = I2 = [1/2, 2]. The points come from a 64-bit linear congruential generator seeded
with S, so the same arguments write the same bytes on any machine.
certificates/scenes/compound/many_parts.json is `tools/make_compound_scene.py OUT --parts 8 --gap 20 --seed 22`.
"""
import argparse
import json


class Lcg:
    def __init__(self, seed):
        self.s = (seed * 6364136223846793005 + 1442695040888963407) % 2**64

    def below(self, n):
        self.s = (self.s * 6364136223846793005 + 1442695040888963407) % 2**64
        return (self.s >> 33) % n


def rank3(pts):
    o = pts[0]
    vs = [[p[i] - o[i] for i in range(3)] for p in pts[1:]]
    for a in vs:
        for b in vs:
            c = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
            for d in vs:
                if c[0] * d[0] + c[1] * d[1] + c[2] * d[2] != 0:
                    return True
    return False


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--parts", type=int, default=8)
    ap.add_argument("--gap", type=int, default=20)
    ap.add_argument("--seed", type=int, default=22)
    a = ap.parse_args()
    if not 1 <= a.parts <= 100:
        ap.error("--parts must be 1 to 100")
    g = Lcg(a.seed)
    scene = {}
    for i, name in enumerate(("P1", "P2")):
        parts = []
        for p in range(a.parts * a.parts):
            cx, cy = (a.gap if i else 0) + (p % a.parts) * 4, (p // a.parts) * 4
            while True:
                pts = [[cx + g.below(5) - 2, cy + g.below(5) - 2, g.below(6)] for _ in range(8)]
                if rank3(pts):
                    break
            parts.append({"vertices": pts})
        scene[name] = {"parts": parts}
    scene["I1"] = ["1/2", 2]
    scene["I2"] = ["1/2", 2]
    with open(a.out, "w") as f:
        f.write("{\n")
        for name in ("P1", "P2"):
            f.write(f'  "{name}": {{"parts": [\n')
            f.write(",\n".join("    " + json.dumps(p, separators=(",", ":")) for p in scene[name]["parts"]))
            f.write("\n  ]},\n")
        f.write('  "I1": ["1/2", 2],\n  "I2": ["1/2", 2]\n}\n')


if __name__ == "__main__":
    main()
