#!/usr/bin/env python3
"""The failure atlas as a Markdown table: scalecert audit --atlas's JSON, per class and method.

Usage: tools/atlas_table.py AUDIT.json

A class is the family of a row's scene (its name without the index). Per class and method: the
wrong verdicts among the queries (each a pair of doubles, judged by the exact verdict of those
doubles), the same among the pairs 2^-k from the exact boundary (with --by-distance), and the
worst relative error of the method's distances and penetration depths against the exact ones.
"""
import json
import sys

CLASSES = ["face-to-face", "long-edge", "scaled", "touching", "decomposition-gap"]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.strip().splitlines()[-5])
    try:
        with open(sys.argv[1]) as f:
            rows = json.load(f)
        assert isinstance(rows, list) and all(isinstance(r, dict) and "scene" in r for r in rows)
    except (OSError, ValueError, AssertionError) as e:
        print("atlas_table: error: %s: not an audit's JSON (%s)" % (sys.argv[1], e or "rows"), file=sys.stderr)
        sys.exit(2)
    table = {}
    for r in rows:
        if "queries" not in r:
            continue  # curve rows
        cls = r["scene"].rsplit("-", 1)[0]
        if cls not in CLASSES:
            continue
        t = table.setdefault((cls, r["method"]), {"scenes": 0, "queries": 0, "wrong": 0, "pairs": 0, "near": 0,
                                                  "dist": None, "depth": None})
        t["scenes"] += 1
        t["queries"] += r["queries"]
        t["wrong"] += r.get("false_separated", 0) + r.get("false_overlapping", 0)
        for b in r.get("by_distance", []):
            t["pairs"] += b["pairs"]
            t["near"] += b["wrong"]
        for key, src in (("dist", "distance_err_max"), ("depth", "depth_err_max")):
            if src in r:
                t[key] = max(t[key] or 0.0, r[src])
    print("| class | method | scenes | wrong verdicts | near the boundary | worst distance error | worst depth error |")
    print("|---|---|---|---|---|---|---|")
    fmt = lambda e: "—" if e is None else "%.2g" % e
    for cls in CLASSES:
        for (c, m), t in sorted(table.items()):
            if c != cls:
                continue
            near = "%d / %d" % (t["near"], t["pairs"]) if t["pairs"] else "—"
            print("| %s | %s | %d | %d / %d | %s | %s | %s |" % (cls, m, t["scenes"], t["wrong"], t["queries"], near,
                                                              fmt(t["dist"]), fmt(t["depth"])))


if __name__ == "__main__":
    main()
