#!/usr/bin/env bash
# A build without the floating-point baselines (SCALECERT_BUILD_BASELINES=OFF; tools/no-baselines.sh
# makes it): scalecert partition, certify-fp and golden work, scalecert-check accepts the partition,
# and audit and grid are not commands. With a full build's scalecert as $4, the partition is
# byte-identical to that build's.
# Usage: test_no_baselines.sh SCALECERT SCALECERT_CHECK SOURCE_DIR [FULL_SCALECERT]
set -uo pipefail
SC="$1" CHECK="$2" SRC="$3" FULL="${4:-}"
WORK=$(mktemp -d)
trap 'rm -rf "$WORK"' EXIT
fail=0
ok() { echo "ok: $*"; }
bad() { echo "FAILED: $*"; fail=1; }

# No floating-point library in the program.
if ldd "$SC" | grep -Eq 'libccd|libfcl|Bullet|LinearMath'; then bad "scalecert links a floating-point library"; else ok "no libccd, FCL or Bullet linked"; fi

# audit and grid are not registered.
"$SC" --help >"$WORK/help" 2>&1 || bad "scalecert --help"
if grep -Eq '^ *(audit|grid) ' "$WORK/help"; then bad "--help lists audit or grid"; else ok "--help lists neither audit nor grid"; fi
"$SC" audit "$SRC/certificates/scenes/stacked_cubes.json" >/dev/null 2>"$WORK/err"
[ $? -eq 2 ] && grep -q "unknown command 'audit'" "$WORK/err" && ok "audit: exit 2, unknown command" || bad "audit was not refused: $(cat "$WORK/err")"

# The partition of a scene with switch points, checked.
SCENE="$SRC/certificates/scenes/fig5_vf_ve_ee.json"
"$SC" partition "$SCENE" --out "$WORK/p.json" || bad "partition"
"$CHECK" "$WORK/p.json" >"$WORK/check" 2>&1 && grep -q '^valid' "$WORK/check" && ok "scalecert-check: $(head -1 "$WORK/check")" || bad "checker: $(cat "$WORK/check")"
if [ -n "$FULL" ]; then
  "$FULL" partition "$SCENE" --out "$WORK/p-full.json" && cmp -s "$WORK/p.json" "$WORK/p-full.json" && ok "partition byte-identical to the full build's" || bad "partition differs from the full build's"
fi

# certify-fp, by hand on the stacked cubes: they touch on rho1 + rho2 = 3 (growth distance 3/2).
CUBES="$SRC/certificates/scenes/stacked_cubes.json"
printf '1 1 separated\n1.5 1.5 touching\ngrowth 1.5\n' >"$WORK/right.txt"
printf '2 2 separated\n' >"$WORK/wrong.txt"
"$SC" certify-fp "$CUBES" "$WORK/right.txt" >"$WORK/r1" && grep -q 'claims: 3, right: 3, wrong: 0' "$WORK/r1" && ok "certify-fp: 3 right claims, exit 0" || bad "certify-fp right claims: $(cat "$WORK/r1")"
"$SC" certify-fp "$CUBES" "$WORK/wrong.txt" >"$WORK/r2"
[ $? -eq 1 ] && grep -q 'wrong: 1' "$WORK/r2" && ok "certify-fp: (2, 2) separated is wrong, exit 1" || bad "certify-fp wrong claim: $(cat "$WORK/r2")"

# golden data of a family.
"$SC" golden --family random --count 2 --dir "$WORK/g" 2>/dev/null && [ -s "$WORK/g/random-1.golden.csv" ] && ok "golden: 2 scenes written" || bad "golden"

exit $fail
