#!/usr/bin/env python3
"""An audit as a page to look at: scalecert audit's JSON as one HTML report.

Usage: tools/report.py AUDIT.json --out report.html [--failures DIR] [--scalecert PROGRAM]

The page has, from the audit's rows: the failure atlas's table (per class and method, when the
audit ran --atlas), a table per scene and method (queries, wrong verdicts each way, time per query), a chart of the wrong verdicts per method, a chart of the fraction wrong by
relative distance 2^-k from the exact boundary (audits run with --by-distance), and the list of
failures (the first 50 a row keeps: the doubles asked, what the method said, the exact verdict).
A click on a failure shows its numbers and a 3-D view of the two bodies scaled to that pair, as
scalecert reads the scene (`scalecert query SCENE 1 1 --json`: its meshes, parts and poses), with
the scene found by the row's scene path (as given or beside the audit's JSON) or, for a family
scene or a mesh pair, in the --failures directory. Of objects made of parts, the part pairs that
meet at the failure's pair, or else come nearest to meeting (their polygons of meeting pairs from
`scalecert region SCENE`), are marked.
The charts are SVG drawn by the page's own script; three.js (Debian's libjs-three) draws the
bodies, each part as its convex hull, and is inlined: the page is one file that works offline
(about 0.9 MB of it three.js). Bad input: one line on stderr, exit 2, nothing written.
"""
import argparse
import html
import json
import math
import os
import sys
import shutil
import stat
import subprocess
import tempfile
from fractions import Fraction

THREE = "/usr/share/javascript/three"
SCRIPTS = [THREE + "/three.min.js", THREE + "/examples/js/math/ConvexHull.js",
           THREE + "/examples/js/geometries/ConvexGeometry.js", THREE + "/examples/js/controls/OrbitControls.js"]


class InputError(Exception):
    pass


def scalecert_program(given):
    """The scalecert program that reads the scenes: --scalecert, $SCALECERT_BIN, scalecert on
    PATH, or this tree's build/scalecert; None when there is none."""
    here = os.path.dirname(os.path.abspath(__file__))
    for c in (given, os.environ.get("SCALECERT_BIN"), shutil.which("scalecert"),
              os.path.join(here, "..", "build", "scalecert")):
        if c and os.path.isfile(c) and os.access(c, os.X_OK):
            return c
    if given:
        raise InputError("%s: no such program (--scalecert)" % given)
    return None


MAX_OUTPUT = 1 << 30  # bytes of a scalecert answer read (a 10^6-point scene's is about 100 MB)


def run_scalecert(program, args, timeout):
    """scalecert's standard output for args, parsed as JSON, or None when it fails, runs past
    `timeout` seconds or writes more than MAX_OUTPUT bytes. It runs in a session of its own, all
    of which is killed then."""
    import select
    import signal
    import time
    try:
        p = subprocess.Popen([program] + args, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, start_new_session=True)
    except OSError:
        return None
    chunks, size, until = [], 0, time.monotonic() + timeout
    try:
        while True:
            left = until - time.monotonic()
            if left <= 0 or size > MAX_OUTPUT:
                return None
            ready, _, _ = select.select([p.stdout], [], [], left)
            if not ready:
                continue
            chunk = os.read(p.stdout.fileno(), 1 << 20)
            if not chunk:
                break
            chunks.append(chunk)
            size += len(chunk)
        if p.wait(timeout=max(0.1, until - time.monotonic())) != 0:
            return None
        return json.loads(b"".join(chunks))
    except (OSError, ValueError, RecursionError, subprocess.TimeoutExpired):
        return None
    finally:
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except OSError:
            pass
        p.stdout.close()
        p.wait()


def bodies(scene_path, program):
    """[{"parts", "seed"}] for P1 and P2 as scalecert reads the scene (its poses applied, its
    meshes read, its parts from groups), taken from `scalecert query SCENE 1 1 --json`, whose
    "scene" holds every point exactly; in doubles, for display. None when it cannot be read."""
    try:
        answer = run_scalecert(program, ["query", scene_path, "1", "1", "--json"], 120)
        if answer is None:
            return None
        scene = answer["scene"]
        out = []
        for key in ("P1", "P2"):
            obj = scene[key]
            parts = [part["vertices"] for part in obj["parts"]] if "parts" in obj else [obj["vertices"]]
            out.append({"parts": [[[float(Fraction(c)) for c in v] for v in part] for part in parts],
                        "seed": [float(Fraction(c)) for c in obj["seed"]]})
        if "parts" in scene["P1"] or "parts" in scene["P2"]:
            out.append({"pairs": pair_regions(scene_path, program)})
        return out
    except (OSError, ValueError, KeyError, TypeError, ZeroDivisionError, OverflowError, RecursionError):
        return None


