#!/usr/bin/python3
"""A claimed touching curve drawn over the exact one, each exact switch point labelled with its
error (PNG and SVG).

usage: tools/plot_claims.py SCENE CLAIMS OUTDIR [SCALECERT]

CLAIMS is a scalecert-claims-1 file (certificates/CLAIMS.md); every claim of kind "curve" in it is
drawn. The exact curve and the errors come from `scalecert curve` and `scalecert certify-fp --json`.
"""
import json
import os
import subprocess
import sys
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot import finish  # noqa: E402  (tools/plot.py, beside this script)


def q(x):
    return float(Fraction(x))


def main():
    if len(sys.argv) not in (4, 5):
        print(__doc__)
        sys.exit(2)
    scene, claims_path, outdir = sys.argv[1:4]
    os.makedirs(outdir, exist_ok=True)
    exe = sys.argv[4] if len(sys.argv) == 5 else os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "scalecert")
    curve = json.loads(subprocess.run([exe, "curve", scene], capture_output=True, text=True, check=True).stdout)
    rep = subprocess.run([exe, "certify-fp", scene, claims_path, "--json"], capture_output=True, text=True)
    if rep.returncode not in (0, 1):
        sys.exit(rep.stderr)
    report = json.loads(rep.stdout)["claims"]
    claims = json.load(open(claims_path))["claims"]
    fig, ax = plt.subplots(figsize=(6.5, 5))
    for p in curve["pieces"]:
        x0, x1 = (q(v) for v in p["rho1"])
        a, b = q(p["slope"]), q(p["intercept"])
        ax.plot([x0, x1], [a * x0 + b, a * x1 + b], "k-", lw=2.5, label="exact" if p is curve["pieces"][0] else None)
    drawn = 0
    for c, r in zip(claims, report):
        if c["kind"] != "curve":
            continue
        if "vertices" in c:
            xs, ys = zip(*[(q(x), q(y)) for x, y in c["vertices"]])
            ax.plot(xs, ys, "o--", ms=3, color="tab:red", label=f"claimed (max vertical error {float(Fraction(r['max_vertical_error'])):.3g})")
        else:
            for k, p in enumerate(c["pieces"]):
                x0, x1 = (q(v) for v in p["rho1"])
                a, b = q(p["slope"]), q(p["intercept"])
                ax.plot([x0, x1], [a * x0 + b, a * x1 + b], "--", color="tab:red",
                        label=f"claimed (max vertical error {float(Fraction(r['max_vertical_error'])):.3g})" if k == 0 else None)
        misplaced = {m["exact_rho1"]: m["claimed_rho1"] for m in r["switch_points_misplaced"]}
        for s in curve["switch_points"]:
            if s["contact"] is None:
                continue
            x, y = q(s["rho1"]), q(s["rho2"])
            if s["rho1"] in misplaced:
                text = f"misplaced by {q(misplaced[s['rho1']]) - x:+.3g}"
            elif s["rho1"] in r["switch_points_missed"]:
                text = "missed"
            else:
                text = "exact"
            ax.plot([x], [y], "s", color="tab:blue", ms=6)
            ax.annotate(f"{s['contact']}: {text}", (x, y), textcoords="offset points", xytext=(8, 8), fontsize=8)
        for w in r["wrong_contacts"]:
            x = q(w["rho1"])
            y = next(q(p["slope"]) * x + q(p["intercept"]) for p in curve["pieces"] if q(p["rho1"][0]) <= x <= q(p["rho1"][1]))
            # Below and left of its point, ending there: under a descending curve, clear of it.
            ax.annotate(f"contact claimed {w['claimed']}, exact {w['exact']}", (x, y), textcoords="offset points",
                        xytext=(-6, -14), ha="right", va="top", fontsize=8, color="tab:red",
                        arrowprops={"arrowstyle": "-", "color": "tab:red", "lw": 0.6})
        for e in r["switch_points_extra"]:
            ax.axvline(q(e), color="tab:orange", lw=0.8, ls=":")
        drawn += 1
    if not drawn:
        sys.exit(f"{claims_path}: no claim of kind \"curve\"")
    finish(fig, ax, outdir, "claimed_curve", "claimed curve over the exact one", "rho1", "rho2")


if __name__ == "__main__":
    main()
