#!/usr/bin/python3
"""Draws a compound's region from `scalecert region` JSON (PNG and SVG).

usage: tools/plot_region.py SCENE.json REGION.json OUTDIR [--at RHO1,RHO2]

  region_rho  I1 x I2 shaded overlap (the union, its holes, the pairs meeting without area) and
              separated; each pair polygon outlined; each boundary edge on a part pair's contact
              labelled with the pair and contact ("P1[1]-P2[0] FF", a part named in the region
              JSON by its name: "P1[foot]-P2[0] FF"); the switch points with the
              contacts there; the growth set on the diagonal rho1 = rho2; the point of the 3-D view
  region_3d   the parts at (RHO1, RHO2), each object's scaled about its seed, those that touch
              or overlap there highlighted and the others faded. Default point: the first switch
              point, else the midpoint of the first edge on a contact. Parts must be given by
              "vertices" (a part given as a mesh is refused, after region_rho is drawn).

Every number is read exactly (fractions.Fraction) and made a float only to be drawn.
"""
import itertools
import json
import math
import os
import sys
from fractions import Fraction

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch, PathPatch  # noqa: E402
from matplotlib.path import Path  # noqa: E402
from matplotlib.ticker import MaxNLocator  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

from plot import finish, q, save  # noqa: E402  (tools/plot.py, beside this script)

OVERLAP, SEPARATED = "#f4a6a6", "#a6c8f4"
DPI = 110
MAX_HULL_POINTS = 200  # the hull below tries every triple of points (128 points: 0.7 s)


def refuse(why):
    print(f"plot_region.py: {why}", file=sys.stderr)
    sys.exit(2)


def point(p):
    return tuple(Fraction(c) for c in p)


def part_name(c, obj):
    """A part of a pair entry ({"P1_part": 3, "P1_part_name": "foot", ...}): 'P1[foot]' when the
    region JSON names it, else 'P1[3]'."""
    return f"{obj}[{c.get(obj + '_part_name', c[obj + '_part'])}]"


def pair_name(c):
    return f"{part_name(c, 'P1')}-{part_name(c, 'P2')}"


def part_names(region):
    """{(object, index): name} of every part the region JSON names ("P1_part_name" beside "P1_part")."""
    names = {}

    def walk(x):
        if isinstance(x, dict):
            for obj in ("P1", "P2"):
                if obj + "_part_name" in x:
                    names[(obj, x[obj + "_part"])] = x[obj + "_part_name"]
            for v in x.values():
                walk(v)
        elif isinstance(x, list):
            for v in x:
                walk(v)

    walk(region)
    return names


def fmt(x):
    return f"({x[0]}, {x[1]})"


# --- exact plane geometry -------------------------------------------------------------------

def cross2(o, a, b):
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def area2(ring):
    return sum(a[0] * b[1] - b[0] * a[1] for a, b in zip(ring, ring[1:] + ring[:1]))


def on_segment(x, a, b):
    return cross2(a, b, x) == 0 and min(a[0], b[0]) <= x[0] <= max(a[0], b[0]) and min(a[1], b[1]) <= x[1] <= max(a[1], b[1])


def locate(x, ring):
    """'inside', 'on' or 'outside' of a convex ring (any orientation), a segment or a point."""
    if len(ring) < 3:
        return "on" if (x == ring[0] if len(ring) == 1 else on_segment(x, ring[0], ring[1])) else "outside"
    sign = 1 if area2(ring) > 0 else -1
    sides = [sign * cross2(a, b, x) for a, b in zip(ring, ring[1:] + ring[:1])]
    if min(sides) < 0:
        return "outside"
    return "inside" if min(sides) > 0 else "on"


def rectangle(scene):
    """((lo1, hi1), (lo2, hi2)): I1 and I2 of the scene."""
    return tuple(tuple(Fraction(v) for v in scene[k]) for k in ("I1", "I2"))