def pair_regions(scene_path, program):
    """Objects made of parts: each part pair that meets somewhere in I1 x I2, with the polygon of
    (rho1, rho2) where it does (`scalecert region SCENE`, exact; in doubles here, to mark in the
    3-D view the parts that meet, or come nearest to meeting, at a failure's pair)."""
    region = run_scalecert(program, ["region", scene_path], 300)
    if region is None:
        return []
    return [{"a": r["P1_part"], "b": r["P2_part"], "a_name": r.get("P1_part_name", ""),
             "b_name": r.get("P2_part_name", ""),
             "poly": [[float(Fraction(x)), float(Fraction(y))] for x, y in r["vertices"]]}
            for r in region["pair_regions"]]


def scene_file(row, audit_dir, failures_dir):
    """The scene file a row names (as given, or relative to the audit's directory), or the scene
    the --failures directory holds for it (a family scene at its eps, a mesh pair's scene)."""
    name = row["scene"]
    for p in (name, os.path.join(audit_dir, name)):
        if os.path.isfile(p):
            return p
    if failures_dir:
        eps = str(row.get("eps", "0")).replace("/", "_")
        base = os.path.basename(name)
        for p in ("%s.eps-%s.scene.json" % (base, eps), "%s.scene.json" % base):
            p = os.path.join(failures_dir, p)
            if os.path.isfile(p):
                return p
    return None


def check(cond, path, what):
    if not cond:
        raise InputError("%s: not an audit (%s)" % (path, what))


def number(v):
    """A finite JSON number that fits a double (a NaN, an infinity or an integer of 400 digits is not)."""
    if not isinstance(v, (int, float)) or isinstance(v, bool):
        return False
    try:
        return math.isfinite(float(v))
    except OverflowError:
        return False


def load_rows(path):
    """The rows of scalecert audit's JSON, each field the page uses checked for its type."""
    try:
        if not os.path.exists(path):
            raise InputError("%s: no such file" % path)
        if not os.path.isfile(path):  # a directory or a FIFO is not an audit, nor waited on
            raise InputError("%s: not a regular file" % path)
        with open(path, encoding="utf-8") as f:
            rows = json.load(f)
    except OSError as e:
        raise InputError("%s: cannot read (%s)" % (path, e.strerror))
    except (ValueError, RecursionError) as e:
        raise InputError("%s: not JSON (%s)" % (path, str(e).splitlines()[0] if str(e) else type(e).__name__))
    if isinstance(rows, dict) and isinstance(rows.get("rows"), list):
        rows = rows["rows"]
    check(isinstance(rows, list), path, "scalecert audit's JSON is a list of rows")
    for i, r in enumerate(rows):
        at = "row %d" % i
        check(isinstance(r, dict) and isinstance(r.get("scene"), str) and isinstance(r.get("method"), str), path,
              at + ": a row has a scene and a method, as text")
        if "queries" not in r:
            continue
        count = lambda x: isinstance(x, int) and not isinstance(x, bool) and x >= 0
        check(count(r["queries"]), path, at + ": queries is a count")
        for k in ("false_separated", "false_overlapping", "false_touching"):
            check(count(r.get(k, 0)) and r.get(k, 0) <= r["queries"], path, at + ": %s is a count of its queries" % k)
        check(r.get("seconds_per_query") is None or number(r["seconds_per_query"]), path,
              at + ": seconds_per_query is a number")
        check(isinstance(r.get("eps", "0"), (str, int, float)), path, at + ": eps is a number")
        bd = r.get("by_distance", [])
        check(isinstance(bd, list) and all(isinstance(b, dict) and all(number(x) for x in b.values()) and
                                           isinstance(b.get("pairs"), int) and isinstance(b.get("wrong"), int)
                                           for b in bd), path, at + ": by_distance is a list of counts")
        for k in ("distance_err_max", "depth_err_max"):
            check(r.get(k) is None or number(r[k]), path, at + ": %s is a number" % k)
        fs = r.get("failures", [])
        check(isinstance(fs, list) and all(isinstance(f, dict) and number(f.get("rho1")) and number(f.get("rho2"))
                                           for f in fs), path, at + ": failures is a list of pairs rho1, rho2")
        check(count(r.get("measures_wrong", 0)), path, at + ": measures_wrong is a count")
        ms = r.get("measure_failures", [])
        check(isinstance(ms, list) and all(isinstance(m, dict) and all(number(m.get(k)) for k in
                                                                       ("rho1", "rho2", "value", "rel_error")) and
                                           m.get("kind") in ("distance", "penetration_depth") for m in ms), path,
              at + ": measure_failures is a list of measures (rho1, rho2, kind, value, rel_error)")
    return rows


