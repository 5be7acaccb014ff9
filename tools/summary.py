#!/usr/bin/env python3
"""Prints a scalecert curve or partition JSON file as a short table."""
import json
import sys

d = json.load(open(sys.argv[1]))
print("touching curve over I1 (rho2 = slope*rho1 + intercept):")
print(f"  {'rho1 from':>14} {'rho1 to':>14} {'slope':>22} {'intercept':>22}  contact")
for p in d["pieces"]:
    print(f"  {p['rho1'][0]:>14} {p['rho1'][1]:>14} {p['slope']:>22} {p['intercept']:>22}  {p['contact']}")
print("switch points:")
for s in d["switch_points"]:
    print(f"  rho1 = {s['rho1']} (~{s['rho1_double']:.6g}), rho2 = {s['rho2']} (~{s['rho2_double']:.6g}), "
          f"contact {s['contact']}, by equation {s['equation']}")
if not d["switch_points"]:
    print("  none in I1")
g = d["growth_distance"]
where = "inside" if d["growth_distance_in_rectangle"] else "outside"
print(f"growth distance rho* = {g} (~{d['growth_distance_double']:.9g}), {where} the rectangle")
if "regions" in d:
    r = d["regions"]
    print(f"overlap polygon: {len(r['overlap']['vertices'])} vertices, each with a witness point; "
          f"separated polygons: {len(r['separated'])}, each with a separating normal")
