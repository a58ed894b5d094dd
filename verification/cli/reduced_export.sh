#!/usr/bin/env bash
# Issue 4 acceptance: T.mtx and K.mtx of `rsi reduce` satisfy T^T K T = K^
# with the K.mtx of `rsi export`, for CB and CCM.
# Usage: reduced_export.sh RSI SOURCE_DIR
set -eu
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case_file=$src/data/cases/batailly2007.json
"$rsi" export "$case_file" --out "$work/export" >/dev/null
for run in "cb 20" "ccm 44"; do
  set -- $run
  "$rsi" reduce "$case_file" --method "$1" --modes "$2" --out "$work/$1" >/dev/null
  echo "$1 with $2 modes:"
  /usr/bin/python3 "$src/verification/cli/check_reduced_export.py" "$work/export" "$work/$1"
done
