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

# --help and --version exit 0; the version is the project's (CMakeLists.txt).
want=$(sed -n 's/^project(scalecert VERSION \([0-9.]*\).*/\1/p' "$SRC/CMakeLists.txt")
[ "$("$MPI" --version)" = "scalecert-mpi $want" ] || fail "scalecert-mpi --version: '$("$MPI" --version)', want 'scalecert-mpi $want'"
"$MPI" --help | grep -q "Usage:" || fail "scalecert-mpi --help"
echo "ok: --help and --version"

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
# golden for the user's own scene files: the same files on 2 ranks as in one process.
"$CLI" golden "$S/stacked_cubes.json" "$S/tetra_box_switch.json" --dir one-gs 2>/dev/null
run_mpi 2 golden "$S/stacked_cubes.json" "$S/tetra_box_switch.json" --dir gs2 --run rgs2 2>log-gs
diff -r one-gs gs2 >/dev/null && grep -q ": 2 scenes; merge" log-gs || fail "golden SCENES on 2 ranks differs: $(tail -1 log-gs)"
echo "ok: golden SCENES on 2 ranks gives the one-process bytes"

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

# A manifest edited by hand to record what a shard file now holds: an empty file, JSON that is no
# shard, or two shards' files swapped (hashes swapped to match). Each is redone, never merged.
: > ra2/shards/00000001.json
echo "{\"shard\":1,\"sha256\":\"$(sha256sum < ra2/shards/00000001.json | cut -d' ' -f1)\"}" >> ra2/manifest.jsonl
echo '{"shard":2,"inputs":[[1,2]],"rows":[]}' > ra2/shards/00000002.json
echo "{\"shard\":2,\"sha256\":\"$(sha256sum < ra2/shards/00000002.json | cut -d' ' -f1)\"}" >> ra2/manifest.jsonl
h3=$(sha256sum < ra2/shards/00000003.json | cut -d' ' -f1) h4=$(sha256sum < ra2/shards/00000004.json | cut -d' ' -f1)
mv ra2/shards/00000003.json swap && mv ra2/shards/00000004.json ra2/shards/00000003.json && mv swap ra2/shards/00000004.json
printf '{"shard":3,"sha256":"%s"}\n{"shard":4,"sha256":"%s"}\n' "$h4" "$h3" >> ra2/manifest.jsonl
run_mpi 2 audit "${AUDIT[@]}" --shard-size 2 --out a2.json --csv a2.csv --run ra2 --resume 2>log-edit
grep -q "(2 done before, 4 redone as damaged, 4 run now)" log-edit || fail "edited manifest: $(tail -1 log-edit)"
cmp one.json a2.json && cmp one.csv a2.csv || fail "audit after an edited manifest differs"
# The identity line written otherwise (a carriage return added): named as edited, exit 2.
sed -i '1s/$/\r/' ra2/manifest.jsonl
set +e
run_mpi 2 audit "${AUDIT[@]}" --shard-size 2 --out a2.json --run ra2 --resume 2>log-cr; st=$?
set -e
[ "$st" -eq 2 ] && grep -q "written otherwise (edited by hand?)" log-cr || fail "edited identity line: $st $(cat log-cr)"
echo "ok: a manifest edited by hand is redone, or named as edited"

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

# Campaigns are keyed by content: the run's identity and each scene shard record the SHA-256 of
# every scene file and every mesh file it names. A resume after either changed is refused (exit 2,
# one line naming the file, no output; mpirun adds its own lines): no shard computed from the old
# contents is merged.
mkdir -p content && cp "$S/stacked_cubes.json" content/a.json && cp "$SRC/examples/tetra.obj" content/t.obj
printf '{"P1": {"mesh": "t.obj"}, "P2": {"vertices": [[-1,-1,-1],[1,-1,-1],[-1,1,-1],[1,1,-1],[-1,-1,1],[1,-1,1],[-1,1,1],[1,1,1]]}, "I1": [0.5, 2], "I2": [1, 4]}\n' > content/b.json
CONTENT=(content/a.json content/b.json --methods libccd-gjk,grid --grid 8 --no-timing)
"$CLI" audit "${CONTENT[@]}" --out c-one.json 2>/dev/null
set +e
run_mpi 2 audit "${CONTENT[@]}" --out c.json --run rc --stop-after 1 2>log-c1; st=$?
set -e
[ "$st" -eq 3 ] || fail "content run: a stopped run should exit 3, got $st"
grep -q '"inputs"' rc/manifest.jsonl || fail "the manifest's identity records no input hashes"
grep -q "$(sha256sum content/a.json | cut -c1-64)" rc/manifest.jsonl || fail "the identity lacks a.json's SHA-256"
grep -q "$(sha256sum content/t.obj | cut -c1-64)" rc/manifest.jsonl || fail "the identity lacks the mesh's SHA-256"
grep -q "$(sha256sum content/a.json | cut -c1-64)" rc/shards/00000000.json || fail "shard 0 records no SHA-256 of a.json"
cp -r rc rc-mesh
sed -i 's/\[0,0,3\]/[0,0,4]/' content/a.json   # P2 moved: other answers
set +e
run_mpi 2 audit "${CONTENT[@]}" --out c.json --run rc --resume 2>log-c2; st=$?
set -e
[ "$st" -eq 2 ] && [ "$(grep -c 'scalecert-mpi' log-c2)" -eq 1 ] || fail "a changed scene file: $st $(cat log-c2)"
grep -q "content/a.json: changed since the run" log-c2 || fail "the refusal should name a.json: $(cat log-c2)"
[ ! -e c.json ] || fail "a refused resume wrote output"
cp "$S/stacked_cubes.json" content/a.json && echo "v 0 0 9" >> content/t.obj   # the mesh a scene names
set +e
run_mpi 2 audit "${CONTENT[@]}" --out c.json --run rc-mesh --resume 2>log-c3; st=$?
set -e
[ "$st" -eq 2 ] && grep -q "content/t.obj: changed since the run" log-c3 || fail "a changed mesh: $st $(cat log-c3)"
[ ! -e c.json ] || fail "a refused resume wrote output"
cp "$SRC/examples/tetra.obj" content/t.obj   # contents restored: the resume goes on, and equals one process
run_mpi 2 audit "${CONTENT[@]}" --out c.json --run rc --resume 2>log-c4
grep -q "(1 done before, 0 redone as damaged, 1 run now)" log-c4 || fail "resume on restored contents: $(tail -1 log-c4)"
cmp c-one.json c.json || fail "resumed content run differs"
echo "ok: a resume after a scene file or mesh changed is refused; never merged stale"

