#!/usr/bin/env bash
# ctest's pip_install: `pip install --no-build-isolation ./python` in a fresh virtual environment
# made with --system-site-packages (numpy from Debian), with no network (--no-index), reusing this
# build tree (SCALECERT_BUILD_DIR); then the module imports and answers a query by hand (stacked
# cubes touching on rho1 + rho2 = 3).
#   test_pip.sh SOURCE_DIR BUILD_DIR WORK_DIR
set -euo pipefail
SRC="$1" BUILD="$2" W="$3"
rm -rf "$W" && mkdir -p "$W"
/usr/bin/python3 -m venv --system-site-packages "$W/venv"
# (A copy of python/'s packaging files: pip builds in the folder it is given, and this test leaves
# the source tree as it was. With SCALECERT_BUILD_DIR the copy needs nothing else of the checkout.)
mkdir -p "$W/pkg" && cp "$SRC/python/setup.py" "$SRC/python/pyproject.toml" "$W/pkg/"
SCALECERT_BUILD_DIR="$BUILD" "$W/venv/bin/pip" install -q --no-build-isolation --no-index "$W/pkg" >"$W/pip.log" 2>&1 || { cat "$W/pip.log"; exit 1; }
cd "$W"
"$W/venv/bin/python" - <<'PY'
import scalecert
assert scalecert.__file__.startswith(__import__("sys").prefix), scalecert.__file__
box = lambda z0, z1: [[x, y, z] for x in (0, 2) for y in (0, 2) for z in (z0, z1)]
s = scalecert.Scene(box(0, 2), box(3, 5), (1, 2), (1, 2))
assert s.query("3/2", "3/2")["verdict"] == scalecert.Verdict.Touching
print("pip install: scalecert", scalecert.__version__, "from", scalecert.__file__)
PY
