#!/usr/bin/env bash
# The test command: installs what is missing, builds (Release, build/), and runs the whole ctest
# suite: the Boost.Test programs, the installed-package test, the Python tests (pytest), the
# MPI tests and the docs test. A few minutes from a fresh clone on 2 cores. .ci/run runs this,
# then the sanitizer suite and a short fuzz pass (tools/ci.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install-deps.sh
tools/build.sh
# One test more than cores: several tests spend part of their time waiting (mpirun, subprocesses).
(cd build && ctest --output-on-failure -j"$(($(nproc) + 1))")
n=$(cd build && ctest -N | sed -n 's/^Total Tests: *//p')
echo "tests: $n passed, 0 failed"
