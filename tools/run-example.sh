#!/usr/bin/env bash
# The main job: installs what is missing, builds, certifies a bundled scene (the paper's Fig. 5
# sequence by default) and shows its curve, switch points and growth distance.
set -euo pipefail
cd "$(dirname "$0")/.."
SCENE="${1:-certificates/scenes/fig5_vf_ve_ee.json}"
tools/install-deps.sh
tools/build.sh >/dev/null
mkdir -p out
name="$(basename "$SCENE" .json)"
build/scalecert partition "$SCENE" --out "out/$name.partition.json"
python3 tools/summary.py "out/$name.partition.json"
echo "certificate: out/$name.partition.json"
