#!/usr/bin/env bash
# A command's output is one run's output (issue 13, class 4): a reused
# --out holds the set of the last run that published (exit 0, or 3 with the
# stopped run's history and summary) and nothing of an earlier run's set;
# exit 2, a refused concurrent run and an interruption leave --out byte for
# byte as it was; a user's own file in --out survives everything; no lock
# file, staging folder or temporary file is left. The paper's case, cut to
# 5 ms (contact from 3.96 ms), keeps it quick.
# Usage: output_directory.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
variant() { # NAME KEY=JSON...
  local name=$1
  shift
  /usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" \
    "$work/$name.json" "$@"
}
variant contact time.duration=0.005 time.output_every=7 'campaign=[{"method": "cb", "modes": [10]}]'
variant other time.duration=0.005 time.output_every=7 'campaign=[{"method": "ccm", "modes": [4]}]'
variant free time.duration=0.005 time.output_every=7 casing.radius=0.6
variant sprag time.duration=0.008 time.output_every=7 bladed_disk.kink_angle_deg=-1.0
variant unstable time.duration=0.005 time.step=1e-5
# Damped, contact-free, about 2 s (0.1 s) and 20 s (1 s) of integration.
variant medium time.duration=0.1 time.output_every=100 casing.radius=0.6 \
  'damping={"rayleigh": {"alpha": 30.0, "beta": 0.0}}'
variant long time.duration=1.0 time.output_every=100 \
  'damping={"rayleigh": {"alpha": 30.0, "beta": 0.0}}'
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
# Every path under DIR with the checksum of each file (hidden ones too).
listing() {
  (cd "$1" && find . | LC_ALL=C sort | while read -r p; do
    if [ -f "$p" ]; then echo "$p $(sha256sum <"$p" | cut -c1-64)"; else echo "$p"; fi
  done)
}
# DIR: the user's notes intact, no lock, staging, old-set or temporary file.
clean() {
  [ "$(cat "$1/notes.txt" 2>/dev/null)" = "my notes" ] || fail "$1: the user's notes.txt is gone or changed"
  local left
  left=$(find "$1" -name '.rsi-*' -o -name '*.tmp*')
  [ -z "$left" ] || fail "$1: left behind: $left"
}
sim=$work/simulate
mkdir -p "$sim"
echo "my notes" >"$sim/notes.txt"

# 1. A contact-free run after a contact run (with --full-field): neither
# casing_first_contact.csv nor field.csv of the earlier run stays.
"$rsi" simulate "$work/contact.json" --method cb --modes 10 --full-field --out "$sim" >"$work/log" 2>&1 ||
  fail "contact run: $(tail -n 1 "$work/log")"
[ -f "$sim/casing_first_contact.csv" ] && [ -f "$sim/field.csv" ] ||
  fail "contact run: no casing_first_contact.csv or field.csv: $(ls -A "$sim")"
"$rsi" simulate "$work/free.json" --method full --out "$sim" >"$work/log" 2>&1 ||
  fail "contact-free run: $(tail -n 1 "$work/log")"
if [ -e "$sim/casing_first_contact.csv" ] || [ -e "$sim/field.csv" ]; then
  fail "contact-free run after a contact run: the old files stay: $(ls -A "$sim")"
elif ! grep -q '"method": "full"' "$sim/summary.json"; then
  fail "contact-free run: summary.json is not this run's"
else
  echo "ok   contact-free run after a contact run: $(ls -A "$sim" | tr '\n' ' ')"
fi
clean "$sim"

# 2. Exit 2 during the run (time step above the stability limit, found
# after --out is locked and staged): --out byte for byte as before.
"$rsi" simulate "$work/contact.json" --method cb --modes 10 --full-field --out "$sim" >/dev/null 2>&1
before=$(listing "$sim")
"$rsi" simulate "$work/unstable.json" --method full --out "$sim" >"$work/log" 2>"$work/err"
status=$?
if [ "$status" -ne 2 ]; then
  fail "unstable run: exit $status, expected 2: $(cat "$work/err")"
elif [ "$(listing "$sim")" != "$before" ]; then
  fail "unstable run (exit 2) changed --out: $(diff <(echo "$before") <(listing "$sim"))"
else
  echo "ok   exit 2 ($(head -c 100 "$work/err")...): --out byte for byte as before"
fi
# Exit 2 before the run (an option the paper's case refuses).
"$rsi" simulate "$work/contact.json" --method macneal --out "$sim" >/dev/null 2>&1
status=$?
[ "$status" -eq 2 ] && [ "$(listing "$sim")" = "$before" ] ||
  fail "--method macneal on the paper's case: exit $status (expected 2) or --out changed"
clean "$sim"

# 3. Exit 3 (blow-up): the stopped run's history.csv and summary.json, and
# none of the previous run's files (field.csv; every file of the set new).
"$rsi" simulate "$work/sprag.json" --method full --out "$sim" >"$work/log" 2>"$work/err"
status=$?
stale=""
for f in history.csv summary.json casing_first_contact.csv; do
  [ -e "$sim/$f" ] && echo "$before" | grep -qF "./$f $(sha256sum <"$sim/$f" | cut -c1-64)" && stale="$stale $f"
