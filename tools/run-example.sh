#!/usr/bin/env bash
# The main job: installs what is missing, builds, certifies a bundled scene (the paper's Fig. 5
# sequence by default), checks the certificate, shows its curve, switch points and growth
# distance, and draws the paper's figures for it.
set -euo pipefail
cd "$(dirname "$0")/.."
SCENE="${1:-certificates/scenes/fig5_vf_ve_ee.json}"
tools/install-deps.sh
echo "building (about 5 minutes on 2 idle cores the first time) ..." >&2
tools/build.sh
name="$(basename "$SCENE" .json)"
out="out/$name"
mkdir -p "$out/figures"
build/scalecert partition "$SCENE" --out "$out/partition.json"
build/scalecert curve "$SCENE" --segment seeds --out "$out/curve.json"
build/scalecert grid "$SCENE" --n 40 --out "$out/grid.json"
python3 tools/summary.py "$out/partition.json"
echo "independent check: $(build/scalecert-check "$out/partition.json")"
/usr/bin/python3 tools/plot.py "$out/partition.json" "$out/curve.json" "$out/grid.json" "$out/figures"
echo "certificate: $out/partition.json"
echo "figures (PNG and SVG): $out/figures/{fig6_rho,fig3_grid,fig6_t,fig7_loci,fig5_3d}"
