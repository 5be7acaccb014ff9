#!/usr/bin/python3
"""Draws the paper's figures from scalecert's JSON output (PNG and SVG).

usage: tools/plot.py PARTITION.json CURVE_WITH_SEGMENT.json GRID.json OUTDIR

  fig6_rho      the rho1-rho2 curve, switch points and contacts, growth distance, regions (Fig. 6 left)
  fig3_grid     grid-search samples beside the exact lines near a switch (Figs. 3 and 4)
  fig6_t        the t1-t2 decision curve in the triangle (Fig. 6 right)
  fig7_loci     loci of contact points (Fig. 7)
  fig5_3d       the scaled polyhedra at each contact configuration along the curve (Fig. 5)
"""
import json
import os
import sys
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402


def q(s):
    return float(Fraction(s))


def save(fig, outdir, name, dpi=130):
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(outdir, f"{name}.{ext}"), dpi=dpi, bbox_inches="tight")
    plt.close(fig)


def finish(fig, ax, outdir, name, title, xlabel=None, ylabel=None, legend_size=8, legend_loc="best", zlabel=None, dpi=130):
    """Axis labels, title and legend, then the PNG and SVG files (shared with plot_audit.py,
    plot_claims.py and plot_region.py).
    legend_loc="outside" puts the legend right of the axes, where it covers no line."""
    if xlabel:
        ax.set_xlabel(xlabel)
    if ylabel:
        ax.set_ylabel(ylabel)
    if zlabel:
        ax.set_zlabel(zlabel)
    ax.set_title(title)
    if legend_loc == "outside":
        ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0, fontsize=legend_size)
    else:
        ax.legend(loc=legend_loc, fontsize=legend_size)
    save(fig, outdir, name, dpi)


def fig6_rho(part, outdir):
    fig, ax = plt.subplots(figsize=(6, 5.5))
    reg = part["regions"]
    ov = [(q(x), q(y)) for x, y in reg["overlap"]["vertices"]]
    if len(ov) >= 3:
        ax.fill(*zip(*ov), color="#f4a6a6", label="overlap (witnessed)")
    for k, r in enumerate(reg["separated"]):
        pts = [(q(x), q(y)) for x, y in r["vertices"]]
        ax.fill(*zip(*pts), color="#a6c8f4", label="separated (by a plane)" if k == 0 else None)
    for p in part["pieces"]:
        x0, x1 = (q(v) for v in p["rho1"])
        a, b = q(p["slope"]), q(p["intercept"])
        ax.plot([x0, x1], [a * x0 + b, a * x1 + b], "k-", lw=2)
        xm = (x0 + x1) / 2
        ax.annotate(p["contact"], (xm, a * xm + b), textcoords="offset points", xytext=(6, 6), fontsize=9)
    for s in part["switch_points"]:
        ax.plot(q(s["rho1"]), q(s["rho2"]), "o", color="darkorange", ms=7)
        ax.annotate(f"{s['contact']}  ({s['rho1']}, {s['rho2']})", (q(s["rho1"]), q(s["rho2"])),
                    textcoords="offset points", xytext=(8, -12), fontsize=8, color="darkorange")
    sc = part["scene"]
    lo1, hi1 = (q(v) for v in sc["I1"])
    lo2, hi2 = (q(v) for v in sc["I2"])
    g = q(part["growth_distance"])
    ax.plot([min(lo1, lo2), max(hi1, hi2)], [min(lo1, lo2), max(hi1, hi2)], ":", color="gray", lw=1)
    ax.plot(g, g, "s", color="green", ms=7, label=f"growth distance {part['growth_distance']}")
    ax.set_xlim(lo1, hi1)
    ax.set_ylim(lo2, hi2)
    finish(fig, ax, outdir, "fig6_rho", "touching curve and certified partition", "rho1", "rho2", legend_loc="upper right")


def fig3_grid(part, grid, outdir):
    if not part["switch_points"]:
        return
    s = part["switch_points"][0]
    x, y = q(s["rho1"]), q(s["rho2"])
    sc = part["scene"]
    w = (q(sc["I1"][1]) - q(sc["I1"][0])) / 4
    fig, ax = plt.subplots(figsize=(6, 5))
    for p in part["pieces"]:
        x0, x1 = (q(v) for v in p["rho1"])
        a, b = q(p["slope"]), q(p["intercept"])
        # each exact line, extended across the window, dashed beyond its piece
        ax.plot([x - w, x + w], [a * (x - w) + b, a * (x + w) + b], "--", lw=1)
        ax.plot([max(x0, x - w), min(x1, x + w)], [a * max(x0, x - w) + b, a * min(x1, x + w) + b], "-", lw=2,
                label=f"{p['contact']}: rho2 = {p['slope']} rho1 + {p['intercept']}")
    pts = [(r1, r2) for r1, r2 in grid["samples"] if abs(r1 - x) <= w]
    if pts:
        ax.plot(*zip(*pts), "k+", label=f"grid search ({grid['method']}, n = {grid['n']})")
    ax.plot(x, y, "o", mfc="none", mec="red", ms=12, label=f"exact junction ({s['rho1']}, {s['rho2']})")
    ax.set_xlim(x - w, x + w)
    finish(fig, ax, outdir, "fig3_grid", "grid samples and the exact lines near a switch", "rho1", "rho2", legend_size=7)


