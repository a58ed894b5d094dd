#!/usr/bin/env bash
# Issue 11: `rsi export` of the paper's case, read back as a matrix_market
# component and exported again, gives byte-identical files, and `rsi modes`
# of both gives identical frequencies (same matrices, same solver).
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
echo "$(( 10 - failures )) passed, $failures failed"
[ "$failures" -eq 0 ]