done
if [ "$status" -ne 3 ]; then
  fail "sprag run: exit $status, expected 3: $(cat "$work/err")"
elif ! [ -s "$sim/history.csv" ] || ! grep -q blow-up "$sim/summary.json"; then
  fail "sprag run (exit 3): history.csv or the blow-up status in summary.json missing"
elif [ -e "$sim/field.csv" ] || [ -n "$stale" ]; then
  fail "sprag run (exit 3): files of the previous run stay: field.csv? $(ls "$sim/field.csv" 2>&1) stale:$stale"
else
  echo "ok   exit 3 (blow-up): this run's $(ls -A "$sim" | tr '\n' ' '), no field.csv of the previous run"
fi
clean "$sim"

# 4. An interrupted run (SIGINT after 2 s of a 20 s run): --out as before.
before=$(listing "$sim")
"$rsi" simulate "$work/long.json" --method full --out "$sim" >"$work/log" 2>"$work/err" &
pid=$!
sleep 2
kill -INT "$pid"
wait "$pid"
status=$?
if [ "$status" -ne 130 ]; then
  fail "interrupted run: exit $status, expected 130: $(cat "$work/err")"
elif [ "$(listing "$sim")" != "$before" ]; then
  fail "interrupted run changed --out: $(diff <(echo "$before") <(listing "$sim"))"
else
  echo "ok   interrupted run (SIGINT, exit 130): --out byte for byte as before"
fi
clean "$sim"

# 5. Two runs on one --out: the second refuses (exit 2, one line naming the
# first's pid) and changes nothing; the first completes and publishes.
"$rsi" simulate "$work/medium.json" --method full --out "$sim" >"$work/log1" 2>"$work/err1" &
first=$!
for _ in $(seq 100); do
  [ -e "$sim/.rsi-lock" ] && [ -s "$sim/.rsi-lock" ] && break
  sleep 0.05
done
during=$(listing "$sim")
"$rsi" simulate "$work/contact.json" --method cb --modes 10 --out "$sim" >"$work/log" 2>"$work/err"
status=$?
message=$(cat "$work/err")
expected="rsi: error: --out $sim: another rsi run (pid $first) is writing it"
wait "$first"
first_status=$?
if [ "$status" -ne 2 ] || [ "$message" != "$expected" ]; then
  fail "second run: exit $status, stderr '$message'; expected 2, '$expected'"
elif [ "$(listing "$sim")" = "$during" ]; then
  fail "second run: listing unchanged after the first finished (the first did not publish?)"
elif [ "$first_status" -ne 0 ] || ! grep -q '"completed": true' "$sim/summary.json" ||
  ! grep -q '"steps": 200000' "$sim/summary.json"; then
  fail "first run: exit $first_status or its summary.json is not in --out: $(cat "$work/err1")"
else
  echo "ok   concurrent run: '$message' (exit 2); the first completed (exit 0) and published"
fi
clean "$sim"

# 6. Stale remains of a killed run (a lock file no process holds, a
# staging folder): taken over and removed.
echo 999999 >"$sim/.rsi-lock"
mkdir -p "$sim/.rsi-stage-999999" && echo x >"$sim/.rsi-stage-999999/history.csv"
if "$rsi" simulate "$work/free.json" --method full --out "$sim" >"$work/log" 2>&1; then
  echo "ok   a killed run's lock file and staging folder: taken over, removed"
else
  fail "after a killed run: $(tail -n 1 "$work/log")"
fi
clean "$sim"

# 7. A campaign without report after one with a report and other runs: no
# report.md, figure or runs/ folder of the first stays.
camp=$work/campaign
mkdir -p "$camp"
echo "my notes" >"$camp/notes.txt"
"$rsi" campaign "$work/contact.json" --jobs 2 --out "$camp" >"$work/log" 2>&1 ||
  fail "campaign with report: $(tail -n 2 "$work/log")"
[ -f "$camp/report.md" ] && [ -d "$camp/runs/cb-10" ] ||
  fail "campaign with report: no report.md or runs/cb-10: $(ls -A "$camp")"
"$rsi" campaign "$work/other.json" --jobs 2 --no-report --out "$camp" >"$work/log" 2>&1 ||
  fail "campaign --no-report: $(tail -n 2 "$work/log")"
left=$(cd "$camp" && ls -A | grep -v -x -e notes.txt -e runs -e convergence.csv -e modes-bladed-disk.csv)
if [ -n "$left" ]; then
  fail "campaign --no-report after one with report: the old files stay: $left"
elif [ "$(ls "$camp/runs" | tr '\n' ' ')" != "ccm-4 full-0 " ]; then
  fail "campaign --no-report: runs/ holds $(ls "$camp/runs" | tr '\n' ' '), expected ccm-4 full-0"
else
  echo "ok   campaign --no-report after a campaign with report: $(ls -A "$camp" | tr '\n' ' '), runs/ $(ls "$camp/runs" | tr '\n' ' ')"
fi
clean "$camp"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "every --out holds one run's output"
