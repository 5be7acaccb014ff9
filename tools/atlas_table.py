#!/usr/bin/env python3
"""The failure atlas as a Markdown table: scalecert audit --atlas's JSON, per class and method.

Usage: tools/atlas_table.py [--by-scene] AUDIT.json

A class is the family of a row's scene (its name without the index); with --by-scene, any audit's
rows per scene (the file's name without its directory and .json) and method. Per class and method: the
wrong verdicts among the queries (each a pair of doubles, judged by the exact verdict of those
doubles), the same among the pairs 2^-k from the exact boundary (with --by-distance), and the
worst relative error of the method's distances and penetration depths against the exact ones. A
method that did not run on a scene (its row's not_run) is counted apart: "3 (1 not run)".
"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import report  # noqa: E402 (its reading of an audit's rows, each field checked)

CLASSES = ["face-to-face", "long-edge", "scaled", "touching", "decomposition-gap", "capsule-hull", "far-spheres",
           "margin-hulls", "sphere-box-edge"]


def main():
    args = sys.argv[1:]
    by_scene = args[:1] == ["--by-scene"]
    if by_scene:
        args = args[1:]
    if len(args) != 1:
        sys.exit(__doc__.strip().splitlines()[2])
    try:
        rows = report.load_rows(args[0])
    except report.InputError as e:
        print("atlas_table: error: %s" % e, file=sys.stderr)
        sys.exit(2)
    table = {}
    for r in rows:
        if "queries" not in r:
            continue  # curve rows
        if by_scene:
            cls = os.path.basename(r["scene"])
            cls = cls[:-5] if cls.endswith(".json") else cls
        else:
            cls = r["scene"].rsplit("-", 1)[0]
            if cls not in CLASSES:
                continue
        t = table.setdefault((cls, r["method"]), {"scenes": 0, "queries": 0, "wrong": 0, "pairs": 0, "near": 0,
                                                  "dist": None, "depth": None, "not_run": 0})
        if r.get("not_run"):  # a method that did not run on the scene: counted apart
            t["not_run"] += 1
            continue
        t["scenes"] += 1
        t["queries"] += r["queries"]
        t["wrong"] += (r.get("false_separated", 0) + r.get("false_overlapping", 0) + r.get("false_touching", 0) +
                       r.get("not_answered", 0))
        for b in r.get("by_distance", []):
            t["pairs"] += b["pairs"]
            t["near"] += b["wrong"]
        for key, src in (("dist", "distance_err_max"), ("depth", "depth_err_max")):
            if r.get(src) is not None:
                t[key] = max(t[key] or 0.0, r[src])
    classes = sorted({c for c, _ in table}) if by_scene else CLASSES
    print("| %s | method | scenes | wrong verdicts | near the boundary | worst distance error | worst depth error |" % ("scene" if by_scene else "class"))
    print("|---|---|---|---|---|---|---|")
    fmt = lambda e: "—" if e is None else "%.2g" % e
    # A scene's or method's name as a Markdown cell: its bars escaped, its line ends as spaces.
    cell = lambda t: t.replace("\\", "\\\\").replace("|", "\\|").replace("\r", " ").replace("\n", " ")
    for cls in classes:
        for (c, m), t in sorted(table.items()):
            if c != cls:
                continue
            near = "%d / %d" % (t["near"], t["pairs"]) if t["pairs"] else "—"
            scenes = "%d" % t["scenes"] + (" (%d not run)" % t["not_run"] if t["not_run"] else "")
            print("| %s | %s | %s | %d / %d | %s | %s | %s |" % (cell(cls), cell(m), scenes, t["wrong"], t["queries"], near,
                                                              fmt(t["dist"]), fmt(t["depth"])))


if __name__ == "__main__":
    main()
