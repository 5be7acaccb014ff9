#!/usr/bin/env bash
# The audit report (tools/report.py) in a real browser: headless Chromium loads it with no script
# error, the page says it drew both charts and a 3-D view, and screenshots show them: the charts'
# method colours, and the 3-D view's two bodies (P1 blue, P2 orange). Skipped (exit 77) where
# Chromium is not installed. Usage: test_report.sh SCALECERT SOURCE_DIR WORK_DIR
set -uo pipefail
SC=$1 SRC=$2 WORK=$3
BROWSER=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$BROWSER" ]; then echo "report: skipped: no chromium"; exit 77; fi
PY=/usr/bin/python3
rm -rf "$WORK" && mkdir -p "$WORK" && cd "$WORK" || exit 1
fail=0
bad() { echo "FAIL: $*"; fail=1; }
browse() {  # chromium headless, the page at URL; its other arguments before
  timeout 120 "$BROWSER" --headless=new --no-sandbox --disable-gpu --use-angle=swiftshader --enable-unsafe-swiftshader \
    --no-first-run --disable-extensions --user-data-dir="$WORK/profile" --virtual-time-budget=8000 "$@"
}
"$SC" audit "$SRC/certificates/scenes/stacked_cubes.json" --methods libccd-gjk,bullet-gjk-epa,libccd-mpr --by-distance \
  --out audit.json 2>/dev/null || bad "audit"
"$SC" report audit.json --out report.html 2>/dev/null || bad "scalecert report"
cp audit.json same.json
"$SC" report same.json --out same.json 2>/dev/null; st=$?
[ $st -eq 2 ] && cmp -s same.json audit.json || bad "report --out the audit itself: exit $st"
[ -s report.html ] && [ ! -e report.html.assets ] && grep -q "REVISION" report.html || bad "report: one file, three.js inlined"
# The bodies the 3-D view draws, from a scene of mesh parts at poses (panda_fingers: the right
# finger is the left one turned half a turn about z, (x, y, z) -> (-x, -y, z), each moved 0.001
# along its own y): the same six parts, each point mirrored, and the mesh part's 185 points.
$PY - "$SRC" "$SC" <<'PYEOF' || bad "bodies of a posed scene with mesh parts"
import importlib.util, sys
spec = importlib.util.spec_from_file_location("report", sys.argv[1] + "/tools/report.py")
r = importlib.util.module_from_spec(spec); spec.loader.exec_module(r)
b = r.bodies(sys.argv[1] + "/certificates/scenes/compound/panda_fingers.json", sys.argv[2])
left, right, regions = b  # objects made of parts: their pair regions third
assert len(left["parts"]) == len(right["parts"]) == 6 and len(left["parts"][0]) == 185 and isinstance(regions["pairs"], list)
for pl, pr in zip(left["parts"], right["parts"]):
    assert all(q == [-p[0], -p[1], p[2]] for p, q in zip(pl, pr))
