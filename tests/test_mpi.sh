#!/usr/bin/env bash
# ctest's mpi: scalecert-mpi under mpirun with 1, 2 and 3 (oversubscribed) ranks writes the same
# bytes as the one-process command; an interrupted run resumed equals an uninterrupted one; a
# corrupt shard file or golden output is found by its hash and redone; bad arguments exit 2 with
# one line, on every rank.
#   test_mpi.sh SCALECERT SCALECERT_MPI SOURCE_DIR WORK_DIR
set -euo pipefail
CLI="$1" MPI="$2" SRC="$3" W="$4"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1  # CI runs as root
export OMPI_MCA_rmaps_base_oversubscribe=1
rm -rf "$W" && mkdir -p "$W" && cd "$W"
fail() { echo "FAIL: $*" >&2; exit 1; }
run_mpi() { local np="$1"; shift; mpirun -np "$np" "$MPI" "$@"; }

S="$SRC/certificates/scenes"
AUDIT=("$S/stacked_cubes.json" "$S/tetra_box_switch.json" --family random --sweep 2 --sweep-to 3 --count 3
       --methods libccd-gjk,bullet-gjk-epa,grid --grid 8 --no-timing --by-distance)
GOLDEN=(--family nearly-equal-slopes --count 9 --seed 11 --eps 1/4096)

"$CLI" audit "${AUDIT[@]}" --out one.json --csv one.csv 2>/dev/null
"$CLI" golden "${GOLDEN[@]}" --dir one-golden 2>/dev/null
[ "$(wc -l < one.csv)" -gt 20 ] || fail "the one-process audit has too few rows"
for np in 1 2 3; do
  run_mpi "$np" audit "${AUDIT[@]}" --shard-size 2 --out "a$np.json" --csv "a$np.csv" --run "ra$np" 2>"log$np"
  cmp one.json "a$np.json" && cmp one.csv "a$np.csv" || fail "audit on $np ranks differs"
  run_mpi "$np" golden "${GOLDEN[@]}" --shard-size 2 --dir "g$np" --run "rg$np" 2>>"log$np"
  diff -r one-golden "g$np" >/dev/null || fail "golden on $np ranks differs"
  grep -q "on $np ranks" "log$np" || fail "no summary on $np ranks"
  echo "ok: $np ranks give the one-process bytes"
done

# Interrupted after 3 shards (as if killed: exit 3, no output), then resumed.
set +e
run_mpi 2 audit "${AUDIT[@]}" --shard-size 2 --out int.json --csv int.csv --run rint --stop-after 3 2>log-int
st=$?
set -e
[ "$st" -eq 3 ] || fail "a stopped run should exit 3, got $st"
[ ! -e int.json ] || fail "a stopped run wrote output"
[ "$(ls rint/shards | wc -l)" -eq 3 ] || fail "a stopped run should leave 3 shard files"
run_mpi 2 audit "${AUDIT[@]}" --shard-size 2 --out int.json --csv int.csv --run rint --resume 2>log-res
grep -q "(3 done before, 0 redone as damaged, 3 run now)" log-res || fail "resume: $(tail -1 log-res)"
cmp one.json int.json && cmp one.csv int.csv || fail "a resumed audit differs"
echo "ok: an interrupted audit resumed equals an uninterrupted one"

# A corrupt shard file: found by its hash and redone.
printf 'x' >> ra2/shards/00000004.json
run_mpi 2 audit "${AUDIT[@]}" --shard-size 2 --out a2.json --csv a2.csv --run ra2 --resume 2>log-cor
grep -q "(5 done before, 1 redone as damaged, 1 run now)" log-cor || fail "corrupt shard: $(tail -1 log-cor)"
cmp one.json a2.json || fail "audit after a corrupt shard differs"
# A truncated golden output file: its shard is redone and the file restored.
head -c 100 g3/nearly-equal-slopes-5.golden.json > t && mv t g3/nearly-equal-slopes-5.golden.json
run_mpi 3 golden "${GOLDEN[@]}" --shard-size 2 --dir g3 --run rg3 --resume 2>log-gcor
grep -q "(4 done before, 1 redone as damaged, 1 run now)" log-gcor || fail "damaged golden file: $(tail -1 log-gcor)"
diff -r one-golden g3 >/dev/null || fail "golden after a damaged file differs"
echo "ok: damaged shards and outputs are found by their hashes and redone"

# A run folder is not silently reused, nor resumed with other arguments.
set +e
run_mpi 2 audit "${AUDIT[@]}" --shard-size 2 --out x.json --run ra2 2>log-x; st1=$?
run_mpi 2 audit "${AUDIT[@]}" --shard-size 3 --out x.json --run ra2 --resume 2>log-y; st2=$?
# Bad arguments: rank 0 says so once, every rank exits, status 2, nothing started.
run_mpi 3 audit "$S/stacked_cubes.json" --grid 1 --out x.json --run rbad 2>log-bad1; st3=$?
run_mpi 3 golden --family bogus --dir gbad --run rbad 2>log-bad2; st4=$?
set -e
[ "$st1" -eq 2 ] && grep -q "already there" log-x || fail "reusing a run folder: $st1 $(cat log-x)"
[ "$st2" -eq 2 ] && grep -q "another command" log-y || fail "resuming with other arguments: $st2 $(cat log-y)"
[ "$st3" -eq 2 ] && [ "$(grep -c 'scalecert-mpi: error' log-bad1)" -eq 1 ] || fail "--grid 1: $st3 $(cat log-bad1)"
[ "$st4" -eq 2 ] && [ "$(grep -c "unknown family 'bogus'" log-bad2)" -eq 1 ] || fail "unknown family: $st4 $(cat log-bad2)"
[ ! -e rbad ] && [ ! -e gbad ] && [ ! -e x.json ] || fail "bad arguments left files behind"
echo "ok: bad arguments exit 2 with one line, before any work"
