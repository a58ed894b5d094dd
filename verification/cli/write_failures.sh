#!/usr/bin/env bash
# A write that fails (disk full, file-size limit) is an error, never a
# truncated file renamed into place with exit 0 (issue 13, class 3). The
# file-size limit stands in for a full disk: with SIGXFSZ ignored (the
# signal would kill rsi instead), write() past `ulimit -f` fails with
# EFBIG, as it fails with ENOSPC on a full disk. Each command must exit 2
# naming the file, leave no temporary file, and leave the previous output
# of the same name as it was.
# Usage: write_failures.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case_file=$src/data/cases/batailly2007.json
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
# shellcheck source=file_size_limit.sh
source "$src/verification/cli/file_size_limit.sh"
check() { # NAME EXPECTED_FILE_PATTERN STATUS DIR
  local name=$1 pattern=$2 status=$3 dir=$4
  if [ "$status" -ne 2 ]; then
    fail "$name: exit $status, expected 2; stderr: $(cat "$work/err")"
  elif ! grep -q "^rsi: error: .*$pattern.*cannot write" "$work/err"; then
    fail "$name: stderr does not name the file: $(cat "$work/err")"
  elif [ -n "$(find "$dir" -name '*.tmp*' 2>/dev/null)" ]; then
    fail "$name: temporary files left: $(find "$dir" -name '*.tmp*')"
  else
    echo "ok   $name: exit 2, $(head -c 160 "$work/err")"
  fi
}

# 1. export: K.mtx of the bladed disk is about 400 kB, the limit 100 kB.
"$rsi" export "$case_file" --out "$work/export" >/dev/null || fail "export without a limit failed"
cp -r "$work/export" "$work/export.before"
limited 100 export "$case_file" --out "$work/export"
check "export over the file-size limit" "K.mtx" $? "$work/export"
if diff -r "$work/export" "$work/export.before" >/dev/null; then
  echo "ok   export: the previous K.mtx, M.mtx, dofs.csv, nodes.csv untouched"
else
  fail "export: the previous output changed"
fi

# 2. reduce: T.mtx of CB-10 (838 x 54, about 1.3 MB) over a 300 kB limit.
limited 300 reduce "$case_file" --method cb --modes 10 --out "$work/reduce"
check "reduce over the file-size limit" "mtx" $? "$work/reduce"
[ -e "$work/reduce/T.mtx" ] && fail "reduce: a T.mtx was left"

# 3. simulate: the streamed history (about 900 kB for 20 ms) over 200 kB.
limited 200 simulate "$case_file" --out "$work/simulate"
check "simulate over the file-size limit" "history.csv" $? "$work/simulate"
[ -e "$work/simulate/history.csv" ] && fail "simulate: a history.csv was left"

# 4. campaign (the reference and CB-10): each run's streamed history (about
# 180 kB for 5 ms) over 100 kB. A write that fails ends the campaign (exit
# 2), not one run: it was a failed run each, the reference's an exit 3
# "numerical failure", and a disk full during one reduced run published the
# others.
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$case_file" "$work/short.json" time.duration=0.005 \
  'campaign=[{"method": "cb", "modes": [10]}]'
"$rsi" campaign "$work/short.json" --no-report --out "$work/campaign" >/dev/null 2>&1 ||
  fail "campaign without a limit failed"
cp -r "$work/campaign" "$work/campaign.before"
limited 100 campaign "$work/short.json" --no-report --out "$work/campaign"
check "campaign over the file-size limit" "history.csv" $? "$work/campaign"
if diff -r "$work/campaign" "$work/campaign.before" >/dev/null; then
  echo "ok   campaign: the previous runs, convergence.csv and modes untouched"
else
  fail "campaign: the previous output changed"
fi

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "all write failures reported"