assert left["parts"][2][0][1] == 0.001 and left["seed"] == [0, 0.016, 0.0784] and right["seed"][1] == -0.016
PYEOF
# Bad input: one line, exit 2, nothing written.
echo '{"not": "an audit"}' > bogus.json
$PY "$SRC/tools/report.py" bogus.json --out never.html 2>err.txt; st=$?
[ $st -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && [ ! -e never.html ] && [ ! -e never.html.assets ] || bad "bad input: exit $st"
# Rows whose fields have the wrong types, a FIFO and nesting deeper than Python parses: the same.
printf '[{"scene": "a", "method": "m", "queries": 3, "failures": "none"}]' > wrongtype.json
printf '%.0s[' $(seq 100000) > deep.json
mkfifo fifo.json
printf '[{"scene": "a", "method": "m", "queries": 1, "distance_err_max": 1%0400d}]' 0 > hugeint.json
for f in wrongtype.json deep.json fifo.json hugeint.json; do
  for tool in report.py atlas_table.py; do
    if [ $tool = report.py ]; then args=(--out never.html); else args=(); fi
    timeout 20 $PY "$SRC/tools/$tool" "$f" "${args[@]}" > /dev/null 2> err.txt; st=$?
    [ $st -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && [ ! -e never.html ] || bad "$tool on $f: exit $st, $(head -c 300 err.txt)"
  done
done
[ -z "$(ls -A . | grep '^\.report\.')" ] || bad "a temporary page left behind"
# --out on a FIFO or a symbolic link is refused as every command's --out is: one line, exit 2, left as it was.
mkfifo out_fifo.html; echo kept > link_target.html; ln -s link_target.html out_link.html
for o in out_fifo.html out_link.html; do
  timeout 20 $PY "$SRC/tools/report.py" audit.json --out "$o" 2> err.txt; st=$?
  [ $st -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] && grep -q "exists and is not a regular file" err.txt ||
    bad "--out $o: exit $st, $(head -c 300 err.txt)"
done
[ -p out_fifo.html ] && [ -L out_link.html ] && [ "$(cat link_target.html)" = kept ] || bad "--out replaced a FIFO or a link"
# Counts that are not counts of the row's queries are refused (a bool is not a count).
for row in '"queries": true' '"queries": 2, "false_touching": -1' '"queries": 2, "false_separated": 3'; do
  printf '[{"scene": "a", "method": "m", %s}]' "$row" > badcount.json
  $PY "$SRC/tools/atlas_table.py" badcount.json > /dev/null 2> err.txt; st=$?
  [ $st -eq 2 ] && [ "$(wc -l < err.txt)" -eq 1 ] || bad "atlas_table on {$row}: exit $st"
done
# A scene named with a bar stays one Markdown cell in atlas_table's table: 7 cells, the bar escaped.
printf '[{"scene": "a|b", "method": "m|n", "queries": 4, "false_separated": 1, "false_touching": 2}]' > bar.json
row="$($PY "$SRC/tools/atlas_table.py" --by-scene bar.json | tail -1)"
[ "$row" = '| a\|b | m\|n | 1 | 3 / 4 | — | — | — |' ] || bad "atlas_table with bars: $row"
# A mesh pair's audit names its scene P1-P2, whose file the --failures directory holds: the page
# finds it there and carries both bodies (the tetrahedron's 4 points).
"$SC" audit --p1 "$SRC/examples/box.stl" --p2 "$SRC/examples/tetra.obj" --i1 1/2,2 --i2 1/2,2 --methods bullet-gjk-epa \
  --failures rep --out pair.json 2>/dev/null || bad "mesh-pair audit"
$PY "$SRC/tools/report.py" pair.json --failures rep --out pair.html --scalecert "$SC" 2>/dev/null || bad "mesh-pair report"
$PY - <<'PYEOF' || bad "mesh-pair report: the bodies"
import json, re
text = open("pair.html", encoding="utf-8").read()
d = json.loads(re.search(r"const D = (.*);\n", text).group(1))
b = d["scenes"]["box-tetra"]
assert len(b[0]["parts"][0]) == 8 and len(b[1]["parts"][0]) == 4, b
PYEOF
# A --scalecert whose answer is nested deeper than Python parses: a page without 3-D views, no traceback.
printf '#!/bin/sh\n/usr/bin/python3 -c "print(\\"[\\" * 100000 + \\"]\\" * 100000)"\n' > deep.sh && chmod +x deep.sh
$PY "$SRC/tools/report.py" audit.json --out deep.html --scalecert ./deep.sh 2> err.txt && [ -s deep.html ] &&
  ! grep -q Traceback err.txt && grep -q "gave no bodies, so its failures get no 3-D view" err.txt ||
  bad "a --scalecert answering deep JSON: $(head -c 300 err.txt)"
# The page, loaded: its status line, and no script error in the console.
browse --enable-logging=stderr --v=0 --dump-dom "file://$WORK/report.html" > dom.html 2> console.txt
grep -q 'id="status"[^>]*>charts drawn: 2; 3-D views drawn: 1<' dom.html || bad "status: $(grep -o 'id="status"[^<]*' dom.html)"
# The distances and depths the audit listed past its tolerance: one table row each (and its header),
# the first 250 drawn with the page.
want=$($PY -c 'import json; print(min(250, sum(len(r.get("measure_failures", [])) for r in json.load(open("audit.json")))))')
got=$($PY -c 'import re; t = open("dom.html").read(); m = re.search(r"<table id=\"measures\">(.*?)</table>", t, re.S); print(m.group(1).count("<tr>") - 1 if m else -1)')
[ "$want" -gt 0 ] && [ "$got" = "$want" ] || bad "measures table: $got rows for $want listed"
if grep "CONSOLE" console.txt | grep -v "GL Driver Message" | grep -q .; then
  bad "console: $(grep CONSOLE console.txt | grep -v 'GL Driver Message' | head -3)"
fi
grep -q "Uncaught" console.txt && bad "uncaught: $(grep Uncaught console.txt | head -2)"
# Names are data, never markup: a method named "<!--<script>..." (which, written raw into the
# page's script, would put the HTML parser in its escaped script state and swallow the page) leaves
# the page drawn and nothing injected.
$PY -c 'import json; r = json.load(open("audit.json"))
for x in r: x["method"] = "<!--<script>document.title=1</script>" + x["method"]
json.dump(r, open("evil.json", "w"))' && $PY "$SRC/tools/report.py" evil.json --out evil.html --scalecert "$SC" 2>/dev/null || bad "evil report"
browse --dump-dom "file://$WORK/evil.html" > evil-dom.html 2>/dev/null
grep -q 'id="status"[^>]*>charts drawn: 2; 3-D views drawn: 1<' evil-dom.html && ! grep -q "<title>1</title>" evil-dom.html ||
  bad "a method name with markup: $(grep -o 'id="status"[^<]*' evil-dom.html)"
# Objects made of parts: the parts marked at a failure. P1 = a box "near" [0,1]^3 and a box "far"
# [10,11] x [0,1]^2 about the seed (1/2, 1/2, 1/2); P2 = boxes [2,3] and [14,15] x [0,1]^2 about
# (5/2, 1/2, 1/2); I1 = I2 = [1/2, 3]. Along x, near(r1) reaches 1/2 + r1/2 and P2's first box
# starts at 5/2 - r2/2: they meet where r1 + r2 >= 4. far(r1) spans [1/2 + 19 r1/2, 1/2 + 21 r1/2]
# and P2's second box [5/2 + 23 r2/2, 5/2 + 25 r2/2]: they meet where 21 r1 - 23 r2 >= 4 and
# 19 r1 - 25 r2 <= 4. At (1, 1) neither meets; the line 21 r1 - 23 r2 = 4 is 3 / sqrt(21^2 + 23^2)
# = 0.19 away (in r1, r2), r1 + r2 = 4 is 2 / sqrt(2) = 1.41 away: far and P2's second box are nearest.
# At (3, 2.3) both pairs meet (5.3 >= 4; 63 - 52.9 >= 4 and 57 - 57.5 <= 4).
$PY - <<'PYEOF'
import json
def box(x0, x1): return [[x, y, z] for x in (x0, x1) for y in (0, 1) for z in (0, 1)]
json.dump({"P1": {"parts": [{"name": "near", "vertices": box(0, 1)}, {"name": "far", "vertices": box(10, 11)}],
                  "seed": ["1/2", "1/2", "1/2"]},
           "P2": {"parts": [{"vertices": box(2, 3)}, {"vertices": box(14, 15)}], "seed": ["5/2", "1/2", "1/2"]},
           "I1": ["1/2", "3"], "I2": ["1/2", "3"]}, open("two.json", "w"))
for name, r1, r2 in (("apart", 1.0, 1.0), ("both", 3.0, 2.3)):
    json.dump([{"scene": "two.json", "method": "m", "queries": 1, "false_separated": 0, "false_overlapping": 1,
                "failures": [{"rho1": r1, "rho2": r2, "said": "intersecting", "exact": "separated"}]}],
              open(name + ".json", "w"))
PYEOF
for name in apart both; do
  "$SC" report $name.json --out $name.html 2>/dev/null || bad "report $name"
  browse --dump-dom "file://$WORK/$name.html" > $name-dom.html 2>/dev/null
done
grep -q "nearest to meeting: P1 part 1 (far) with P2 part 1<" apart-dom.html ||
  bad "marked at (1, 1): $(grep -o 'nearest to meeting: [^<]*\|meeting here: [^<]*' apart-dom.html)"
grep -q "meeting here: P1 part 0 (near) with P2 part 0; P1 part 1 (far) with P2 part 1<" both-dom.html ||
  bad "marked at (3, 2.3): $(grep -o 'nearest to meeting: [^<]*\|meeting here: [^<]*' both-dom.html)"
# Screenshots of the charts and of the 3-D view alone, and their colours counted.
browse --window-size=1000,900 --screenshot="$WORK/charts.png" "file://$WORK/report.html#charts" 2>/dev/null
browse --window-size=700,500 --screenshot="$WORK/view.png" "file://$WORK/report.html#view" 2>/dev/null
$PY - <<'PYEOF' || bad "screenshots"
from PIL import Image
def near(c, ref, tol=40): return all(abs(a - b) <= tol for a, b in zip(c, ref))
def count(path, ref):
    img = Image.open(path).convert("RGB")
    return sum(1 for c in img.getdata() if near(c, ref))
blue, red, green = (0x1f, 0x77, 0xb4), (0xd6, 0x27, 0x28), (0x2c, 0xa0, 0x2c)
charts = {name: count("charts.png", ref) for name, ref in (("blue", blue), ("red", red), ("green", green))}
# The 3-D view: blended with white at opacity 0.55, lit, P1 and P2 come out as light blue and light
# orange; count pixels clearly bluer than red, and clearly redder than blue.
img = Image.open("view.png").convert("RGB")
b = sum(1 for r, g, bb in img.getdata() if bb > r + 40)
o = sum(1 for r, g, bb in img.getdata() if r > bb + 60 and g > bb)
print("charts", charts, "view blue", b, "orange", o)
assert charts["blue"] > 500 and charts["red"] > 200 and charts["green"] > 100, charts
assert b > 500 and o > 2000, (b, o)
PYEOF
[ $fail -eq 0 ] && echo "report: all checks passed"
exit $fail
