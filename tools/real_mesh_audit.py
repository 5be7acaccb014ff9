#!/usr/bin/env python3
"""Audits the floating-point baselines on convex hulls of real meshes from CGAL's data set
(Debian's libcgal-demo ships it in /usr/share/doc/libcgal-dev/data.tar.gz).

usage: tools/real_mesh_audit.py [--install] OUTDIR

Needs the meshes (Debian's libcgal-demo, about 60 packages with what it pulls in) and a scalecert
command: $SCALECERT, else build/scalecert of this checkout, else `scalecert` on the PATH (an
installed prefix). When libcgal-demo is missing it asks before installing it (tools/install-deps.sh);
without a terminal it installs only with --install, and otherwise stops with exit status 2.

For each pair (A, B) it reads both OFF files exactly (decimal text as fractions), scales B by a
power of two to A's size, places B's centre at A's centre plus (size_A + size_B) / 2 along x
(exact rationals throughout), writes OUTDIR/A-B.json with I1 = I2 = [1/2, 2] and the mean seeds,
then runs `build/scalecert audit` on the scenes and prints a table of missed collisions (false
"separated") and false "overlapping" per method."""
import csv
import os
import shutil
import subprocess
import sys
import tarfile
from fractions import Fraction as F

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = "/usr/share/doc/libcgal-dev/data.tar.gz"
PAIRS = [("bunny00", "armadillo"), ("cow", "elephant"), ("ChineseDragon-10kv", "fandisk"), ("eight", "cow")]
METHODS = "libccd-gjk,libccd-mpr,fcl-gjk-libccd,fcl-gjk-indep,bullet-gjk-epa,double-envelope"


def read_off(text):
    words = [w for line in text.splitlines() for w in line.split("#")[0].split()]
    assert words[0] == "OFF"
    nv = int(words[1])
    nums = words[4:4 + 3 * nv]
    return [tuple(F(x) for x in nums[3 * i:3 * i + 3]) for i in range(nv)]


def box(pts):
    lo = [min(p[k] for p in pts) for k in range(3)]
    hi = [max(p[k] for p in pts) for k in range(3)]
    return lo, hi


def exact(q):
    return str(q.numerator) if q.denominator == 1 else f"{q.numerator}/{q.denominator}"


def scalecert_command():
    for c in (os.environ.get("SCALECERT"), os.path.join(ROOT, "build/scalecert"), shutil.which("scalecert")):
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    print("real_mesh_audit.py: no scalecert command: build it (tools/build.sh), put an installed one on "
          "the PATH, or name it in $SCALECERT", file=sys.stderr)
    sys.exit(2)


def main():
    args = [a for a in sys.argv[1:] if a != "--install"]
    install = len(args) < len(sys.argv) - 1
    if len(args) > 1 or any(a.startswith("-") for a in args):
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    out = args[0] if args else "out/real-meshes"
    scalecert = scalecert_command()
    if not os.path.exists(DATA):
        if not install and sys.stdin.isatty():
            answer = input("real_mesh_audit.py: the meshes need Debian's libcgal-demo (about 60 packages); install it? [y/N] ")
            install = answer.strip().lower() in ("y", "yes")
        if not install:
            print(f"real_mesh_audit.py: {DATA} is missing: install libcgal-demo (or run with --install)", file=sys.stderr)
            sys.exit(2)
        subprocess.run([os.path.join(ROOT, "tools/install-deps.sh"), "libcgal-demo"], check=True)
    os.makedirs(out, exist_ok=True)
    meshes = {}
    with tarfile.open(DATA) as t:
        for a, b in PAIRS:
            for n in (a, b):
                if n not in meshes:
                    meshes[n] = read_off(t.extractfile(f"data/meshes/{n}.off").read().decode())
    scenes = []
    for a, b in PAIRS:
        A, B = meshes[a], meshes[b]
        (la, ha), (lb, hb) = box(A), box(B)
        sa, sb = max(h - l for l, h in zip(la, ha)), max(h - l for l, h in zip(lb, hb))
        k = F(1)  # a power of two: B scaled to A's size, exactly
        while sb * k * 2 <= sa:
            k *= 2
        while sb * k > 2 * sa:
            k /= 2
        ca = [(l + h) / 2 for l, h in zip(la, ha)]
        cb = [(l + h) / 2 * k for l, h in zip(lb, hb)]
        shift = [ca[0] + (sa + sb * k) / 2 - cb[0], ca[1] - cb[1], ca[2] - cb[2]]
        Bt = [tuple(p[i] * k + shift[i] for i in range(3)) for p in B]
        path = os.path.join(out, f"{a}-{b}.json")
        with open(path, "w") as f:
            f.write('{"P1": {"vertices": [' + ",".join("[" + ",".join(f'"{exact(x)}"' for x in p) + "]" for p in A) + ']},\n')
            f.write(' "P2": {"vertices": [' + ",".join("[" + ",".join(f'"{exact(x)}"' for x in p) + "]" for p in Bt) + ']},\n')
            f.write(' "I1": ["1/2", 2], "I2": ["1/2", 2]}\n')
        scenes.append(path)
        print(f"{path}: {len(A)} + {len(B)} vertices", file=sys.stderr)
    csv_path = os.path.join(out, "audit.csv")
    subprocess.run([scalecert, "audit", *scenes, "--methods", METHODS,
                    "--out", os.path.join(out, "audit.json"), "--csv", csv_path], check=True)
    rows = [r for r in csv.DictReader(open(csv_path)) if not r["method"].startswith("scalecert")]
    methods = list(dict.fromkeys(r["method"] for r in rows))
    print("| scene | " + " | ".join(methods) + " |")
    print("|---|" + "---|" * len(methods))
    for s in scenes:
        name = os.path.basename(s)[:-5]
        cells = []
        for m in methods:
            r = next(r for r in rows if r["scene"] == s and r["method"] == m)
            touching = f" / {r['false_touching']} touching" if r.get("false_touching", "0") != "0" else ""
            cells.append(f"{r['false_separated']} / {r['false_overlapping']}{touching}")
        print(f"| {name} | " + " | ".join(cells) + " |")
    print(f"(false separated / false overlapping, of {rows[0]['queries']} pairs per scene)")


if __name__ == "__main__":
    main()
