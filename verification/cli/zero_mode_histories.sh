#!/usr/bin/env bash
# Issue 4 acceptance, from the CLI: |gap_1(CB, 0) - gap_1(CCM, 0)| <= 1e-9 of
# max |gap_1| over the default case's history.csv (CB(0) and CCM(0) are the
# same basis in the same coordinates, SPEC V4).
# Usage: zero_mode_histories.sh RSI SOURCE_DIR
set -eu
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case_file=$src/data/cases/batailly2007.json
for method in cb ccm; do
  "$rsi" simulate "$case_file" --method "$method" --modes 0 --out "$work/$method" >/dev/null
done
/usr/bin/python3 - "$work/cb/history.csv" "$work/ccm/history.csv" <<'PY'
import sys
import numpy as np

cb = np.genfromtxt(sys.argv[1], delimiter=",", names=True)
ccm = np.genfromtxt(sys.argv[2], delimiter=",", names=True)
assert len(cb) == len(ccm), f"{len(cb)} and {len(ccm)} history rows"
d = np.max(np.abs(cb["gap_1"] - ccm["gap_1"])) / np.max(np.abs(cb["gap_1"]))
print(f"{len(cb)} rows: max |gap_1(CB 0) - gap_1(CCM 0)| / max |gap_1| = {d:.3e} (limit 1e-9)")
sys.exit(0 if d <= 1e-9 else 1)
PY