# Nothing in a run folder may be a symbolic link: a dangling manifest.jsonl planted there made a
# new run create the link's target, outside the folder.
mkdir -p rsym outside && ln -s "$PWD/outside/planted" rsym/manifest.jsonl
mkdir -p rsym2 && ln -s "$PWD/outside" rsym2/shards
set +e
run_mpi 2 audit "${CONTENT[@]}" --out s.json --run rsym 2>log-s1; st1=$?
run_mpi 2 audit "${CONTENT[@]}" --out s.json --run rsym --resume 2>log-s2; st2=$?
run_mpi 2 audit "${CONTENT[@]}" --out s.json --run rsym2 2>log-s3; st3=$?
set -e
for i in 1 2 3; do
  eval st=\$st$i
  [ "$st" -eq 2 ] && [ "$(grep -c 'scalecert-mpi' log-s$i)" -eq 1 ] && grep -q "symbolic link" log-s$i || fail "planted link $i: $st $(cat log-s$i)"
done
[ ! -e outside/planted ] && [ -z "$(ls outside)" ] && [ ! -e s.json ] || fail "a planted link was followed: $(ls outside)"
[ -L rsym/manifest.jsonl ] && [ ! -e rsym2/manifest.jsonl ] || fail "the run folder was changed"
# A shard file replaced by a link: the resume refuses it rather than read through it.
cp -r rc rc-link && rm rc-link/shards/00000000.json && echo secret > outside/secret && ln -s "$PWD/outside/secret" rc-link/shards/00000000.json
set +e
run_mpi 2 audit "${CONTENT[@]}" --out s.json --run rc-link --resume 2>log-s4; st=$?
set -e
[ "$st" -eq 2 ] && grep -q "00000000.json: is a symbolic link" log-s4 || fail "a linked shard file: $st $(cat log-s4)"
[ "$(cat outside/secret)" = secret ] && [ ! -e s.json ] || fail "a linked shard file was written through"
echo "ok: symbolic links in a run folder are refused, nothing made at their targets"

# An input that is a FIFO with no writer: refused at once, not waited on.
mkfifo content/fifo.json
set +e
t0=$(date +%s.%N)
timeout -k 5 30 mpirun -np 2 "$MPI" audit content/a.json content/fifo.json --methods libccd-gjk --out f.json --run rfifo 2>log-f; st=$?
t1=$(date +%s.%N)
set -e
[ "$st" -eq 2 ] && [ "$(grep -c 'scalecert-mpi' log-f)" -eq 1 ] && grep -q "content/fifo.json: is a named pipe (FIFO)" log-f || fail "a FIFO scene: $st $(cat log-f)"
[ ! -e f.json ] && [ ! -e rfifo ] || fail "a FIFO scene left files behind"
echo "ok: a FIFO scene is refused in $(echo "$t1 - $t0" | bc) s"

# The single-machine command of docs/mpi.md, flags and all, with the OpenMPI variables above unset.
(unset OMPI_ALLOW_RUN_AS_ROOT OMPI_ALLOW_RUN_AS_ROOT_CONFIRM OMPI_MCA_rmaps_base_oversubscribe
 mpirun --allow-run-as-root --oversubscribe -np 3 "$MPI" golden --family random --count 6 --dir readme-g --run readme-g-run >/dev/null 2>&1) ||
  fail "docs/mpi.md's mpirun command"
[ "$(ls readme-g/*.scene.json | wc -l)" -eq 6 ] || fail "docs/mpi.md's mpirun command wrote $(ls readme-g | wc -l) files"
echo "ok: docs/mpi.md's mpirun command"
