#!/usr/bin/env bash
# ctest's docs: every command in README.md and docs/*.md runs as written.
#   test_docs.sh SOURCE_DIR BUILD_DIR WORK_DIR
#
# Runnable examples are fenced ```sh blocks; synopses with placeholders (SCENE, FILE, PREFIX, ...)
# are ```text blocks and are not run. Each line of an sh block (a line ending in \ joined with the
# next; blank lines and comment lines skipped) runs in its own `bash -e -o pipefail`, in file order
# (README.md, then docs/*.md), from WORK_DIR. WORK_DIR is laid out like a checkout: each top-level
# entry of the source but those git ignores is a symbolic link to it, and build/ links to BUILD_DIR, so
# `build/scalecert certificates/scenes/x.json` runs as written against the built binaries, and what
# the commands write (out/, cert.json, a prefix) stays in WORK_DIR. A non-zero exit fails the test;
# a command meant to fail is written `cmd || test $? -eq 2` (or `! cmd`).
#
# Not run, because they cannot run in a test:
#   - the set-up commands tools/run-example.sh, tools/run-tests.sh, .ci/run (tools/ci.sh): they
#     install Debian packages and build;
#   - ctest, this script, tools/sanitize.sh and tools/fuzz.sh: the suite this test belongs to, a
#     second (clang) build, and minutes to half an hour of fuzzing;
#   - mpirun and srun with hundreds of ranks: a cluster;
#   - runs of minutes, past this test's minute: build/scalecert-bench (up to 7 GB; built by
#     `cmake --build build --target scalecert-bench`), tools/bench-mpi.sh, tools/bench-audit.sh
#     and tools/real_mesh_audit.py (which also installs libcgal-demo). These run with
#     SCALECERT_DOCS_LONG=1.
#   - the two ε-sweep audits of docs/audits.md (`--sweep 2 --sweep-to 40`, about 45 s each): they
#     run with SCALECERT_DOCS_SWEEPS=1, as CI runs the test command (tools/ci.sh), or with
#     SCALECERT_DOCS_LONG=1.
# Everything else runs.
# Lines using mpirun are skipped (and said so) when scalecert-mpi or mpirun is missing.
set -euo pipefail
SRC="$(cd "$1" && pwd)" BUILD="$(cd "$2" && pwd)" W="$3"
rm -rf "$W" && mkdir -p "$W"
W="$(cd "$W" && pwd)"
for entry in "$SRC"/* "$SRC"/.ci; do
  name="$(basename "$entry")"
  case "$name" in build*|out) continue ;; esac  # build trees and outputs of a checkout's own runs
  # What the docs' commands write at the top (fig5.json, venv-scalecert, ...) and git ignores: a
  # copy left by the user's own runs of them is not linked, so the test writes its own beside.
  if git -C "$SRC" check-ignore -q -- "$name" 2>/dev/null; then continue; fi
  ln -s "$entry" "$W/$name"
done
ln -s "$BUILD" "$W/build"
cd "$W"
# reason LINE: why LINE is not run here, or nothing if it is.
reason() {
  case "$1" in
    tools/run-example.sh*|tools/run-tests.sh*|.ci/run*|tools/ci.sh*|tools/no-baselines.sh*) echo "set-up: installs and builds" ;;
    ctest*|*"&& ctest"*|*tests/test_docs.sh*|tools/sanitize.sh*|tools/fuzz.sh*) echo "the test suite itself, or a fuzzing run" ;;
    "cmake --build build --target scalecert-bench"*) echo "builds the bench, which CI builds (tools/ci.sh)" ;;
    "mpirun -np "[1-9][0-9][0-9]*|srun*) echo "a cluster" ;;
    *)
      if [ "${SCALECERT_DOCS_LONG:-0}" != 1 ]; then
        case "$1" in
          build/scalecert-bench*|tools/bench-mpi.sh*|tools/bench-audit.sh*|*tools/real_mesh_audit.py*)
            echo "runs for minutes (SCALECERT_DOCS_LONG=1 runs it)"; return ;;
        esac
        if [ "${SCALECERT_DOCS_SWEEPS:-0}" != 1 ] && [[ "$1" == *"scalecert audit "*"--sweep-to 40"* ]]; then
          echo "an ε-sweep audit (SCALECERT_DOCS_SWEEPS=1 runs it, as CI does)"; return
        fi
      fi
      if [[ "$1" == mpirun* ]] && { [ ! -x build/scalecert-mpi ] || ! command -v mpirun >/dev/null; }; then
        echo "scalecert-mpi or mpirun is not built or installed"
      fi ;;
  esac
}

# The sh blocks of one file, one command a line, as "FILE:LINE<TAB>COMMAND".
commands() {
  awk -v f="$1" '
    /^```/ { if (inblock) { inblock = 0; next } if ($0 == "```sh") { inblock = 1; next } }
    !inblock { next }
    {
      line = $0
      if (cmd == "") { start = FNR; sub(/^[ \t]+/, "", line) }
      else sub(/^[ \t]+/, " ", line)
      if (line ~ /\\$/) { sub(/\\$/, "", line); cmd = cmd line; next }
      cmd = cmd line
      if (cmd !~ /^[ \t]*(#|$)/) printf "%s:%d\t%s\n", f, start, cmd
      cmd = ""
    }' "$1"
}

ran=0 skipped=0 failed=0
t0=$(date +%s)
files=(README.md docs/*.md)
for f in "${files[@]}"; do
  while IFS=$'\t' read -r where cmd; do
    why="$(reason "$cmd")"
    if [ -n "$why" ]; then
      echo "skip $where ($why): $cmd"
      skipped=$((skipped + 1))
      continue
    fi
    s=$(date +%s.%N)
    if bash -e -o pipefail -c "$cmd" </dev/null >"$W/last.out" 2>&1; then
      printf 'ok   %s (%.1f s): %s\n' "$where" "$(echo "$(date +%s.%N) - $s" | bc)" "$cmd"
      ran=$((ran + 1))
    else
      st=$?
      echo "FAIL $where (exit $st): $cmd" >&2
      tail -n 20 "$W/last.out" | sed 's/^/     | /' >&2
      failed=$((failed + 1))
    fi
  done < <(commands "$f")
done
echo "docs: $ran commands ran, $failed failed, $skipped not run (above), in $(( $(date +%s) - t0 )) s"
[ "$ran" -gt 0 ] || { echo "FAIL: no sh block found" >&2; exit 1; }
[ "$failed" -eq 0 ]