def meeting_at(region, x, rect):
    """The part pairs meeting at x: {(i, j): [state, contact]}. 'touching' where x lies on one of
    the pair's contact lines (a switch point, a labelled boundary edge, or its polygon's edge off
    the rectangle's sides: a constraint holds with equality there) or the pair meets without area;
    elsewhere in its polygon 'meeting' (overlapping, or touching along a normal that touches
    everywhere: `scalecert region --at` tells). The contact from the labels through x, if any."""
    found = {}
    for s in region.get("switch_points") or []:
        if (Fraction(s["rho1"]), Fraction(s["rho2"])) == x:
            for c in s["contacts"]:
                found[(c["P1_part"], c["P2_part"])] = ["touching", c["contact"]]
    for ring in region.get("boundary") or []:
        for e in ring["edges"]:
            on = e["on"]
            if isinstance(on, dict) and on_segment(x, point(e["from"]), point(e["to"])):
                found.setdefault((on["P1_part"], on["P2_part"]), ["touching", on["contact"]])

    def on_side(a, b):
        return any(a[c] == b[c] and a[c] in rect[c] for c in (0, 1))

    for p in region["pair_regions"]:
        ring = [point(v) for v in p["vertices"]]
        if locate(x, ring) == "outside":
            continue
        touching = len(ring) < 3 or any(on_segment(x, a, b) and not on_side(a, b) for a, b in zip(ring, ring[1:] + ring[:1]))
        entry = found.setdefault((p["P1_part"], p["P2_part"]), [None, None])
        entry[0] = "touching" if touching or entry[0] == "touching" else "meeting"
    return found


# --- the region in the (rho1, rho2) plane ------------------------------------------------------

def ring_path(rings):
    """One path of rings, the first counterclockwise and the rest clockwise (outer, then holes)."""
    verts, codes = [], []
    for k, ring in enumerate(rings):
        if (area2(ring) > 0) != (k == 0):
            ring = ring[::-1]
        verts += [(q(a), q(b)) for a, b in ring] + [(0, 0)]
        codes += [Path.MOVETO] + [Path.LINETO] * (len(ring) - 1) + [Path.CLOSEPOLY]
    return Path(verts, codes)


def edge_label(on):
    """The pair, its contact and the first tight normal: 'P1[0]-P2[0] FF n=(1,0,0)'."""
    return f"{pair_name(on)} {on['contact']} n=({','.join(on['normals'][0])})"


def contact_runs(boundary):
    """Each ring's edges on a pair contact, consecutive edges with the same label joined:
    (label, pair, [points])."""
    runs = []
    for ring in boundary:
        edges = ring["edges"]
        label = [edge_label(e["on"]) if isinstance(e["on"], dict) else None for e in edges]
        # start at an edge whose predecessor has another label, so no run is cut by the ring's end
        start = next((k for k in range(len(edges)) if label[k] != label[k - 1]), 0)
        for k in range(start, start + len(edges)):
            e, lab = edges[k % len(edges)], label[k % len(edges)]
            if lab is None:
                continue
            if runs and runs[-1][0] == lab and runs[-1][2][-1] == point(e["from"]) and k != start:
                runs[-1][2].append(point(e["to"]))
            else:
                runs.append((lab, (e["on"]["P1_part"], e["on"]["P2_part"]), [point(e["from"]), point(e["to"])]))
    return runs


def label_run(ax, pts, text, color):
    """The label at the run's middle, pushed off it to the right of its direction (the separated
    side: the region lies on the left of every boundary edge), or to the left where that leaves
    the axes, or on the line itself."""
    lengths = [math.dist((q(a[0]), q(a[1])), (q(b[0]), q(b[1]))) for a, b in zip(pts, pts[1:])]
    half, k = sum(lengths) / 2, 0
    while k < len(lengths) - 1 and half > lengths[k]:
        half -= lengths[k]
        k += 1
    a, b = pts[k], pts[k + 1]
    t = half / lengths[k] if lengths[k] else 0.5
    m = (q(a[0]) + t * (q(b[0]) - q(a[0])), q(a[1]) + t * (q(b[1]) - q(a[1])))
    d = ax.transData.transform([(q(b[0]), q(b[1]))])[0] - ax.transData.transform([(q(a[0]), q(a[1]))])[0]
    r = math.hypot(*d) or 1.0
    box = ax.get_window_extent()
    renderer = ax.figure.canvas.get_renderer()
    for side in (14, -14, 0):
        off = (side * d[1] / r, -side * d[0] / r)
        ann = ax.annotate(text, m, textcoords="offset points", xytext=off, fontsize=8, color=color,
                          ha="left" if off[0] > 4 else "right" if off[0] < -4 else "center",
                          va="bottom" if off[1] > 4 else "top" if off[1] < -4 else "center",
                          bbox=dict(boxstyle="round,pad=0.15", fc="white", ec="none", alpha=0.8))
        e = ann.get_window_extent(renderer)
        if side == 0 or (e.x0 >= box.x0 and e.x1 <= box.x1 and e.y0 >= box.y0 and e.y1 <= box.y1):
            return
        ann.remove()


