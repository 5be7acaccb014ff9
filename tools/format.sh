#!/usr/bin/env bash
# The house style (.clang-format: 4-space indent, 120 columns) on every C++ file git tracks.
#   tools/format.sh           rewrites the files in place
#   tools/format.sh --check   changes nothing; fails, naming each file and line, when clang-format
#                             would change a file or a line is longer than 120 columns (raw string
#                             literals and comments, which clang-format leaves as written)
set -euo pipefail
cd "$(dirname "$(readlink -f "$0")")/.."  # the checkout, also when reached through a link
mapfile -t files < <(git ls-files '*.cpp' '*.hpp' '*.h')
if [ "${1:-}" != --check ]; then
  clang-format -i "${files[@]}"
  exit 0
fi
status=0
clang-format --dry-run --Werror "${files[@]}" || status=1
python3 - "${files[@]}" <<'PY' || status=1
import sys
long = [f"{f}:{i}: {len(l)} columns" for f in sys.argv[1:]
        for i, l in enumerate(open(f, encoding="utf-8").read().split("\n"), 1) if len(l) > 120]
print("\n".join(long), file=sys.stderr) if long else None
sys.exit(1 if long else 0)
PY
[ $status -eq 0 ] && echo "format: ${#files[@]} files in the house style"
exit $status
