#!/usr/bin/env bash
# Issue 11: `rsi export` of the paper's case, read back as a matrix_market
# component and exported again, gives byte-identical files, and `rsi modes`
# of both gives identical frequencies (same matrices, same solver). The same
# round trip for a CalculiX component with a node ccx created.
# Usage: export_import_roundtrip.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
check() { # DESCRIPTION COMMAND...
  local what=$1
  shift
  if "$@"; then echo "ok   $what"; else echo "FAIL $what"; failures=$((failures + 1)); fi
}
"$rsi" export "$src/data/cases/batailly2007.json" --out "$work/a" >/dev/null || exit 1
for part in bladed-disk casing; do
  printf '{"component": {"name": "%s", "source": {"matrix_market": "a/%s"}, "units": "N, m, kg, s"}}\n' \
    "$part" "$part" >"$work/$part.json"
  "$rsi" export "$work/$part.json" --out "$work/b" >/dev/null || exit 1
  for f in K.mtx M.mtx dofs.csv nodes.csv; do
    check "$part/$f byte-identical after export, import, export" cmp "$work/a/$part/$f" "$work/b/$part/$f"
  done
  "$rsi" modes "$src/data/cases/batailly2007.json" --part "$part" --count 60 --out "$work/ma-$part" >/dev/null || exit 1
  "$rsi" modes "$work/$part.json" --count 60 --out "$work/mb-$part" >/dev/null || exit 1
  check "$part: 60 frequencies identical (modes.csv columns index, frequency_hz)" \
    cmp <(cut -d, -f1,2 "$work/ma-$part/modes.csv") <(cut -d, -f1,2 "$work/mb-$part/modes.csv")
done
# A CalculiX component with a node ccx created (above the deck's largest
# id: the incompatible modes of a C3D8I element, a knot's rotations): no
# position, written with empty coordinates, read back as such.
mkdir -p "$work/ccx"
printf '*NODE, NSET=NALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n' >"$work/ccx/deck.inp"
printf '1.1\n1.2\n2.1\n2.2\n2.1\n3.1\n3.2\n' >"$work/ccx/job.dof"
printf '1 1 4\n2 2 4\n3 3 4\n4 4 4\n5 5 4\n6 6 4\n7 7 4\n1 3 -1\n3 6 -1\n' >"$work/ccx/job.sti"
printf '1 1 1\n2 2 1\n3 3 1\n4 4 1\n5 5 1\n6 6 1\n7 7 1\n' >"$work/ccx/job.mas"
printf '{"component": {"name": "beam", "source": {"calculix_deck": "ccx/deck.inp", "calculix_matrices": "ccx/job"}, "boundary": {"nodes": [2]}, "units": "N, mm, t, s"}}\n' >"$work/beam.json"
printf '{"component": {"name": "beam", "source": {"matrix_market": "a/beam"}, "units": "N, mm, t, s"}}\n' >"$work/beam-mm.json"
"$rsi" export "$work/beam.json" --out "$work/a" >/dev/null || exit 1
"$rsi" export "$work/beam-mm.json" --out "$work/b" >/dev/null || exit 1
for f in K.mtx M.mtx dofs.csv nodes.csv; do
  check "beam/$f byte-identical after export, import, export" cmp "$work/a/beam/$f" "$work/b/beam/$f"
done
check "beam/nodes.csv: the created node 3 has empty coordinates" grep -qx '3,,,' "$work/a/beam/nodes.csv"
check "beam/dofs.csv: the three rows of node 2 (two of ux) are the boundary" \
  test "$(grep -c ',2,u[xy],1$' "$work/a/beam/dofs.csv")" -eq 3
echo "$(( 16 - failures )) passed, $failures failed"
[ "$failures" -eq 0 ]