def region_rho(scene, region, at, outdir):
    (lo1, hi1), (lo2, hi2) = rectangle(scene)
    fig, ax = plt.subplots(figsize=(6, 5))
    ax.set_xlim(q(lo1), q(hi1))
    ax.set_ylim(q(lo2), q(hi2))
    ax.add_patch(plt.Rectangle((q(lo1), q(lo2)), q(hi1 - lo1), q(hi2 - lo2), color=SEPARATED, label="separated"))
    pieces = region["region"]
    if pieces is None:  # the union not formed: its pair polygons shaded one by one
        pieces = [{"outer": p["vertices"], "holes": []} for p in region["pair_regions"] if len(p["vertices"]) >= 3]
    for k, piece in enumerate(pieces):
        rings = [[point(v) for v in r] for r in [piece["outer"]] + piece["holes"]]
        ax.add_patch(PathPatch(ring_path(rings), fc=OVERLAP, ec="none", label="overlap" if k == 0 else None))
    for k, p in enumerate(region["pair_regions"]):
        ring = [point(v) for v in p["vertices"]]
        xs, ys = [q(v[0]) for v in ring + ring[:1]], [q(v[1]) for v in ring + ring[:1]]
        ax.plot(xs, ys, "--", color="gray", lw=0.7, label="a pair's polygon" if k == 0 else None)
    for k, p in enumerate(region["region_without_area"]):
        ring = [point(v) for v in p["vertices"]]
        ax.plot([q(v[0]) for v in ring], [q(v[1]) for v in ring], "-o", color="firebrick", lw=2, ms=4,
                label="pairs meeting without area" if k == 0 else None)
    colors = {}
    for lab, pair, pts in contact_runs(region["boundary"] or []):
        c = colors.setdefault(pair, plt.cm.tab10(len(colors) % 10))
        ax.plot([q(v[0]) for v in pts], [q(v[1]) for v in pts], "-", color=c, lw=2.2)
        label_run(ax, pts, lab, c)
    d0, d1 = max(lo1, lo2), min(hi1, hi2)
    if d0 <= d1:
        ax.plot([q(d0), q(d1)], [q(d0), q(d1)], ":", color="gray", lw=1, label="rho1 = rho2")
    for k, g in enumerate(region["growth_set"]):
        a, b = q(g["from"]), q(g["to"])
        ax.plot([a, b], [a, b], "-", color="green", lw=4, alpha=0.7, solid_capstyle="butt",
                label=f"growth set [{g['from']}, {g['to']}], first {pair_name(g['first_contact'])}")
    for s in region["switch_points"] or []:
        text = "\n".join(f"  {pair_name(c)} {c['contact']}" for c in s["contacts"])
        ax.plot(q(s["rho1"]), q(s["rho2"]), "o", color="darkorange", ms=8, mec="k",
                label=f"switch point {fmt((s['rho1'], s['rho2']))}, new {s['change']}:\n{text}")
    if at is not None:
        ax.plot(q(at[0]), q(at[1]), "*", color="k", ms=9, ls="", label=f"3-D view at {fmt(at)}")
    finish(fig, ax, outdir, "region_rho", "where the compounds overlap", "rho1", "rho2",
           legend_loc="outside", dpi=DPI)


# --- the scene in 3-D ------------------------------------------------------------------------

