#!/usr/bin/env bash
# What CI runs (.ci/run): the house style (tools/format.sh --check: clang-format and 120 columns);
# the test command (tools/run-tests.sh), with the docs test's ε-sweep audits
# (SCALECERT_DOCS_SWEEPS=1) and the bench built (not in the default build); the command and checker built
# without the floating-point baselines and tried (tools/no-baselines.sh); the Boost.Test programs
# again under AddressSanitizer and UndefinedBehaviorSanitizer (tools/sanitize.sh, clang-14); then
# each libFuzzer target for SCALECERT_FUZZ_SECONDS (default 20) seconds (tools/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
tools/format.sh --check
SCALECERT_DOCS_SWEEPS=1 tools/run-tests.sh
cmake --build build --target scalecert-bench -j"$(nproc)"
tools/no-baselines.sh
tools/install-deps.sh clang-14 libclang-rt-14-dev
tools/sanitize.sh
tools/fuzz.sh "${SCALECERT_FUZZ_SECONDS:-20}"
n=$(cd build && ctest -N | sed -n 's/^Total Tests: *//p')
m=$(cd build-san && ctest -N | sed -n 's/^Total Tests: *//p')
echo "ci: $((n + m + 7)) passed, 0 failed ($n tests, the build without baselines, $m of them again under ASan+UBSan, and 6 fuzz targets)"
