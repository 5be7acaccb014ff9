#!/usr/bin/env bash
# Every command's output on every bundled scene, one file each, in DIR: run it before and after a
# change that must not alter outputs, then `diff -r BEFORE AFTER`. Usage:
#   tools/same-outputs.sh BUILD_DIR DIR
# (certificates/scenes, its compound scenes, tests/data, examples; curve, query with and without
# --json, partition, classify, certify-fp with and without its certificate, golden, region.)
set -u
build=$(cd "$1" && pwd)
out=$2
src=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$out"
out=$(cd "$out" && pwd)
cd "$src" || exit 2
sc=$build/scalecert
# Inputs and golden folders at one path, so that messages naming them are the same in both runs.
work=${TMPDIR:-/tmp}/scalecert-same-outputs
rm -rf "$work"
mkdir -p "$work"
pairs=$'1 1\n0.5 0.5\n1.5 1.5\n2 2\n0.75 1.25\n3 0.5\n1 3\n'
run() {  # NAME COMMAND...: stdout, stderr and the exit status in NAME.*
    local name=$1
    shift
    "$@" >"$out/$name.out" 2>"$out/$name.err" </dev/null
    echo $? >"$out/$name.rc"
}
# A scene the walk answers by default (2,000 points and more): integer points near two spheres.
python3 - "$work/walked.json" <<'PY'
import json, math, random, sys
rng = random.Random(7)
def cloud(cx, n):
    pts = []
    for _ in range(n):
        z, t = rng.uniform(-1, 1), rng.uniform(0, 2 * math.pi)
        r = math.sqrt(1 - z * z)
        pts.append([round(1000 * (cx + r * math.cos(t))), round(1000 * r * math.sin(t)), round(1000 * z)])
    return pts
json.dump({"P1": {"vertices": cloud(0, 1200)}, "P2": {"vertices": cloud(2.5, 1200)},
           "I1": ["1/2", "2"], "I2": ["1/2", "2"]}, open(sys.argv[1], "w"))
PY
for f in certificates/scenes/*.json certificates/scenes/compound/*.json tests/data/*.json "$work/walked.json"; do
    case $f in *_claims.json) continue ;; esac
    n=$(echo "${f#"$work"/}" | tr '/' '_')
    run "$n.curve" "$sc" curve "$f"
    run "$n.partition" "$sc" partition "$f"
    run "$n.region" "$sc" region "$f"
    run "$n.curve-scan" "$sc" curve "$f" --engine scan
    run "$n.partition-scan" "$sc" partition "$f" --engine scan
    run "$n.partition-hull" "$sc" partition "$f" --engine hull
    run "$n.curve-segment" "$sc" curve "$f" --segment seeds
    run "$n.query-segment" "$sc" query "$f" 1 1 --segment seeds
    run "$n.query-segment.json" "$sc" query "$f" 1 1 --segment ellipsoids --json
    run "$n.query-in-t" "$sc" query "$f" 1/2 1/2 --in-t
    for p in "1 1" "3/2 3/2" "1 19/10" "1/2 2"; do
        set -- $p
        q=$(echo "$1_$2" | tr '/' '_')  # (3/2 in a file name would be a folder)
        run "$n.query.$q" "$sc" query "$f" "$1" "$2"
        run "$n.query.$q.json" "$sc" query "$f" "$1" "$2" --json
        run "$n.query.$q.scan.json" "$sc" query "$f" "$1" "$2" --json --engine scan
    done
    printf '%s' "$pairs" >"$work/pairs.txt"
    run "$n.classify" "$sc" classify "$f" "$work/pairs.txt"
    printf '1 1 separated\n3/2 3/2 touching\n2 2 overlapping\n1 1 intersecting\ncurve 1 1\ngrowth 3/2\n' >"$work/claims.txt"
    run "$n.certify-lines" "$sc" certify-fp "$f" "$work/claims.txt"
    run "$n.certify-json" "$sc" certify-fp "$f" examples/claims.json --json --certificate "$work/j.json"
    [ -e "$work/j.json" ] && mv "$work/j.json" "$out/$n.judgements.json"
    run "$n.certify-posed" "$sc" certify-fp "$f" examples/posed_claim.json --json
    run "$n.certify-band" "$sc" certify-fp "$f" tests/data/compound_band_claims.json --json
    run "$n.certify-band-text" "$sc" certify-fp "$f" tests/data/compound_band_claims.json
    rm -rf "$work/g"
    run "$n.golden" "$sc" golden "$f" --dir "$work/g"
    for g in "$work"/g/*; do [ -e "$g" ] && mv "$g" "$out/$n.golden.$(basename "$g")"; done
done
rm -rf "$work/g"
run mesh.curve "$sc" curve --p1 examples/tetra.obj --p2 examples/box.stl --i1 1/2,2 --i2 1,4
run mesh.partition "$sc" partition --p1 examples/tetra.obj --p2 examples/box.stl --i1 1/2,2 --i2 1,4
run mesh.certify "$sc" certify-fp --p1 examples/tetra.obj --p2 examples/box.stl --i1 1/2,2 --i2 1,4 examples/claims.json --json
run mesh.region "$sc" region tests/data/compound_band.json --at 7/6,2
# Audits (their timings left out): the convex methods on the convex scenes, the parts' methods on
# scenes of parts, with the failures they write.
audit() {  # NAME SCENES... -- METHODS
    local name=$1 methods=$2
    shift 2
    rm -rf "$work/failures"
    "$sc" audit "$@" --methods "$methods" --by-distance --failures "$work/failures" --csv "$work/a.csv" \
        --out "$work/a.json" >/dev/null 2>"$out/$name.err" </dev/null
    echo $? >"$out/$name.rc"
    for f in "$work/a.json"; do  # (the CSV rows hold the timings in place)
        [ -e "$f" ] && grep -v seconds "$f" >"$out/$name.$(basename "$f")"
    done
    # (index.json's replay commands name the program that ran: the same name in both runs.)
    for f in "$work"/failures/*; do
        [ -e "$f" ] && sed "s|$sc |scalecert |g" "$f" >"$out/$name.failures.$(basename "$f")"
    done
    rm -f "$work/a.json" "$work/a.csv"
}
audit audit.convex libccd-gjk,libccd-mpr,fcl-gjk-indep,bullet-gjk-epa certificates/scenes/*.json
audit audit.parts bullet-compound,fcl-compound-libccd,fcl-compound-indep,libccd-gjk-parts \
    certificates/scenes/compound/band.json certificates/scenes/compound/l_box.json \
    certificates/scenes/compound/u_peg.json
run family.golden "$sc" golden --family nearly-equal-slopes --count 3 --eps 1/1024 --dir "$work/family"
for g in "$work"/family/*; do mv "$g" "$out/family.$(basename "$g")"; done
rm -rf "$work"