def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def hull_faces(pts):
    """The convex hull's faces of a few exact points, each a list of point indices in order round
    it: every triple whose plane has all the points on one side spans a face (its points on that
    plane). Flat point sets have none. Exact, in integers (the points times their denominators'
    least common multiple)."""
    if len(pts) > MAX_HULL_POINTS:
        refuse(f"a part has {len(pts)} points; region_3d draws parts of at most {MAX_HULL_POINTS}")
    den = math.lcm(*(Fraction(c).denominator for p in pts for c in p))
    P = [tuple(int(c * den) for c in p) for p in pts]
    faces, seen = [], set()
    for i, j, k in itertools.combinations(range(len(P)), 3):
        if (i, j, k) in seen:
            continue
        u, v = sub(P[j], P[i]), sub(P[k], P[i])
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        if n == (0, 0, 0):
            continue
        off = n[0] * P[i][0] + n[1] * P[i][1] + n[2] * P[i][2]
        above = below = False
        for p in P:
            h = n[0] * p[0] + n[1] * p[1] + n[2] * p[2] - off
            above, below = above or h > 0, below or h < 0
            if above and below:
                break
        if above and below:
            continue
        face = [m for m in range(len(P)) if n[0] * P[m][0] + n[1] * P[m][1] + n[2] * P[m][2] == off]
        seen.update(itertools.combinations(face, 3))
        # order round the face's centre, in float (for drawing only)
        c = [sum(P[m][t] for m in face) / len(face) for t in range(3)]
        e1 = [P[face[0]][t] - c[t] for t in range(3)]
        e2 = [n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]]
        ang = {m: math.atan2(sum((P[m][t] - c[t]) * e2[t] for t in range(3)),
                             sum((P[m][t] - c[t]) * e1[t] for t in range(3))) for m in face}
        faces.append(sorted(face, key=ang.get))
    return faces


def mesh_part(scene):
    """Why region_3d cannot draw the scene (a part given as a mesh or as OBJ groups), or None."""
    for name in ("P1", "P2"):
        obj = scene[name]
        for k, p in enumerate(obj.get("parts", [obj])):
            if "vertices" not in p or obj.get("parts_from_groups"):
                return (f"{name}'s part {k} is not given by \"vertices\" (a mesh or OBJ groups): region_3d draws "
                        f"only parts listed as vertices in the scene")
    return None


def object_parts(scene, name):
    """An object's parts (lists of exact points) and seed (every part given by vertices: mesh_part)."""
    obj = scene[name]
    parts = obj.get("parts", [obj])
    pts = [[point(v) for v in p["vertices"]] for p in parts]
    if "seed" in obj:
        seed = point(obj["seed"])
    else:
        allp = [v for p in pts for v in p]
        seed = tuple(sum(v[t] for v in allp) / len(allp) for t in range(3))
    return pts, seed


def region_3d(scene, region, at, outdir):
    meeting = meeting_at(region, at, rectangle(scene))
    names = part_names(region)
    for obj in ("P1", "P2"):  # and the scene's own names, of parts in no pair the region lists
        for k, p in enumerate(scene[obj].get("parts", [])):
            if isinstance(p, dict) and isinstance(p.get("name"), str):
                names.setdefault((obj, k), p["name"])

    def entry(obj, k):
        return {f"{obj}_part": k, **({f"{obj}_part_name": names[(obj, k)]} if (obj, k) in names else {})}

    fig = plt.figure(figsize=(6.5, 5.5))
    ax = fig.add_subplot(projection="3d")
    drawn = []
    for i, (name, color) in enumerate((("P1", "tab:blue"), ("P2", "tab:orange"))):
        parts, seed = object_parts(scene, name)
        rho = at[i]
        for k, pts in enumerate(parts):
            lit = any(pair[i] == k for pair in meeting)
            V = [tuple(q(s + rho * (c - s)) for c, s in zip(v, seed)) for v in pts]
            polys = [[V[m] for m in f] for f in hull_faces(pts)]
            ax.add_collection3d(Poly3DCollection(polys, facecolor=color, alpha=0.55 if lit else 0.07,
                                                 edgecolor="k" if lit else "gray", lw=0.8 if lit else 0.3))
            drawn += V
            top = [sum(v[0] for v in V) / len(V), sum(v[1] for v in V) / len(V), max(v[2] for v in V)]
            ax.text(*top, part_name(entry(name, k), name), fontsize=8, color="k" if lit else "gray", ha="center", va="bottom", zorder=1000,
                    bbox=dict(boxstyle="round,pad=0.1", fc="white", ec="none", alpha=0.7))
        ax.scatter(*[q(x) for x in seed], marker="+", color=color, s=40)
    lo = [min(v[t] for v in drawn) for t in range(3)]
    hi = [max(v[t] for v in drawn) for t in range(3)]
    for setlim, a, b in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), lo, hi):
        setlim(a, b)
    ax.set_box_aspect([b - a for a, b in zip(lo, hi)], zoom=0.9)
    for axis, a, b in zip((ax.xaxis, ax.yaxis, ax.zaxis), lo, hi):  # fewer ticks on a shorter side
        axis.set_major_locator(MaxNLocator(nbins=max(1, round(4 * (b - a) / max(h - l for l, h in zip(lo, hi))))))
    ax.view_init(elev=22, azim=-62)
    said = [f"{pair_name({**entry('P1', p[0]), **entry('P2', p[1])})} {state}" + (f" {c}" if c else "")
            for p, (state, c) in sorted(meeting.items())] or ["no parts meet"]
    handles = [Patch(facecolor="tab:blue", alpha=0.55, edgecolor="k", label="P1(rho1) parts meeting there"),
               Patch(facecolor="tab:orange", alpha=0.55, edgecolor="k", label="P2(rho2) parts meeting there"),
               Patch(facecolor="gray", alpha=0.1, edgecolor="gray", label="other parts"),
               Line2D([], [], marker="+", color="k", ls="", label="seeds")]
    ax.legend(handles=handles, loc="upper left", fontsize=7)
    ax.set_title(f"rho = {fmt(at)}:\n" + "\n".join(said), fontsize=9)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
    ax.set_zlabel("z")
    save(fig, outdir, "region_3d", DPI)


