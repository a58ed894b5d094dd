#!/usr/bin/env bash
# SIGINT and SIGTERM stop the component commands cleanly (issue 13, class
# 6), as signals.sh checks for the paper's case: exit 130 / 143 with one
# `rsi: error: interrupted by SIG...` line, within 60 s of the signal (the
# runs poll it every 1000 steps: 0.1-2.5 s measured in Release, up to ten
# times that under the sanitizers; a run that polled nothing would go on
# for minutes), no temporary file left, no child left running, and no
# output that claims a finished run (the --out the command created is
# removed). On the gmsh blade (data/cases/blade3d*.json):
#  - component `simulate`, full reference (SIGINT) and CB-10 (SIGTERM), in
#    the middle of the integration (10 revolutions: about 220 s and 130 s
#    if the signal were not polled);
#  - the rubbing `campaign --no-report`, during its CB-10 run, after the
#    reference's files were staged;
#  - the rubbing campaign's report step (make_rubbing_report.py, a child);
#  - `modal-campaign` while it computes (it polls between bases) and
#    during its report step (make_modal_report.py);
#  - Ctrl-C while ccx builds the matrices (SIGINT to the process group,
#    ccx included, on a cold cache): exit 130, and the cache keeps no
#    half-made or ".failed" entry (a killed ccx is no failure of the model).
# About 23 s in Release (21-23 s measured on a shared 2-core machine).
# Skipped (exit 77) without gmsh or ccx; the two report steps are skipped
# without matplotlib.
# Usage: signals_components.sh RSI SOURCE_DIR CCX_CACHE
set -u
rsi=$1
src=$2
cache=$3
for tool in gmsh ccx setsid; do
  if ! command -v "$tool" >/dev/null; then
    echo "skipped: $tool is not on PATH (Debian packages gmsh, calculix-ccx, util-linux)"
    exit 77
  fi
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
variant() { /usr/bin/python3 "$src/verification/cli/case_variant.py" "$@"; }
rubbing=$src/data/cases/blade3d-rubbing.json
# Long runs, stopped after about a second of integration.
variant "$rubbing" "$work/long.json" rubbing.revolutions=10
# The campaign: a short reference (0.05 revolution), then a long CB-10.
variant "$rubbing" "$work/campaign.json" rubbing.revolutions=10 rubbing.campaign.full_revolutions=0.05 \
  'rubbing.campaign.runs=[{"method": "cb", "modes": [10]}]'
# Short campaigns, to reach the report steps in a few seconds.
variant "$rubbing" "$work/short.json" rubbing.revolutions=0.1 rubbing.campaign.full_revolutions=0.1 \
  'rubbing.campaign.runs=[{"method": "cb", "modes": [10]}]'
variant "$src/data/cases/blade3d.json" "$work/modal.json" \
  'modal_campaign={"methods": ["cb", "macneal"], "modes": [5, 10], "frequencies": 20}'
# The gmsh mesh and ccx matrices in the cache first (not timed below).
"$rsi" modes "$src/data/cases/blade3d.json" --count 1 --ccx-cache "$cache" --out "$work/warm" \
  >/dev/null || { echo "FAIL rsi modes on blade3d.json (warming the ccx cache)"; exit 1; }
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
now_ms() { echo $(($(date +%s%N) / 1000000)); }

# NAME SIGNAL EXPECTED_STATUS READY COMMAND...: starts COMMAND --out DIR,
# waits until READY (a glob under DIR: the run's temporary file exists; or
# sleep:SECONDS; or child:SCRIPT: that child of rsi runs), signals rsi and
# checks what it left.
interrupt() {
  local name=$1 signal=$2 expected=$3 ready=$4
  shift 4
  local out=$work/out-$name child="" started
  started=$(now_ms)
  "$@" --out "$out" >"$work/log" 2>"$work/err" &
  local pid=$!
  case $ready in
  sleep:*) sleep "${ready#sleep:}" ;;
  child:*)
    for _ in $(seq 1 1200); do # up to 60 s
      child=$(pgrep -P "$pid" -f "${ready#child:}" || true)
      [ -z "$child" ] && kill -0 "$pid" 2>/dev/null || break
      sleep 0.05
    done
    [ -n "$child" ] && sleep 0.2 # the script has started (imports)
    ;;
  *)
    for _ in $(seq 1 1200); do # up to 60 s (loading, the basis)
      compgen -G "$out/$ready" >/dev/null && break
      kill -0 "$pid" 2>/dev/null || break
      sleep 0.05
    done
    sleep 0.5 # into the integration
    ;;
  esac
  if ! kill -0 "$pid" 2>/dev/null; then
    wait "$pid"
    fail "$name: finished before the signal (exit $?; $(tail -n 2 "$work/log" "$work/err"))"
    return
  fi
  if [[ $ready == child:* && -z $child ]]; then
    kill -KILL "$pid"
    wait "$pid"
    fail "$name: no ${ready#child:} seen while rsi ran"
    return
  fi
  local before state
  before=$(now_ms)
  state=$(awk '{print $3}' "/proc/$pid/stat" 2>/dev/null) # R, S, D; Z: it had finished
  kill "-$signal" "$pid"
  wait "$pid"
  local status=$?
  local ms=$(($(now_ms) - before))
  sleep 0.5
  local temporaries
  temporaries=$(find "$work" -name '*.tmp[0-9]*' -o -name '.rsi-*' | head -n 5)
  if [ "$status" -ne "$expected" ]; then
    fail "$name: exit $status after SIG$signal sent $((before - started)) ms after the start" \
      "(process state ${state:-gone}), expected $expected; stderr: $(tail -n 3 "$work/err");" \
      "stdout: $(tail -n 3 "$work/log")"
  elif [ "$(grep -c '^rsi: error:' "$work/err")" -ne 1 ] ||
    ! grep -q "^rsi: error: interrupted by SIG$signal" "$work/err"; then
    fail "$name: not one 'rsi: error: interrupted by SIG$signal' line: $(cat "$work/err")"
  elif [ "$ms" -gt 60000 ]; then
    fail "$name: rsi exited $ms ms after SIG$signal (more than 60 s: the signal is not polled)"
  elif [ -n "$child" ] && kill -0 "$child" 2>/dev/null; then
    fail "$name: the child ${ready#child:} (pid $child) still runs after rsi exited"
    kill -KILL "$child" 2>/dev/null
  elif [ -n "$temporaries" ]; then
    fail "$name: temporary files left: $temporaries"
  elif [ -e "$out" ]; then
    fail "$name: output left behind: $(find "$out" | head -n 5)"
  else
    echo "ok   $name: SIG$signal -> exit $status in $ms ms, $(grep '^rsi: error' "$work/err" | head -c 60)..., nothing left"
  fi
}

