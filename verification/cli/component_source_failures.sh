#!/usr/bin/env bash
# A component's source failing is reported where the user can read it, with
# exit 2 naming the key (issue "Hardening, third round", class 5; the gmsh
# blade's cache key on its material is test_gmsh_blade_cache's):
# 1. young_modulus 1e-300 (in range: > 0): exit 2, one line naming the
#    material keys (was exit 1 "TridiagEigen: eigen decomposition failed").
# 2. gmsh failing (a fake gmsh first on PATH, printing an Error line): exit
#    2, one line naming the key, quoting gmsh's error, and naming a log that
#    exists and holds it (was a .tmpPID folder already removed).
# 3. A CalculiX deck with E = 0, which ccx refuses: exit 2, one line naming
#    component.source.calculix_deck and quoting ccx's whole message ("the
#    Young modulus should exceed 0.0", cut over two lines of its log; only
#    "the Young" was quoted, on lines of their own).
# About 3 s in Release. Skipped (exit 77) without gmsh or ccx.
# Usage: component_source_failures.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
. "$(dirname "$0")/skip_without_gmsh_ccx.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
variant() { /usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/blade3d.json" "$@"; }

# 1. A vanishing Young's modulus.
variant "$work/vanishing.json" component.source.gmsh_blade.young_modulus=1e-300
"$rsi" modes "$work/vanishing.json" --count 3 --ccx-cache "$work/cache-fresh" --out "$work/out-vanishing" >"$work/out" 2>"$work/err"
status=$?
if [ "$status" -ne 2 ] || [ "$(wc -l <"$work/err")" -ne 1 ] ||
  ! grep -q "^rsi: error: .*keys 'component.source.gmsh_blade.young_modulus' and 'component.source.gmsh_blade.density': the stiffness vanishes against the mass" "$work/err"; then
  fail "young_modulus 1e-300: exit $status, $(head -c 400 "$work/err")"
else
  echo "ok   young_modulus 1e-300: exit 2, $(head -c 300 "$work/err")"
fi
[ -e "$work/out-vanishing" ] && fail "young_modulus 1e-300: --out was written"

# 2. gmsh failing: its log kept and named.
mkdir -p "$work/bin"
printf '#!/bin/sh\necho "Info    : fake gmsh reading $1"\necho "Error   : fake failure of the mesher"\nexit 3\n' >"$work/bin/gmsh"
chmod +x "$work/bin/gmsh"
variant "$work/other.json" component.source.gmsh_blade.span=95.0
PATH="$work/bin:$PATH" "$rsi" modes "$work/other.json" --count 3 --ccx-cache "$work/cache-fresh" --out "$work/out-gmsh" >"$work/out" 2>"$work/err"
status=$?
log=$(sed -n "s/.*output in \([^)]*gmsh\.log\)).*/\1/p" "$work/err")
if [ "$status" -ne 2 ] || [ "$(wc -l <"$work/err")" -ne 1 ] ||
  ! grep -q "^rsi: error: .*key 'component.source.gmsh_blade': 'gmsh blade.geo -3 .*' failed (exit status 3)" "$work/err" ||
  ! grep -q "Error   : fake failure of the mesher" "$work/err"; then
  fail "gmsh failing: exit $status, $(head -c 600 "$work/err")"
elif [ -z "$log" ] || ! grep -q "fake failure of the mesher" "$log" 2>/dev/null; then
  fail "gmsh failing: the log named ('$log') is missing or does not hold gmsh's error: $(head -c 600 "$work/err")"
elif [ -n "$(find "$work/cache-fresh" -name '*.tmp*')" ]; then
  fail "gmsh failing: a temporary folder was left: $(find "$work/cache-fresh" -name '*.tmp*')"
else
  echo "ok   gmsh failing: exit 2, the log $log kept ($(wc -l <"$log") lines): $(head -c 400 "$work/err")"
fi
# 3. A deck ccx refuses.
cat >"$work/zero.inp" <<'DECK'
*NODE, NSET=NALL
1, 100., -5., -5.
2, 110., -5., -5.
3, 110., 5., -5.
4, 100., 5., -5.
5, 100., -5., 5.
6, 110., -5., 5.
7, 110., 5., 5.
8, 100., 5., 5.
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
*NSET, NSET=ROOT
1, 4, 5, 8
*NSET, NSET=TIP
2, 3, 6, 7
*MATERIAL, NAME=STEEL
*ELASTIC
0., 0.3
*DENSITY
7.85e-9
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*BOUNDARY
ROOT, 1, 3
DECK
printf '{"component": {"name": "zero", "source": {"calculix_deck": "zero.inp"}, "boundary": {"node_set": "TIP"}, "units": "N, mm, t, s"}}\n' >"$work/zero.json"
"$rsi" modes "$work/zero.json" --count 3 --ccx-cache "$work/cache-fresh" --out "$work/out-zero" >"$work/out" 2>"$work/err"
status=$?
if [ "$status" -ne 2 ] || [ "$(wc -l <"$work/err")" -ne 1 ] ||
  ! grep -q "^rsi: error: .*zero.json: key 'component.source.calculix_deck': .*ccx failed on the model.*the Young modulus should exceed 0.0" "$work/err"; then
  fail "deck with E = 0: exit $status, $(head -c 600 "$work/err")"
else
  echo "ok   deck with E = 0: exit 2, $(head -c 400 "$work/err")"
fi
echo "$failures failed"
[ "$failures" -eq 0 ]