def page(rows, audit_dir, failures_dir, program, scripts):
    scenes, data_rows, failures, measures = {}, [], [], []
    for r in rows:
        if "queries" not in r:
            continue  # curve rows (the exact engine, the grid): no verdicts to chart
        key = r["scene"]
        if key not in scenes:
            f = scene_file(r, audit_dir, failures_dir) if program else None
            scenes[key] = bodies(f, program) if f else None
            if program and not f and r.get("failures"):
                print("report.py: note: %s: not found from here nor beside the audit (the audit names scenes relative "
                      "to the folder it ran in; give --failures DIR for family and mesh-pair scenes), so its failures "
                      "get no 3-D view" % key, file=sys.stderr)
            if f and scenes[key] is None:
                print("report.py: note: %s: `%s query` gave no bodies, so its failures get no 3-D view"
                      % (f, program), file=sys.stderr)
        data_rows.append({
            "scene": key, "method": r["method"], "eps": str(r.get("eps", "0")), "queries": r["queries"],
            "false_separated": r.get("false_separated", 0), "false_overlapping": r.get("false_overlapping", 0),
            "false_touching": r.get("false_touching", 0), "measures_wrong": r.get("measures_wrong", 0),
            "seconds_per_query": r.get("seconds_per_query"), "by_distance": r.get("by_distance", []),
            "not_answered": r.get("not_answered", 0), "not_run": r.get("not_run", "")})
        for f in r.get("failures", []):
            failures.append(dict(f, scene=key, method=r["method"]))
        for m in r.get("measure_failures", []):
            measures.append({"scene": key, "method": r["method"], "rho1": m["rho1"], "rho2": m["rho2"],
                             "kind": m["kind"], "value": m["value"], "rel_error": m["rel_error"],
                             "parts": m.get("parts", "")})
    doc = {"rows": data_rows, "failures": failures, "measures": measures, "scenes": scenes}
    title = "scalecert audit: %d rows, %d listed failures, %d listed distances and depths off" % (
        len(data_rows), len(failures), len(measures))
    scripts = "\n".join("<script>\n%s\n</script>" % js.replace("</script", "<\\/script") for js in scripts)
    return TEMPLATE.replace("@TITLE@", html.escape(title)).replace("@SCRIPTS@", scripts).replace(
        "@DATA@", json.dumps(doc, sort_keys=True).replace("<", "\\u003c"))