cache_args=(--ccx-cache "$cache")
interrupt simulate-full INT 130 '.rsi-stage-*/history.csv.tmp*' \
  "$rsi" simulate "$work/long.json" "${cache_args[@]}"
interrupt simulate-cb TERM 143 '.rsi-stage-*/history.csv.tmp*' \
  "$rsi" simulate "$work/long.json" --method cb --modes 10 "${cache_args[@]}"
interrupt campaign TERM 143 '.rsi-stage-*/runs/cb-10/history.csv.tmp*' \
  "$rsi" campaign "$work/campaign.json" --no-report "${cache_args[@]}"
# modal-campaign writes nothing before its tables: interrupted by time,
# in the middle of its 15 bases (1.5 s of 6 s in Release; under the
# sanitizers possibly still loading, which must stop it all the same).
interrupt modal-campaign TERM 143 sleep:1.5 \
  "$rsi" modal-campaign "$src/data/cases/blade3d.json" --no-report "${cache_args[@]}"
if /usr/bin/python3 -c 'import matplotlib, numpy' 2>/dev/null; then
  interrupt campaign-report TERM 143 child:make_rubbing_report \
    "$rsi" campaign "$work/short.json" "${cache_args[@]}"
  interrupt modal-campaign-report TERM 143 child:make_modal_report \
    "$rsi" modal-campaign "$work/modal.json" "${cache_args[@]}"
else
  echo "skipped: campaign-report, modal-campaign-report (python3-matplotlib or numpy missing)"
fi

# Ctrl-C while ccx runs: the terminal sends SIGINT to the whole process
# group, rsi and its ccx child alike (setsid: a group of their own here).
cold=$work/cold-cache
out=$work/out-ccx
setsid "$rsi" modes "$src/data/cases/blade3d.json" --count 1 --ccx-cache "$cold" --out "$out" \
  >"$work/log" 2>"$work/err" &
pid=$!
ccx=""
for _ in $(seq 1 1200); do # up to 60 s for gmsh
  ccx=$(pgrep -P "$pid" -x ccx || true)
  [ -z "$ccx" ] && kill -0 "$pid" 2>/dev/null || break
  sleep 0.02
done
if [ -z "$ccx" ]; then
  wait "$pid"
  fail "ccx-int: no ccx child seen while rsi ran (exit $?): $(tail -n 2 "$work/err")"
else
  kill -INT -- "-$pid"
  wait "$pid"
  status=$?
  left=$(find "$cold" -maxdepth 1 \( -name '*.failed' -o -name '*.tmp*' \) | head -n 3)
  if [ "$status" -ne 130 ]; then
    fail "ccx-int: exit $status after SIGINT to rsi and ccx, expected 130: $(tail -n 2 "$work/err")"
  elif [ "$(grep -c '^rsi: error:' "$work/err")" -ne 1 ] ||
    ! grep -q '^rsi: error: interrupted by SIGINT' "$work/err"; then
    fail "ccx-int: not one 'rsi: error: interrupted by SIGINT' line: $(cat "$work/err")"
  elif [ -n "$left" ]; then
    fail "ccx-int: the interrupted ccx run left $left in the cache"
  elif [ -e "$out" ]; then
    fail "ccx-int: output left behind: $(find "$out" | head -n 5)"
  else
    echo "ok   ccx-int: SIGINT to rsi and ccx -> exit 130, $(head -c 60 "$work/err")..., no cache entry"
  fi
fi

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "all interruptions clean"
