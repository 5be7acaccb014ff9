#!/usr/bin/env bash
# The scalecert command and the checker built without the floating-point baselines
# (SCALECERT_BUILD_BASELINES=OFF, in build-core/), then tests/test_no_baselines.sh on them: no
# libccd, FCL or Bullet, and partition, certify-fp and golden still work; then the checker's, io's
# and campaign's tests, which need no baselines, built and run there. .ci/run calls it.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build-core -DCMAKE_BUILD_TYPE=Release -DSCALECERT_BUILD_BASELINES=OFF -DSCALECERT_BUILD_TESTS=ON \
  -DSCALECERT_BUILD_PYTHON=OFF -DSCALECERT_BUILD_MPI=OFF >/dev/null
cmake --build build-core -j"$(nproc)" --target scalecert scalecert-check >/dev/null
full=""
[ -x build/scalecert ] && full=build/scalecert
bash tests/test_no_baselines.sh build-core/scalecert build-core/scalecert-check "$PWD" $full
cmake --build build-core -j"$(nproc)" --target test_checker test_io test_campaign >/dev/null
(cd build-core && ctest --output-on-failure -j"$(nproc)" -R '^(checker_.*|io|campaign)$')
