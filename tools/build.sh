#!/usr/bin/env bash
# Configures and builds scalecert (Release) in ./build, on every core, printing a progress line
# every tenth of the way (the compiler's warnings and errors in full).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
start=$SECONDS
cmake --build build -j"$(nproc)" | awk -v start="$start" '
  /^\[ *[0-9]+%\]/ { p = substr($0, 2, index($0, "%") - 2) + 0
                     if (p >= next_at) { printf "build: %3d%% (%s)\n", p, $0 > "/dev/stderr"; next_at = p - p % 10 + 10 }
                     next }
  /^(gmake|make)\[/ { next }
  { print > "/dev/stderr" }'
echo "build: done in $((SECONDS - start)) s" >&2