def default_at(region):
    if region["switch_points"]:
        s = region["switch_points"][0]
        return Fraction(s["rho1"]), Fraction(s["rho2"])
    for ring in region["boundary"] or []:
        for e in ring["edges"]:
            if isinstance(e["on"], dict):
                a, b = point(e["from"]), point(e["to"])
                return (a[0] + b[0]) / 2, (a[1] + b[1]) / 2
    return None


def main():
    args = sys.argv[1:]
    at = None
    if "--at" in args:
        k = args.index("--at")
        if k + 1 >= len(args) or args[k + 1].count(",") != 1:
            refuse("--at wants RHO1,RHO2, e.g. --at 6/7,12/7")
        try:
            at = tuple(Fraction(v) for v in args[k + 1].split(","))
        except (ValueError, ZeroDivisionError):
            refuse(f"--at: {args[k + 1]!r} is not two numbers")
        del args[k:k + 2]
    if len(args) != 3:
        print(__doc__)
        sys.exit(2)
    try:
        with open(args[0]) as f:
            scene = json.load(f, parse_float=Fraction)
        with open(args[1]) as f:
            region = json.load(f)
        rect = rectangle(scene)
    except (OSError, ValueError, ZeroDivisionError, KeyError, TypeError, AttributeError) as e:
        refuse(f"cannot read the scene or the region: {e}")
    if not isinstance(region, dict) or region.get("kind") != "region":
        refuse(f"{args[1]} is not the output of scalecert region")
    if at is not None and not all(rect[c][0] <= at[c] <= rect[c][1] for c in (0, 1)):
        refuse(f"--at: {fmt(at)} lies outside I1 x I2 of {args[0]}")
    outdir = args[2]
    try:
        os.makedirs(outdir, exist_ok=True)
        at = at or default_at(region)
        # region_rho marks the 3-D view's point only when region_3d draws it.
        no_3d = mesh_part(scene)
        region_rho(scene, region, None if no_3d else at, outdir)
        if no_3d:
            print(f"plot_region.py: no region_3d: {no_3d}", file=sys.stderr)
            return
        if at is None:
            print("plot_region.py: no switch point and no edge on a contact: no region_3d (give --at)", file=sys.stderr)
            return
        region_3d(scene, region, at, outdir)
    except (OSError, ValueError, ZeroDivisionError, KeyError, TypeError, AttributeError, IndexError) as e:
        refuse(f"{args[1]} does not fit {args[0]}, or cannot be drawn: {type(e).__name__}: {e}")


if __name__ == "__main__":
    main()
