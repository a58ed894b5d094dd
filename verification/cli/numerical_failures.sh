#!/usr/bin/env bash
# Exit 3 end to end (issue 13, class 8): every numerical failure a valid case
# reaches through the CLI exits 3 with exactly one stderr line starting
# "rsi: error:" that says what failed and what to change. The paths no
# valid case reaches (the reduced integrator's mass, a singular contact
# matrix, the reference's own factor of M, the reduced eigenproblem) are
# tested on their functions in test_failure_messages.cpp, which says why.
# Also (the messages of commands without --force, and of a staged output):
#  - a step above the limit in `rsi campaign` and `rsi sweep`, which have no
#    --force, names the key to change, never "or --force";
#  - a write that fails names the file under the --out the user gave, not
#    the staging folder (.rsi-stage-PID) it was written in.
# Cases (the default case shortened): the sprag case (kink -1 degree: the
# reference blows up at 6.6 ms); a campaign run whose given step is above the
# casing's limit (4.69e-6 s); a sweep of one speed with the same run and one
# with the case's step above the bladed disk's limit; `rsi modes` of a
# Matrix Market component whose M is indefinite (a diagonal entry 1e-30
# beside its off-diagonal terms); simulate and campaign under `ulimit -f`.
# Release: about 3 s (the AddressSanitizer build: 11 s).
# Usage: numerical_failures.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case_file=$src/data/cases/batailly2007.json
variant() { /usr/bin/python3 "$src/verification/cli/case_variant.py" "$case_file" "$@"; }
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}

# expect NAME STATUS -- COMMAND...: runs COMMAND (stdout to $work/out.txt,
# stderr to $work/err); checks its exit status and that stderr has exactly
# one line starting "rsi: error:" (its other lines, if any, are the runs'
# own: progress, failed runs). Then each `has TEXT` / `lacks TEXT` checks
# that line.
expect() {
  local name=$1 status=$2
  shift 3
  "$@" >"$work/out.txt" 2>"$work/err"
  local got=$?
  checked=$name
  error_line=$(grep '^rsi: error:' "$work/err")
  local n
  n=$(grep -c '^rsi: error:' "$work/err")
  if [ "$got" -ne "$status" ]; then
    fail "$name: exit $got, expected $status; stderr: $(head -c 800 "$work/err")"
  elif [ "$n" -ne 1 ]; then
    fail "$name: $n 'rsi: error:' lines on stderr, expected 1: $(head -c 800 "$work/err")"
  else
    echo "ok   $name: exit $got, $(head -c 300 <<<"$error_line")"
  fi
}
has() {
  grep -qF -- "$1" <<<"$error_line" || fail "$checked: the error line does not say \"$1\": $error_line"
}
lacks() {
  ! grep -qF -- "$1" <<<"$error_line" || fail "$checked: the error line says \"$1\": $error_line"
}

# 1. simulate, the sprag case: the run stops (blow-up), exit 3, and the line
# says the step was stable and which keys feed the energy in.
variant "$work/sprag.json" time.duration=0.008 time.output_every=7 bladed_disk.kink_angle_deg=-1.0 \
  'campaign=[{"method": "cb", "modes": [10]}]'
expect "simulate, sprag" 3 -- "$rsi" simulate "$work/sprag.json" --out "$work/sim"
has "numerical failure: the run stopped: blow-up"
has "change operating_point.friction_coefficient or the sign of bladed_disk.kink_angle_deg"
has "--out $work/sim holds the run up to the stop"

# 2. simulate above the limit with --force: the bladed disk's top mode grows
# from the first contact on (step 472 of 3e-6 s; stopped at step 488); the
# line says to drop --force.
variant "$work/forced.json" time.duration=0.0045 time.step=3e-6
expect "simulate --force above the limit" 3 -- "$rsi" simulate "$work/forced.json" --force --out "$work/sim"
has "numerical failure: the run stopped: blow-up"
has "use a smaller step (time.step, --time-step) and drop --force"

# 3. campaign, the sprag case: the reference fails, exit 3 before any output
# (--out not created), the line says why and what to change.
expect "campaign, sprag reference" 3 -- "$rsi" campaign "$work/sprag.json" --jobs 1 --no-report --out "$work/c3"
has "numerical failure: campaign: the reference run failed: blow-up"
has "change operating_point.friction_coefficient"
[ -e "$work/c3" ] && fail "campaign, sprag reference: --out was created"

# 4. campaign, a reduced run's given step 5e-6 s above the casing's limit:
# that run fails, the others are published, exit 3 with one error line; the
# run's own line names its key, and no --force (a campaign has none).
variant "$work/given.json" time.duration=0.002 \
  'campaign=[{"method": "cb", "modes": [10], "time_step": [5e-6]}, {"method": "cb", "modes": [10]}]'
