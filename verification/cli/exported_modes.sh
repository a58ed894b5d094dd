#!/usr/bin/env bash
# Issue 2 acceptance: `rsi modes --count 120` agrees with an independent
# dense solve (scipy) of the matrices written by `rsi export`.
# Usage: exported_modes.sh RSI SOURCE_DIR
set -eu
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$rsi" export "$src/data/cases/batailly2007.json" --out "$work/export" >/dev/null
"$rsi" modes "$src/data/cases/batailly2007.json" --part bladed-disk --count 120 --out "$work/modes" >/dev/null
/usr/bin/python3 "$src/verification/cli/check_exported_modes.py" "$work/export" "$work/modes/modes.csv"