def fig6_t(curve, outdir):
    fig, ax = plt.subplots(figsize=(5, 5))
    ax.plot([0, 1, 0, 0], [0, 0, 1, 0], color="gray", lw=1)
    pts = curve.get("t_curve_double", [])
    if pts:
        ax.plot(*zip(*pts), "k-o", ms=3, lw=2, label="t-plane decision curve")
    ax.set_aspect("equal")
    finish(fig, ax, outdir, "fig6_t", "decision curve along the seed segment", "t1", "t2")


def fig7_loci(curve, outdir):
    pts = [[q(c) for c in w["point"]] for w in curve.get("contact_loci", [])]
    fig = plt.figure(figsize=(6, 5))
    ax = fig.add_subplot(projection="3d")
    ax.set_box_aspect(None, zoom=0.85)  # room for the z label
    if pts:
        ax.plot(*zip(*pts), "r-o", ms=4, label="contact point")
        for w, p in zip(curve["contact_loci"], pts):
            ax.text(*p, f" ({w['rho1']}, {w['rho2']})", fontsize=7)
    finish(fig, ax, outdir, "fig7_loci", "loci of contact points along the curve", "x", "y", zlabel="z")


def fig5_3d(curve, outdir):
    sc = curve["scene"]
    loci = curve.get("contact_loci", [])
    if not loci:
        return
    fig = plt.figure(figsize=(4 * len(loci), 4))
    for k, w in enumerate(loci):
        ax = fig.add_subplot(1, len(loci), k + 1, projection="3d")
        for i, (name, color) in enumerate((("P1", "tab:blue"), ("P2", "tab:orange"))):
            rho = q(w["rho1"] if i == 0 else w["rho2"])
            s = [q(c) for c in sc[name]["seed"]]
            V = [[s[j] + rho * (q(v[j]) - s[j]) for j in range(3)] for v in sc[name]["vertices"]]
            polys = [[V[idx] for idx in f] for f in curve["faces"][name]]
            ax.add_collection3d(Poly3DCollection(polys, alpha=0.35, facecolor=color, edgecolor="k", lw=0.4))
        p = [q(c) for c in w["point"]]
        ax.scatter(*p, color="red", s=20)
        allpts = [[q(c) for c in v] for name in ("P1", "P2") for v in sc[name]["vertices"]] + [p]
        for j, setlim in enumerate((ax.set_xlim, ax.set_ylim, ax.set_zlim)):
            lo = min(v[j] for v in allpts)
            hi = max(v[j] for v in allpts)
            pad = (hi - lo) * 0.6 + 1e-9
            setlim(lo - pad, hi + pad)
        ax.set_title(f"rho = ({w['rho1']}, {w['rho2']})", fontsize=8)
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_zlabel("z")
    from matplotlib.patches import Patch
    from matplotlib.lines import Line2D
    fig.legend(handles=[Patch(facecolor="tab:blue", alpha=0.35, edgecolor="k", label="P1(rho1)"),
                        Patch(facecolor="tab:orange", alpha=0.35, edgecolor="k", label="P2(rho2)"),
                        Line2D([], [], marker="o", color="red", ls="", ms=5, label="contact point (witness)")],
               loc="lower center", ncol=3, fontsize=8, bbox_to_anchor=(0.5, -0.02))
    save(fig, outdir, "fig5_3d")


def main():
    if len(sys.argv) != 5:
        print(__doc__)
        sys.exit(2)
    part, curve, grid = (json.load(open(p)) for p in sys.argv[1:4])
    outdir = sys.argv[4]
    os.makedirs(outdir, exist_ok=True)
    fig6_rho(part, outdir)
    fig3_grid(part, grid, outdir)
    fig6_t(curve, outdir)
    fig7_loci(curve, outdir)
    fig5_3d(curve, outdir)


if __name__ == "__main__":
    main()
