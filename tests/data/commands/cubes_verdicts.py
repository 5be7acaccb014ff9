#!/usr/bin/env python3
"""A user's program for `scalecert audit --command` (tests/test_cli.cpp): verdicts on the stacked
cubes (certificates/scenes/stacked_cubes.json), which touch where rho1 + rho2 = 3.

Usage: cubes_verdicts.py MODE SCENE.json PAIRS.json CLAIMS.json, MODE "exact" (the sum of the two
doubles taken exactly) or "float32" (each rounded to float32 and summed in float32, as a careless
program might), optionally followed by "+WAY" words that make it a hostile guest (the tests of
audit --command's guest rules):
  +print     writes 20 MB to its standard output and 1 MB to its standard error
  +fraction  writes each rho as the exact fraction of the double asked ("p/q" strings)
  +pose      puts pose2 (P2 lifted by 100) on every tenth claim
  +distance  writes a distance claim in place of every tenth verdict
  +next      writes every tenth claim at the next double above the rho2 asked
  +repeat    writes a distance claim where a pair is asked again (no answer there)
  +fewer     leaves out the last 5 claims; +extra adds 3 claims past the pairs asked
  +daemon    starts a process in a session of its own (setsid) that would sleep for an hour,
             writing its pid to the file $DAEMON_PID, then goes on
  +hang      sleeps for an hour after writing its claims (with $GUEST_PID set, its pid is written there)
  +bignum    writes the first claim's rho2 as the JSON number 1e400 (past the double range)
  +fail      writes to its standard error and exits with status 3
With PAIRS_COPY set, it copies the pairs asked there, for the test's own count; with TMP_COPY set,
it writes there the folder its files are in.
"""
import json
import math
import os
import re
import struct
import subprocess
import sys
import time
from fractions import Fraction


def f32(x):
    return struct.unpack("f", struct.pack("f", x))[0]


mode, scene, pairs_path, out = sys.argv[1:5]
mode, *ways = mode.split("+")
pairs = json.load(open(pairs_path))["pairs"]
if "daemon" in ways:
    subprocess.Popen([sys.executable, "-c", "import os, time; open(os.environ['DAEMON_PID'], 'w').write("
                      "str(os.getpid())); time.sleep(3600)"], start_new_session=True,
                     stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    for _ in range(1000):  # until it has written its pid
        if os.path.exists(os.environ["DAEMON_PID"]) and open(os.environ["DAEMON_PID"]).read():
            break
        time.sleep(0.01)
if "print" in ways:
    sys.stdout.write("x" * (20 << 20))
    sys.stderr.write("y" * (1 << 20))
if "fail" in ways:
    print("cubes_verdicts: cannot read the scene", file=sys.stderr)
    sys.exit(3)
claims = []
asked = set()
for i, (r1, r2) in enumerate(pairs):
    if mode == "exact":
        s = Fraction(r1) + Fraction(r2)
    else:
        s = Fraction(f32(f32(r1) + f32(r2)))
    v = "separated" if s < 3 else "touching" if s == 3 else "overlapping"
    c = {"kind": "verdict", "rho1": r1, "rho2": r2, "verdict": v}
    if "fraction" in ways:
        c["rho1"], c["rho2"] = str(Fraction(r1)), str(Fraction(r2))
    if "pose" in ways and i % 10 == 0:
        c["pose2"] = [[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 100]]
        c["verdict"] = "separated"
    if "next" in ways and i % 10 == 0:
        c["rho2"] = math.nextafter(r2, math.inf)
    if "repeat" in ways and (r1, r2) in asked:
        c = {"kind": "distance", "rho1": r1, "rho2": r2, "value": 1}
    asked.add((r1, r2))
    if "distance" in ways and i % 10 == 0:
        c = {"kind": "distance", "rho1": r1, "rho2": r2, "value": 1}
    claims.append(c)
if "fewer" in ways:
    claims = claims[:-5]
if "extra" in ways:
    claims += claims[:3]
text = json.dumps({"format": "scalecert-claims-1", "claims": claims})
if "bignum" in ways:
    text = re.sub(r'"rho2": [^,}]*', '"rho2": 1e400', text, count=1)
open(out, "w").write(text)
if os.environ.get("PAIRS_COPY"):
    json.dump(pairs, open(os.environ["PAIRS_COPY"], "w"))
if os.environ.get("TMP_COPY"):
    open(os.environ["TMP_COPY"], "w").write(os.path.dirname(out))
if "hang" in ways:
    if os.environ.get("GUEST_PID"):
        open(os.environ["GUEST_PID"], "w").write(str(os.getpid()))
    time.sleep(3600)
