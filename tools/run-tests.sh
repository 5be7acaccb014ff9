#!/usr/bin/env bash
# Installs what is missing, builds, and runs every test: the Boost.Test suite (ctest) on the
# Release build, the same suite under AddressSanitizer and UndefinedBehaviorSanitizer
# (tools/sanitize.sh), and each libFuzzer target for SCALECERT_FUZZ_SECONDS (default 60) seconds
# (tools/fuzz.sh). About 12 minutes on 2 cores from a fresh clone (the ctest suite alone: about 1 minute).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh clang-14 libclang-rt-14-dev
tools/build.sh
(cd build && ctest --output-on-failure)
tools/sanitize.sh
tools/fuzz.sh "${SCALECERT_FUZZ_SECONDS:-60}"
n=$(cd build && ctest -N | sed -n 's/^Total Tests: *//p')
m=$(cd build-san && ctest -N | sed -n 's/^Total Tests: *//p')
echo "ci: $((n + m + 6)) passed, 0 failed ($n tests, $m of them again under ASan+UBSan, and 6 fuzz targets)"
