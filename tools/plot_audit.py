#!/usr/bin/python3
"""Charts from `scalecert audit` JSON (PNG and SVG).

usage: tools/plot_audit.py AUDIT.json OUTDIR

  stability       wrong-verdict rate against the degeneracy eps, per method (family audits only:
                  a scene-file audit has no eps, and no stability chart is drawn)
  speed_accuracy  time per curve against switch-point error (grid at each resolution, exact engine;
                  drawn when some scene has a switch point in its rectangle)
  by_distance     wrong-verdict rate against the relative distance 2^-k from the curve, per method
                  (audits run with --by-distance; pairs exactly touching once rounded are counted apart);
                  for objects made of parts, from the boundary of the overlap region
  on_boundary     objects made of parts: what each method says at the points exactly on the region's
                  boundary (touching): separated, touching or overlapping, as shares of those points
"""
import json
import os
import sys
from collections import defaultdict
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from plot import finish  # noqa: E402  (tools/plot.py, beside this script)


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    rows = json.load(open(sys.argv[1]))
    outdir = sys.argv[2]
    os.makedirs(outdir, exist_ok=True)
    # Stability: per method, per eps: wrong verdicts / queries over all scenes.
    acc = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    for r in rows:
        if "queries" in r and float(Fraction(r["eps"])) > 0:
            a = acc[r["method"]][float(Fraction(r["eps"]))]
            a[0] += r["false_separated"] + r["false_overlapping"]
            a[1] += r["queries"]
    # (A scene-file audit has no degeneracy eps: no stability chart then, rather than an empty one.)
    if acc:
        fig, ax = plt.subplots(figsize=(6, 4))
        for method, by_eps in sorted(acc.items()):
            xs = sorted(by_eps)
            ax.plot(xs, [by_eps[x][0] / by_eps[x][1] for x in xs], "o-", ms=3, label=method)
        ax.axhline(0, color="green", lw=2, label="scalecert (exact): 0 by construction")
        ax.set_xscale("log", base=2)
        finish(fig, ax, outdir, "stability", "stability", "degeneracy eps", "wrong-verdict rate (pairs on and near the curve)",
               legend_loc="outside")
    # Wrong-verdict rate against the relative distance from the curve.
    bd = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    touching = defaultdict(int)
    for r in rows:
        for b in r.get("by_distance", []):
            a = bd[r["method"]][b["k"]]
            a[0] += b["wrong"]
            a[1] += b["pairs"]
            touching[b["k"]] += b["touching"]
    if bd:
        # (Compound rows, those with on_boundary, measure from the region's boundary.)
        kinds = {"on_boundary" in r for r in rows if r.get("by_distance")}
        what = "the boundary" if kinds == {True} else "the curve" if kinds == {False} else "the curve or boundary"
        fig, ax = plt.subplots(figsize=(6, 4))
        for method, by_k in sorted(bd.items()):
            ks = sorted(by_k)
            ax.plot([2.0 ** -k for k in ks], [by_k[k][0] / max(1, by_k[k][1]) for k in ks], "o-", ms=3, label=method)
        ax.axhline(0, color="green", lw=2, label="scalecert (exact): 0 by construction")
        ax.set_xscale("log", base=2)
        ax.invert_xaxis()
        t = ", ".join(f"2^-{k}: {n}" for k, n in sorted(touching.items()) if n)
        finish(fig, ax, outdir, "by_distance", f"wrong verdicts near {what}" + (f" (touching, apart: {t})" if t else ""),
               f"relative distance from {what}", "wrong-verdict rate", legend_loc="outside")
    # What each method says exactly on the boundary (objects made of parts).
    said = defaultdict(lambda: [0, 0, 0])
    for r in rows:
        o = r.get("on_boundary")
        if o:
            a = said[r["method"]]
            a[0] += o["said_separated"]
            a[1] += o["said_touching"]
            a[2] += o["said_overlapping"]
    if any(sum(v) for v in said.values()):
        methods = sorted(m for m, v in said.items() if sum(v))
        fig, ax = plt.subplots(figsize=(6, 4))
        left = [0.0] * len(methods)
        for k, (label, color) in enumerate((("said separated", "#d62728"), ("said touching", "#2ca02c"), ("said overlapping", "#1f77b4"))):
            share = [said[m][k] / sum(said[m]) for m in methods]
            ax.barh(methods, share, left=left, color=color, label=label)
            left = [a + b for a, b in zip(left, share)]
        ax.set_xlim(0, 1)
        n = sum(said[methods[0]])
        finish(fig, ax, outdir, "on_boundary", f"on the boundary: {n} exactly touching points", "share of the points", None,
               legend_loc="outside")
    # Speed against accuracy.
    pts = defaultdict(list)
    for r in rows:
        # only scenes with a switch point in the rectangle say anything about junction error
        if "seconds_per_curve" in r and r["exact_junctions"] > 0:
            err = r["max_junction_error"] if r["junctions_missed"] == 0 else float("nan")
            label = r["method"] + (f" n={r['grid_n']}" if r.get("grid_n") else "")
            pts[label].append((r["seconds_per_curve"], max(err, 1e-17) if err == err else None))
    if not any(e is not None for v in pts.values() for t, e in v):
        print("plot_audit.py: no scene with a switch point in its rectangle: no speed_accuracy chart", file=sys.stderr)
        return
    fig, ax = plt.subplots(figsize=(6, 4))
    for label, v in sorted(pts.items()):
        xs = [t for t, e in v if e is not None]
        ys = [e for t, e in v if e is not None]
        if xs:
            ax.plot(xs, ys, "o", ms=4, label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    finish(fig, ax, outdir, "speed_accuracy", "speed against accuracy", "seconds per curve",
           "switch-point error in rho1 (exact: plotted at 1e-17)", legend_size=7, legend_loc="outside")


if __name__ == "__main__":
    main()