TEMPLATE = r"""<!DOCTYPE html>
<html lang="en"><head><meta charset="utf-8"><title>@TITLE@</title>
<style>
body { font-family: sans-serif; margin: 1.5em; color: #222; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em; }
td, th { border: 1px solid #ccc; padding: 3px 8px; text-align: right; }
td:first-child, td:nth-child(2) { text-align: left; }
#failures tr.f { cursor: pointer; }
#failures tr.f:hover { background: #eef; }
#view { width: 600px; height: 420px; border: 1px solid #ccc; }
.chart { width: 900px; height: 380px; }
#failure-pane { display: flex; gap: 1.5em; align-items: flex-start; }
#failure-list { max-height: 480px; overflow: auto; }
#detail { font-size: 85%; }
body.only-view > *:not(#failure-pane), body.only-view #failure-list, body.only-view #detail,
body.only-charts > *:not(.chart), body.only-charts #failure-pane { display: none; }
</style>
@SCRIPTS@
</head><body>
<h1>@TITLE@</h1>
<div id="status">loading</div>
<div id="atlas-section"><h2>Failure atlas</h2>
<p>Per class of reported failure (audit --atlas; docs/audits.md, "The failure atlas") and method:
wrong verdicts among the queries, and among the pairs near the exact boundary.</p>
<table id="atlas"></table></div>
<h2>Rows</h2><table id="rows"></table>

<div id="chart-wrong" class="chart"></div>
<div id="chart-distance" class="chart"></div>
<h2>Failures</h2>
<p>Each failure is a pair of doubles the method was asked, what it said and the exact verdict. Click
one for its numbers and the two bodies at that pair (P1 blue, P2 orange, each part as its convex hull; of objects made of parts, the parts that meet at that pair, or
else come nearest to meeting, are drawn opaque and edged in red).</p>
<div id="failure-pane">
<div id="failure-list"><table id="failures"></table></div>
<div><div id="view"></div><pre id="detail"></pre></div>
</div>
<div id="measures-section"><h2>Distances and depths</h2>
<p>Where a method's distance or penetration depth was off by more than the audit's
--measure-tolerance (relative): the worst of each row, with the pair asked, the value it gave and
its relative error against the exact one (--failures writes them as claims that certify-fp replays).
The worst first: the first 250 are drawn with the page, the rest on request.</p>
<table id="measures"></table><button id="measures-more" style="display:none"></button></div>
<script>
"use strict";
const D = @DATA@;
// #view or #charts: that part of the page alone (the browser test's screenshots).
if (location.hash === "#view") document.body.className = "only-view";
if (location.hash === "#charts") document.body.className = "only-charts";
const status = {charts: 0, view: 0};
function say() {
  document.getElementById("status").textContent = "charts drawn: " + status.charts + "; 3-D views drawn: " + status.view;
}
function cell(tr, text, tag) { const c = document.createElement(tag || "td"); c.textContent = text; tr.appendChild(c); }
// The rows' table.
const rt = document.getElementById("rows");
let tr = rt.insertRow();
for (const h of ["scene", "method", "eps", "queries", "wrong: said separated", "wrong: said intersecting", "wrong: said touching", "no answer", "distances and depths wrong", "µs per query", "not run"]) cell(tr, h, "th");
for (const r of D.rows) {
  tr = rt.insertRow();
  for (const v of [r.scene.split("/").pop(), r.method, r.eps, r.queries, r.false_separated, r.false_overlapping,
                   r.false_touching, r.not_answered, r.method.startsWith("command (") ? "—" : r.measures_wrong,
                   r.not_run || r.seconds_per_query == null ? "" : (1e6 * r.seconds_per_query).toPrecision(3), r.not_run]) cell(tr, v);
}
// The atlas table: rows of the atlas's families, per class and method.
const classes = ["face-to-face", "long-edge", "scaled", "touching", "decomposition-gap", "capsule-hull", "far-spheres", "margin-hulls", "sphere-box-edge"];
const atlas = {};
for (const r of D.rows) {
  const cls = r.scene.replace(/-[0-9]+$/, "");
  if (!classes.includes(cls) || r.not_run) continue;  // (a method not run on a scene is in the rows' table)
  const a = atlas[cls + "\u0000" + r.method] = atlas[cls + "\u0000" + r.method] || {cls, method: r.method, scenes: 0, queries: 0, wrong: 0, pairs: 0, near: 0};
  a.scenes++; a.queries += r.queries; a.wrong += r.false_separated + r.false_overlapping + r.false_touching + r.not_answered;
  for (const b of r.by_distance) { a.pairs += b.pairs; a.near += b.wrong; }
}
const at = document.getElementById("atlas");
const atlasRows = Object.values(atlas).sort((x, y) => classes.indexOf(x.cls) - classes.indexOf(y.cls) || (x.method < y.method ? -1 : 1));
if (atlasRows.length) {
  tr = at.insertRow();
  for (const h of ["class", "method", "scenes", "wrong verdicts", "near the boundary"]) cell(tr, h, "th");
  for (const a of atlasRows) {
    tr = at.insertRow();
    for (const v of [a.cls, a.method, a.scenes, a.wrong + " / " + a.queries + " (" + (100 * a.wrong / a.queries).toFixed(1) + "%)",
                     a.pairs ? a.near + " / " + a.pairs : "—"]) cell(tr, v);
  }
} else {
  document.getElementById("atlas-section").style.display = "none";
}
// Charts (SVG): only with data; one colour and one marker per method, a legend clear of the plot.
const colours = ["#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"];
// The charts draw the rows whose method ran (a row that did not run says why in the table).
const ran = D.rows.filter(r => !r.not_run);
const methods = [...new Set(ran.map(r => r.method))];
const colourOf = m => colours[methods.indexOf(m) % colours.length];
const markerOf = m => methods.indexOf(m) % 6;
const scenes = new Set(D.rows.map(r => r.scene)).size;
const NS = "http://www.w3.org/2000/svg";
function el(parent, tag, attrs, text) {
  const e = document.createElementNS(NS, tag);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (text !== undefined) e.textContent = text;
  parent.appendChild(e);
  return e;
}
// Round tick values from 0 to at least `top`.
function ticks(top) {
  if (!(top > 0)) top = 1;
  const raw = top / 5, p = Math.pow(10, Math.floor(Math.log10(raw)));
  const step = [1, 2, 5, 10].map(f => f * p).find(x => x >= raw);
  const out = [];
  for (let v = 0; v < top + step / 2; v += step) out.push(+v.toPrecision(12));
  if (out[out.length - 1] < top) out.push(+(out[out.length - 1] + step).toPrecision(12));
  return out;
}
function marker(g, kind, x, y, colour) {
  const r = 5, a = {fill: colour, stroke: colour};
  if (kind === 0) return el(g, "circle", Object.assign({cx: x, cy: y, r: r}, a));
  if (kind === 1) return el(g, "rect", Object.assign({x: x - r, y: y - r, width: 2 * r, height: 2 * r}, a));
  const pts = {2: [[0, -1.3], [1.1, 0], [0, 1.3], [-1.1, 0]], 3: [[0, -1.2], [1.1, 0.8], [-1.1, 0.8]],
               4: [[0, 1.2], [1.1, -0.8], [-1.1, -0.8]], 5: [[-1, -1], [1, 1], [0, 0], [1, -1], [-1, 1], [0, 0]]}[kind];
  return el(g, kind === 5 ? "polyline" : "polygon", Object.assign({points: pts.map(([u, v]) => (x + r * u) + "," + (y + r * v)).join(" ")},
            kind === 5 ? {fill: "none", stroke: colour, "stroke-width": 2.5} : a));
}
// A frame: title, y axis with ticks and grid, x axis label; returns the plot area and the y scale.
function frame(id, title, ylabel, xlabel, top) {
  const W = 900, H = 380, L = 70, R = 260, T = 40, B = 55;
  const svg = el(document.getElementById(id), "svg", {width: W, height: H, viewBox: "0 0 " + W + " " + H, "font-size": 12});
  el(svg, "text", {x: L, y: 22, "font-size": 15}, title);
  const ys = ticks(top), ymax = ys[ys.length - 1];
  const y = v => T + (H - T - B) * (1 - v / ymax);
  for (const v of ys) {
    el(svg, "line", {x1: L, x2: W - R, y1: y(v), y2: y(v), stroke: "#e4e4e4"});
    el(svg, "text", {x: L - 6, y: y(v) + 4, "text-anchor": "end"}, String(v));
  }
  el(svg, "line", {x1: L, x2: W - R, y1: y(0), y2: y(0), stroke: "#444"});
  el(svg, "text", {x: 16, y: T + (H - T - B) / 2, transform: "rotate(-90 16 " + (T + (H - T - B) / 2) + ")", "text-anchor": "middle"}, ylabel);
  el(svg, "text", {x: L + (W - R - L) / 2, y: H - 10, "text-anchor": "middle"}, xlabel);
  return {svg, L, R: W - R, T, B: H - B, y, legendX: W - R + 20};
}
function legend(f, entries) {  // [label, colour, marker or null]
  entries.forEach(([label, colour, kind], i) => {
    const y = f.T + 10 + 20 * i;
    if (kind === null) el(f.svg, "rect", {x: f.legendX, y: y - 6, width: 14, height: 12, fill: colour});
    else { el(f.svg, "line", {x1: f.legendX - 4, x2: f.legendX + 18, y1: y, y2: y, stroke: colour, "stroke-width": 2.5}); marker(f.svg, kind, f.legendX + 7, y, colour); }
    el(f.svg, "text", {x: f.legendX + 26, y: y + 4}, label);
  });
}
if (ran.length) {
  const sum = (m, k) => ran.filter(r => r.method === m).reduce((a, r) => a + r[k], 0);
  const series = [["said separated (they meet)", "#d62728", "false_separated"], ["said intersecting (they are apart)", "#1f77b4", "false_overlapping"],
                  ["said touching (they do not touch)", "#9467bd", "false_touching"]];
  if (ran.some(r => r.not_answered)) series.push(["no answer (a program's claim)", "#7f7f7f", "not_answered"]);
  const top = Math.max(...methods.map(m => Math.max(...series.map(s => sum(m, s[2])))));
  const f = frame("chart-wrong", "Wrong verdicts per method (" + scenes + " scene" + (scenes === 1 ? "" : "s") + ", " +
                  ran.reduce((a, r) => a + r.queries, 0) + " queries)", "wrong verdicts", "method", top);
  const slot = (f.R - f.L) / methods.length, bw = Math.min(40, slot / 3);
  methods.forEach((m, i) => {
    const cx = f.L + slot * (i + 0.5);
    series.forEach(([name, colour, key], j) => {
      const v = sum(m, key), x = cx + (j - series.length / 2) * bw;
      el(f.svg, "rect", {x: x, y: f.y(v), width: bw, height: f.y(0) - f.y(v), fill: colour}).appendChild(
        document.createElementNS(NS, "title")).textContent = m + ": " + v + " " + name;
    });
    el(f.svg, "text", {x: cx, y: f.B + 16, "text-anchor": "middle", "font-size": 11}, m);
  });
  legend(f, series.map(([name, colour]) => [name, colour, null]));
  status.charts++;
}
const withDistance = D.rows.filter(r => r.by_distance.length);
if (withDistance.length) {
  const ms = methods.filter(m => withDistance.some(r => r.method === m));
  const lines = ms.map(m => {
    const ks = withDistance.find(r => r.method === m).by_distance.map(b => b.k);
    return {m, pts: ks.map(k => { let w = 0, n = 0;
      for (const r of withDistance.filter(r => r.method === m)) for (const b of r.by_distance) if (b.k === k) { w += b.wrong; n += b.pairs; }
      return [k, n ? w / n : null]; }).filter(p => p[1] !== null)};
  });
  const ks = lines.flatMap(l => l.pts.map(p => p[0])), kmin = Math.min(...ks), kmax = Math.max(...ks);
  const f = frame("chart-distance", "Fraction wrong at relative distance 2^-k from the exact boundary (" + withDistance.length +
                  " rows)", "fraction wrong", "k", Math.max(...lines.flatMap(l => l.pts.map(p => p[1]))));
  const x = k => f.L + 20 + (f.R - f.L - 40) * (kmax > kmin ? (k - kmin) / (kmax - kmin) : 0.5);
  for (const k of [...new Set(ks)].sort((a, b) => a - b)) el(f.svg, "text", {x: x(k), y: f.B + 16, "text-anchor": "middle"}, String(k));
  for (const l of lines) {
    const colour = colourOf(l.m);
    el(f.svg, "polyline", {points: l.pts.map(([k, v]) => x(k) + "," + f.y(v)).join(" "), fill: "none", stroke: colour, "stroke-width": 2.5});
    for (const [k, v] of l.pts) marker(f.svg, markerOf(l.m), x(k), f.y(v), colour);
  }
  legend(f, ms.map(m => [m, colourOf(m), markerOf(m)]));
  status.charts++;
}
say();
// The failures, and the 3-D view of one.
// The distances and depths off by more than the tolerance.
if (D.measures.length) {
  // Thousands of rows take seconds to lay out: the worst 250 with the page, the others on request.
  const mt = document.getElementById("measures"), shown = 250;
  const worst = D.measures.map((m, i) => [m, i]).sort((a, b) => b[0].rel_error - a[0].rel_error || a[1] - b[1]).map(p => p[0]);
  tr = mt.insertRow();
  for (const h of ["scene", "method", "rho1", "rho2", "kind", "value", "relative error", "parts"]) cell(tr, h, "th");
  const rows = (from, to) => {
    for (const m of worst.slice(from, to)) {
      tr = mt.insertRow();
      for (const v of [m.scene.split("/").pop(), m.method, m.rho1, m.rho2, m.kind, m.value, m.rel_error.toPrecision(3),
                       Array.isArray(m.parts) ? m.parts.join(", ") : ""]) cell(tr, v);
    }
  };
  rows(0, shown);
  if (worst.length > shown) {
    const more = document.getElementById("measures-more");
    more.textContent = "Show the other " + (worst.length - shown);
    more.style.display = "";
    more.onclick = () => { rows(shown, worst.length); more.style.display = "none"; };
  }
} else {
  document.getElementById("measures-section").style.display = "none";
}
const ft = document.getElementById("failures");
tr = ft.insertRow();
for (const h of ["scene", "method", "rho1", "rho2", "said", "exact"]) cell(tr, h, "th");
D.failures.forEach((f, i) => {
  tr = ft.insertRow(); tr.className = "f"; tr.id = "failure-" + i;
  for (const v of [f.scene.split("/").pop(), f.method, f.rho1, f.rho2, f.said, f.exact]) cell(tr, v);
  tr.onclick = () => show(i);
});
let renderer = null;
// The distance from (x, y) to a convex polygon (its vertices in order), negative inside (minus the
// distance to its boundary); +Infinity for an empty one. Display only: doubles.
function polygonDistance(poly, x, y) {
  if (!poly.length) return Infinity;
  let out = Infinity, inside = poly.length > 2, sign = 0;
  for (let k = 0; k < poly.length; k++) {
    const [ax, ay] = poly[k], [bx, by] = poly[(k + 1) % poly.length];
    const ex = bx - ax, ey = by - ay, len2 = ex * ex + ey * ey;
    const t = len2 > 0 ? Math.max(0, Math.min(1, ((x - ax) * ex + (y - ay) * ey) / len2)) : 0;
    out = Math.min(out, Math.hypot(x - ax - t * ex, y - ay - t * ey));
    const cross = ex * (y - ay) - ey * (x - ax);
    if (cross !== 0) { if (sign === 0) sign = Math.sign(cross); else if (Math.sign(cross) !== sign) inside = false; }
  }
  return inside || out === 0 ? -out : out;
}
function show(i) {
  const f = D.failures[i];
  document.getElementById("detail").textContent = JSON.stringify(f, null, 1);
  const geo = D.scenes[f.scene];
  const view = document.getElementById("view");
  if (!geo) { view.textContent = "no geometry: the scene file was not found when the page was made (the audit names it relative to the folder it ran in)"; return; }
  view.textContent = "";
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xffffff);
  const box = new THREE.Box3();
  // Objects made of parts: the part pairs that meet at this pair, or else come nearest to meeting
  // (whose polygon of meeting (rho1, rho2) lies nearest), are marked: drawn opaque, edged in red.
  const marked = [new Set(), new Set()];
  const pairs = geo.length > 2 ? geo[2].pairs : [];
  if (pairs.length) {
    const d = pairs.map(q => polygonDistance(q.poly, f.rho1, f.rho2));
    const inside = d.some(x => x <= 0), least = Math.min(...d);
    const chosen = pairs.filter((q, k) => inside ? d[k] <= 0 : d[k] <= least * (1 + 1e-9));
    for (const q of chosen) { marked[0].add(q.a); marked[1].add(q.b); }
    const name = (i, k, n) => "P" + (i + 1) + " part " + k + (n ? " (" + n + ")" : "");
    document.getElementById("detail").textContent += "\n" + (inside ? "meeting here: " : "nearest to meeting: ") +
      chosen.map(q => name(0, q.a, q.a_name) + " with " + name(1, q.b, q.b_name)).join("; ");
  }
  // P2 first and fainter, P1 drawn over it: a body inside the other stays in sight.
  [[geo[1], f.rho2, 0xff7f0e, 0.35, 0, 1], [geo[0], f.rho1, 0x1f77b4, 0.8, 1, 0]].forEach(([obj, rho, colour, faint, order, side]) => {
    obj.parts.forEach((part, index) => {
      const mark = marked[side].has(index), opacity = mark ? 0.9 : faint;
      const pts = part.map(v => new THREE.Vector3(...v.map((c, k) => obj.seed[k] + rho * (c - obj.seed[k]))));
      const g = new THREE.ConvexBufferGeometry(pts);
      const mesh = new THREE.Mesh(g, new THREE.MeshLambertMaterial({color: colour, transparent: true, opacity: opacity,
                                                                     depthWrite: false}));
      mesh.renderOrder = order;
      scene.add(mesh);
      scene.add(new THREE.LineSegments(new THREE.EdgesGeometry(g),
                                       new THREE.LineBasicMaterial({color: mark ? 0xd62728 : 0x333333})));
      box.expandByObject(mesh);
    });
  });
  scene.add(new THREE.AmbientLight(0xffffff, 0.6));
  const light = new THREE.DirectionalLight(0xffffff, 0.6); light.position.set(1, 2, 3); scene.add(light);
  const c = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3()).length() || 1;
  const camera = new THREE.PerspectiveCamera(45, view.clientWidth / view.clientHeight, size / 100, size * 10);
  camera.up.set(0, 0, 1);  // z up, as robot scenes are written
  camera.position.set(c.x + 1.1 * size, c.y - 1.3 * size, c.z + 0.5 * size); camera.lookAt(c);
  if (renderer) renderer.dispose();
  renderer = new THREE.WebGLRenderer({antialias: true});
  renderer.setSize(view.clientWidth, view.clientHeight);
  view.appendChild(renderer.domElement);
  const controls = new THREE.OrbitControls(camera, renderer.domElement); controls.target.copy(c); controls.update();
  const draw = () => renderer.render(scene, camera);
  controls.addEventListener("change", draw);
  draw();
  status.view++; say();
}
if (D.failures.length) show(0);
say();
// Milliseconds from the start of navigation to a drawn page (docs/audits.md measures the load by it).
document.getElementById("status").dataset.ms = performance.now().toFixed(0);
</script>
</body></html>
"""


