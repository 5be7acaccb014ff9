#!/usr/bin/env bash
# Seconds of an audit campaign, in one process and on 1, 3 and 4 MPI ranks, with distances and
# depths (the default) and verdicts only (--no-measures): the table of docs/mpi.md. One run each.
# Usage: tools/bench-audit.sh [COUNT]  (after a build; COUNT scenes per ε, 4 ε: 200 gives 800)
set -euo pipefail
cd "$(dirname "$0")/.."
COUNT="${1:-200}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
A=(--family near-sphere --sweep 2 --sweep-to 5 --count "$COUNT" --methods libccd-gjk,libccd-mpr,double-envelope,bullet-gjk-epa --no-timing)
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
secs() {  # wall time of the command, in seconds
  local t0 t1
  t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N)
  echo "$t0 $t1" | awk '{printf "%.2f", $2 - $1}'
}
echo "audit of $((4 * COUNT)) near-sphere scenes, four methods, on $(nproc) cores"
echo "| | one process | 1 rank | 3 ranks | 4 ranks |"
echo "|---|---|---|---|---|"
for extra in "" --no-measures; do
  row="| ${extra:-verdicts, distances and depths} | $(secs build/scalecert audit "${A[@]}" $extra --out "$W/one.json") s"
  for np in 1 3 4; do
    rm -rf "$W/run"
    row="$row | $(secs mpirun -np "$np" build/scalecert-mpi audit "${A[@]}" $extra --out "$W/mpi.json" --run "$W/run") s"
  done
  echo "$row |"
done
