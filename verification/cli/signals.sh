#!/usr/bin/env bash
# SIGINT and SIGTERM stop rsi cleanly (issue 13, class 6): exit 130 / 143
# with one `rsi: error:` line, no temporary file left, and no output that
# claims a finished run (the run's --out, created by it, is removed). The
# runs are long enough (the default case damped to run 1 s: 2e6 steps,
# about 20 s) to be interrupted in the middle; the campaign's report step
# is interrupted too.
# Usage: signals.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" "$work/long.json" \
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

# During the report step (issue 13, class 6: the Python child kept writing
# after rsi had exited): a 5 ms campaign (the reference and CB-10) with its
# report; SIGTERM once the report script runs (a child of rsi). rsi exits
# 143, the child is stopped (it is gone 1 s later), and --out is not created.
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" "$work/short.json" \
  time.duration=0.005 'campaign=[{"method": "cb", "modes": [10]}]'
if /usr/bin/python3 -c 'import matplotlib, scipy' 2>/dev/null; then
  out=$work/out-report
  "$rsi" campaign "$work/short.json" --out "$out" >"$work/log" 2>"$work/err" &
  pid=$!
  child=""
  for _ in $(seq 1 1200); do # up to 60 s for the runs
    child=$(pgrep -P "$pid" -f make_campaign_report || true)
    [ -n "$child" ] || ! kill -0 "$pid" 2>/dev/null || { sleep 0.05; continue; }
    break
  done
  if [ -z "$child" ]; then
    wait "$pid"
    fail "campaign-report: no report script seen while rsi ran (exit $?): $(tail -n 2 "$work/err")"
  else
    sleep 0.2 # the script has started (imports)
    kill -TERM "$pid"
    wait "$pid"
    status=$?
    sleep 1
    if [ "$status" -ne 143 ]; then
      fail "campaign-report: exit $status after SIGTERM in the report step, expected 143: $(tail -n 2 "$work/err")"
    elif kill -0 "$child" 2>/dev/null; then
      fail "campaign-report: the report script (pid $child) still runs after rsi exited"
      kill -KILL "$child" 2>/dev/null
    elif [ -e "$out" ]; then
      fail "campaign-report: output left behind: $(find "$out" | head -n 5)"
    else
      echo "ok   campaign-report: SIGTERM in the report step -> exit 143, the script stopped, nothing left in --out"
    fi
  fi
else
  echo "skipped: campaign-report (python3-matplotlib or python3-scipy missing)"
fi
if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "all interruptions clean"
