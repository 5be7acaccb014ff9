#!/usr/bin/env bash
# Scenes per second of a golden campaign against the number of MPI ranks, each as a ratio to the
# one-process `scalecert golden` measured in the same run (best of 3). Rank 0 coordinates and
# merges; the other ranks compute. Usage: tools/bench-mpi.sh [COUNT] [FAMILY]  (after a build)
set -euo pipefail
cd "$(dirname "$0")/.."
COUNT="${1:-400}" FAMILY="${2:-near-sphere}"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
W=$(mktemp -d)
trap 'rm -rf "$W"' EXIT
best() {  # best wall time of 3 runs of the command, in seconds
  local b=
  for r in 1 2 3; do
    rm -rf "$W/out" "$W/run"
    local t0 t1
    t0=$(date +%s.%N); "$@" >/dev/null 2>&1; t1=$(date +%s.%N)
    b=$(echo "$t0 $t1 ${b:-1e9}" | awk '{d=$2-$1; print (d<$3)?d:$3}')
  done
  echo "$b"
}
base=$(best build/scalecert golden --family "$FAMILY" --count "$COUNT" --dir "$W/out")
echo "golden --family $FAMILY --count $COUNT on $(nproc) cores; one process: $base s ($(echo "$COUNT $base" | awk '{printf "%.0f", $1/$2}') scenes/s)"
echo "| ranks | workers | seconds | scenes/s | speed vs one process |"
echo "|---|---|---|---|---|"
for np in 1 2 3 4; do
  t=$(best mpirun -np "$np" build/scalecert-mpi golden --family "$FAMILY" --count "$COUNT" --dir "$W/out" --run "$W/run")
  workers=$((np > 1 ? np - 1 : 1))
  echo "$np $workers $t $COUNT $base" | awk '{printf "| %d | %d | %.2f | %.0f | %.2fx |\n", $1, $2, $3, $4/$3, $5/$3}'
done
