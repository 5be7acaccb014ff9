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


# A colour and a marker per method, none of them the exact line's (black, dashed), so a method
# that is never wrong is drawn over that line, not hidden under it.
STYLES = [("#1f77b4", "o"), ("#d62728", "s"), ("#9467bd", "^"), ("#ff7f0e", "D"), ("#8c564b", "v"),
          ("#e377c2", "P"), ("#7f7f7f", "X"), ("#17becf", "*"), ("#bcbd22", "h")]


def style(k):
    colour, marker = STYLES[k % len(STYLES)]
    return {"color": colour, "marker": marker, "ms": 4, "zorder": 3}


def exact_line(ax):
    ax.axhline(0, color="black", lw=1, ls="--", zorder=1, label="scalecert (exact): 0 by construction")


def main():
    if len(sys.argv) != 3:
        print(__doc__)
        sys.exit(2)
    # The rows, read as tools/report.py reads them (each field used checked): one line, exit 2.
    import report  # noqa: E402  (tools/report.py, beside this script)
    try:
        rows = report.load_rows(sys.argv[1])
    except report.InputError as e:
        print("plot_audit.py: error: %s" % e, file=sys.stderr)
        sys.exit(2)
    outdir = sys.argv[2]
    os.makedirs(outdir, exist_ok=True)
    # Stability: per method, per eps: wrong verdicts / queries over all scenes.
    acc = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    for r in rows:
        if "queries" in r and float(Fraction(r["eps"])) > 0:
            a = acc[r["method"]][float(Fraction(r["eps"]))]
            a[0] += r["false_separated"] + r["false_overlapping"] + r.get("false_touching", 0)
            a[1] += r["queries"]
    # (A scene-file audit has no degeneracy eps: no stability chart then, rather than an empty one.)
    if acc:
        # The families (a family scene is named FAMILY-INDEX) and how many scenes each eps has.
        fam_rows = [r for r in rows if "queries" in r and float(Fraction(r["eps"])) > 0]
        families = sorted({os.path.basename(r["scene"]).rsplit("-", 1)[0] for r in fam_rows})
        per_eps = len({(r["scene"], r["eps"]) for r in fam_rows}) // max(1, len({r["eps"] for r in fam_rows}))
        fig, ax = plt.subplots(figsize=(6, 4))
        for k, (method, by_eps) in enumerate(sorted(acc.items())):
            xs = sorted(by_eps)
            ax.plot(xs, [by_eps[x][0] / by_eps[x][1] for x in xs], "-", label=method, **style(k))
        exact_line(ax)
        ax.set_xscale("log", base=2)
        finish(fig, ax, outdir, "stability", "stability: %s, %d scene%s per eps" % (
            ", ".join(families), per_eps, "" if per_eps == 1 else "s"), "degeneracy eps",
            "wrong-verdict rate (pairs on and near the curve)", legend_loc="outside")
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
        for k, (method, by_k) in enumerate(sorted(bd.items())):
            ks = sorted(by_k)
            ax.plot([2.0 ** -j for j in ks], [by_k[j][0] / max(1, by_k[j][1]) for j in ks], "-", label=method,
                    **style(k))
        exact_line(ax)
        ax.set_xscale("log", base=2)
        ax.invert_xaxis()
        t = ", ".join(f"2^-{k}: {n}" for k, n in sorted(touching.items()) if n)
        scenes = len({r["scene"] for r in rows if r.get("by_distance")})
        finish(fig, ax, outdir, "by_distance", f"wrong verdicts near {what}, {scenes} scene{'' if scenes == 1 else 's'}" +
               (f" (touching, apart: {t})" if t else ""),
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
    # Speed against accuracy compares the grid search with the exact engine: without a grid row
    # with an error there is nothing to compare, and no chart.
    if not any(e is not None for label, v in pts.items() if not label.startswith("scalecert") for t, e in v):
        print("plot_audit.py: no grid method on a scene with a switch point in its rectangle: no speed_accuracy chart",
              file=sys.stderr)
        return
    fig, ax = plt.subplots(figsize=(6, 4))
    def by_method_then_n(item):  # "grid+... n=16" before "n=64" before "n=256"
        method, _, n = item[0].partition(" n=")
        return method, int(n) if n.isdigit() else 0

    for k, (label, v) in enumerate(sorted(pts.items(), key=by_method_then_n)):
        xs = [t for t, e in v if e is not None]
        ys = [e for t, e in v if e is not None]
        if xs:
            ax.plot(xs, ys, ls="none", label=label, **style(k))
    ax.set_xscale("log")
    ax.set_yscale("log")
    finish(fig, ax, outdir, "speed_accuracy", "speed against accuracy", "seconds per curve",
           "switch-point error in rho1 (exact: plotted at 1e-17)", legend_size=7, legend_loc="outside")


if __name__ == "__main__":
    main()