expect "campaign, a run above its limit" 3 -- "$rsi" campaign "$work/given.json" --jobs 1 --no-report --out "$work/c4"
has "numerical failure: 1 of 3 campaign runs failed"
run_line=$(grep '^rsi: campaign run cb-10-dt-5e-06 failed:' "$work/err")
grep -qF "a smaller time_step of run cb-10-dt-5e-06 in key 'campaign'" <<<"$run_line" ||
  fail "campaign, a run above its limit: its line does not name its time_step: $run_line"
grep -qF "or --force" "$work/err" && fail "campaign, a run above its limit: stderr offers --force: $(cat "$work/err")"
[ -s "$work/c4/runs/cb-10/history.csv" ] || fail "campaign, a run above its limit: the other runs were not published"

# 5. campaign with the case's step above the bladed disk's limit: refused
# before any run, exit 2, naming time.step, no --force.
variant "$work/unstable.json" time.duration=0.002 time.step=3e-6
expect "campaign, time.step above the limit" 2 -- "$rsi" campaign "$work/unstable.json" --no-report --out "$work/c5"
has "time.step = 3e-06 s is not below the central-difference stability limit of the bladed disk"
has "(time.step; a campaign has no --force)"
lacks "or --force"

# 6. sweep (no --force either), one speed: a CB-10 run at the given step
# 5e-6 s: its speed's line names the key; one error line, exit 3. Then a
# full run at the case's step 3e-6 s: refused before any run as in the
# campaign (5.), exit 2, nothing in --out (until session 10 each speed's
# full run failed in turn, exit 3, with the sweep's files written).
variant "$work/sweep.json" sweep.duration=0.002 sweep.transient=0.001
expect "sweep, --time-step above the limit" 3 -- "$rsi" sweep "$work/sweep.json" --speeds 300 --method cb --modes 10 \
  --time-step 5e-6 --jobs 1 --quiet --no-report --out "$work/s6"
has "numerical failure: 1 run(s) of the sweep failed"
grep -qF "a smaller time_step of run cb-10-dt-5e-06 (sweep.runs or --time-step)" "$work/err" ||
  fail "sweep, --time-step above the limit: no line names the run's time_step: $(cat "$work/err")"
grep -qF "or --force" "$work/err" && fail "sweep, --time-step above the limit: stderr offers --force: $(cat "$work/err")"
variant "$work/sweep-unstable.json" time.step=3e-6 time.output_every=10 sweep.duration=0.002 sweep.transient=0.001
expect "sweep, time.step above the limit" 2 -- "$rsi" sweep "$work/sweep-unstable.json" --speeds 300 --method full \
  --jobs 1 --quiet --no-report --out "$work/s7"
has "time.step = 3e-06 s is not below the central-difference stability limit of the bladed disk"
has "(time.step; a sweep has no --force)"
lacks "or --force"
[ -e "$work/s7" ] && fail "sweep, time.step above the limit: --out was created: $(ls -A "$work/s7")"

# 7. modes of a component whose M is not positive definite (the import
# checks only that its diagonal is positive): exit 3, naming the remedy.
"$rsi" export "$case_file" --out "$work/export" >/dev/null || fail "export failed"
mkdir "$work/indefinite"
cp "$work/export/casing/K.mtx" "$work/export/casing/dofs.csv" "$work/export/casing/nodes.csv" "$work/indefinite/"
awk 'NR <= 2 { print; next } $1 == 1 && $2 == 1 { print $1, $2, "1e-30"; next } { print }' \
  "$work/export/casing/M.mtx" >"$work/indefinite/M.mtx"
printf '{"component": {"name": "casing", "source": {"matrix_market": "indefinite"}, "units": "N, m, kg, s"}}\n' \
  >"$work/indefinite.json"
expect "modes, indefinite M of a component" 3 -- "$rsi" modes "$work/indefinite.json" --count 5 --out "$work/m7"
has "numerical failure: modal analysis: the mass matrix is not positive definite"
has "set component.mass to \"lumped\" (HRZ)"

# 8. A failed write names the file under the --out the user gave, not the
# staging folder (write_failures.sh checks the rest: exit 2, nothing left).
limited() { # LIMIT_KB COMMAND...: rsi under a file-size limit, SIGXFSZ ignored
  local limit=$1
  shift
  (
    trap '' XFSZ
    ulimit -f "$limit"
    "$@"
  )
}
expect "simulate over the file-size limit" 2 -- limited 200 "$rsi" simulate "$case_file" --out "$work/w8"
has "rsi: error: $work/w8/history.csv: cannot write (File too large)"
lacks ".rsi-stage"
lacks ".tmp"
variant "$work/short.json" time.duration=0.005 'campaign=[{"method": "cb", "modes": [10]}]'
expect "campaign over the file-size limit" 2 -- limited 100 "$rsi" campaign "$work/short.json" --jobs 1 --no-report --out "$work/w9"
has "rsi: error: $work/w9/runs/"
has "/history.csv: cannot write (File too large)"
lacks ".rsi-stage"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "every exit 3 a case reaches: one 'rsi: error:' line saying what to change"
