#!/usr/bin/env bash
# The whole test suite under AddressSanitizer and UndefinedBehaviorSanitizer (any undefined
# behaviour is fatal), built with clang-14 in build-san/ — the same build as the fuzz targets
# (tools/fuzz.sh). Installs clang-14 and libclang-rt-14-dev if missing.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh clang-14 libclang-rt-14-dev
# (Configured every time: the options stick to an old cache otherwise. No Python module, install
# test or MPI here: an ASan library cannot be loaded into an uninstrumented python3 or example,
# and OpenMPI's own allocations would be reported as leaks.)
CC=clang-14 CXX=clang++-14 cmake -S . -B build-san -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSCALECERT_FUZZ=ON -DSCALECERT_BUILD_PYTHON=OFF -DSCALECERT_INSTALL_TEST=OFF -DSCALECERT_BUILD_MPI=OFF >/dev/null
cmake --build build-san -j"$(nproc)" >/dev/null
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:suppressions=$PWD/tools/ubsan.supp"  # CGAL's arrangement records only
cd build-san && ctest --output-on-failure
