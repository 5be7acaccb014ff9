#!/usr/bin/env bash
# Runs every libFuzzer target for SECONDS each (default 60), under AddressSanitizer and
# UndefinedBehaviorSanitizer, two at a time on this machine's cores. Builds them first with
# clang-14 in build-san/ (installing clang-14 and libclang-rt-14-dev if missing).
#   tools/fuzz.sh [SECONDS] [TARGET...]   targets: scene mesh pairs claims checker differential
# Seeds: tests/fuzz/corpus/TARGET (committed); what a run finds new goes to
# build-san/corpus/TARGET. A finding (crash, sanitizer report, oracle failure, timeout, memory
# blow-up) is saved in build-san/artifacts/ and makes the script exit 1.
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_EACH="${1:-60}"
shift || true
TARGETS=("$@")
[ ${#TARGETS[@]} -eq 0 ] && TARGETS=(scene mesh pairs claims checker differential)
tools/install-deps.sh clang-14 libclang-rt-14-dev
# (Configured every time: the options stick to an old cache otherwise. No Python module, install
# test or MPI here: an ASan library cannot be loaded into an uninstrumented python3 or example,
# and OpenMPI's own allocations would be reported as leaks.)
CC=clang-14 CXX=clang++-14 cmake -S . -B build-san -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSCALECERT_FUZZ=ON -DSCALECERT_BUILD_PYTHON=OFF -DSCALECERT_INSTALL_TEST=OFF -DSCALECERT_BUILD_MPI=OFF >/dev/null
cmake --build build-san -j"$(nproc)" --target $(printf 'fuzz_%s ' "${TARGETS[@]}") >/dev/null
mkdir -p build-san/artifacts build-san/logs
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-}:suppressions=$PWD/tools/ubsan.supp"  # CGAL's arrangement records only (tools/ubsan.supp)
run() {
  local t="$1" max_len=4096
  [ "$t" = checker ] && max_len=200000
  mkdir -p "build-san/corpus/$t"
  build-san/fuzz_"$t" "build-san/corpus/$t" "tests/fuzz/corpus/$t" \
    -max_total_time="$SECONDS_EACH" -timeout=30 -rss_limit_mb=4096 -max_len="$max_len" \
    -artifact_prefix="build-san/artifacts/$t-" -print_final_stats=1 >"build-san/logs/$t.log" 2>&1
}
status=0
pids=()
names=()
for t in "${TARGETS[@]}"; do
  run "$t" &
  pids+=($!)
  names+=("$t")
  if [ ${#pids[@]} -ge "$(nproc)" ]; then
    if ! wait "${pids[0]}"; then status=1; echo "fuzz: ${names[0]}: FINDING (build-san/logs/${names[0]}.log)"; else echo "fuzz: ${names[0]}: no finding"; fi
    pids=("${pids[@]:1}")
    names=("${names[@]:1}")
  fi
done
for i in "${!pids[@]}"; do
  if ! wait "${pids[$i]}"; then status=1; echo "fuzz: ${names[$i]}: FINDING (build-san/logs/${names[$i]}.log)"; else echo "fuzz: ${names[$i]}: no finding"; fi
done
for t in "${TARGETS[@]}"; do
  runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "build-san/logs/$t.log" | grep -o '[0-9]*$' || echo "?")
  echo "fuzz: $t: $runs inputs in ${SECONDS_EACH} s"
done
if [ $status -ne 0 ]; then
  grep -h -A3 "FUZZ FINDING\|ERROR: \|runtime error" build-san/logs/*.log | head -40
fi
exit $status
