#!/usr/bin/env bash
# SIGINT and SIGTERM stop rsi cleanly (issue 13, class 6): exit 130 / 143
# with one `rsi: error:` line, no temporary file left, and no output that
# claims a finished run (the run's --out, created by it, is removed). The
# runs are long enough (the default case damped to run 1 s: 2e6 steps,
# about 20 s) to be interrupted in the middle.
# Usage: signals.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$src/verification/case_variant.py" "$src/data/cases/batailly2007.json" "$work/long.json" \
  time.duration=1.0 time.output_every=100 'damping={"rayleigh": {"alpha": 30.0, "beta": 0.0}}' \
  'campaign=[{"method": "cb", "modes": [10]}]'
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
# NAME SIGNAL EXPECTED_STATUS COMMAND...: start, wait 2 s, signal, check.
interrupt() {
  local name=$1 signal=$2 expected=$3
  shift 3
  local out=$work/out-$name
  "$@" --out "$out" >"$work/log" 2>"$work/err" &
  local pid=$!
  sleep 2
  if ! kill -0 "$pid" 2>/dev/null; then
    fail "$name: finished before the signal (log: $(tail -n 2 "$work/log" "$work/err"))"
    return
  fi
  kill "-$signal" "$pid"
  wait "$pid"
  local status=$?
  if [ "$status" -ne "$expected" ]; then
    fail "$name: exit $status after SIG$signal, expected $expected; stderr: $(cat "$work/err")"
  elif ! grep -q "^rsi: error: interrupted by SIG$signal" "$work/err"; then
    fail "$name: no 'rsi: error: interrupted' line: $(cat "$work/err")"
  elif [ -e "$out" ]; then
    fail "$name: output left behind: $(find "$out")"
  else
    echo "ok   $name: SIG$signal -> exit $status, $(grep '^rsi: error' "$work/err"), nothing left in --out"
  fi
}
interrupt simulate-int INT 130 "$rsi" simulate "$work/long.json"
interrupt simulate-term TERM 143 "$rsi" simulate "$work/long.json" --method full
interrupt campaign-term TERM 143 "$rsi" campaign "$work/long.json" --no-report
if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "all interruptions clean"