def main():
    ap = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    ap.add_argument("audit", help="scalecert audit's JSON (--out)")
    ap.add_argument("--out", required=True, help="the HTML page (one file, its scripts inlined)")
    ap.add_argument("--failures", help="the audit's --failures directory (the family scenes' files)")
    ap.add_argument("--scalecert", help="the scalecert program that reads the scenes (default: $SCALECERT_BIN, "
                    "scalecert on PATH, or build/scalecert)")
    a = ap.parse_args()
    tmp = None
    try:
        scripts = []
        for s in SCRIPTS:
            if not os.path.isfile(s):
                raise InputError("%s is missing (tools/install-deps.sh installs libjs-three)" % s)
            with open(s, encoding="utf-8") as f:
                scripts.append(f.read())
        rows = load_rows(a.audit)
        if a.failures and not os.path.isdir(a.failures):
            raise InputError("%s: no such directory (--failures)" % a.failures)
        if os.path.exists(a.out) and os.path.samefile(a.out, a.audit):
            raise InputError("%s: --out would replace the audit it reads" % a.out)
        program = scalecert_program(a.scalecert)
        if not a.out or os.path.isdir(a.out):
            raise InputError("%r: --out names no file" % a.out)
        if os.path.lexists(a.out) and not stat.S_ISREG(os.lstat(a.out).st_mode):
            # as every scalecert command's --out: a device, a FIFO or a symbolic link is not replaced
            raise InputError("%s: exists and is not a regular file (refused as an output)" % a.out)
        out_dir = os.path.dirname(os.path.abspath(a.out))
        if not os.path.isdir(out_dir):
            raise InputError("%s: no such directory for --out" % out_dir)
        text = page(rows, os.path.dirname(os.path.abspath(a.audit)), a.failures, program, scripts)
        # Written beside the page under a temporary name, then renamed; removed if that fails.
        with tempfile.NamedTemporaryFile("w", dir=out_dir, delete=False, prefix=".report.", suffix=".html",
                                         encoding="utf-8") as f:
            tmp = f.name
            f.write(text)
        os.chmod(tmp, 0o644)
        os.replace(tmp, a.out)
        tmp = None
    except (InputError, OSError) as e:
        print("report: error: %s" % e, file=sys.stderr)
        sys.exit(2)
    finally:
        if tmp:
            try:
                os.unlink(tmp)
            except OSError:
                pass
    if program is None:
        print("report: note: no scalecert program found (--scalecert): the page has no 3-D views", file=sys.stderr)
    print("report: wrote %s (%d bytes)" % (a.out, len(text.encode())), file=sys.stderr)


if __name__ == "__main__":
    main()
