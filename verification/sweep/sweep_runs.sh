#!/usr/bin/env bash
# Issue 15: rsi sweep end to end on a small sweep of the paper's case
# (3 speeds x (full, CB-10 at its own step), 10 ms a run, damped).
# Checked: one row per (speed, run) in order, sweep.csv the same bytes with
# --jobs 1 and --jobs 2 (a row depends only on its speed and run); a failed
# speed (RSI_SWEEP_FAIL_SPEED, the test hook) is a "failed" row, the other
# rows are the same bytes as without it, the summary names the speed and
# the exit status is 3; bad input exits 2 and leaves --out as it was; the
# report script writes its report and figures. In the sanitizer build a
# run lasts 5 ms (transient 2 ms), past blade 1's first contact (3.96 ms at
# 310 rad/s, the case's note): the contact and friction code runs, the
# rows and the byte comparisons are checked as in Release.
# Usage: sweep_runs.sh RSI SOURCE_DIR [SANITIZED]
set -u
rsi=$1
src=$2
duration=0.01 transient=0.004
[ "${3:-0}" = 1 ] && duration=0.005 transient=0.002
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

/usr/bin/python3 - "$src/data/cases/batailly2007.json" "$work/case.json" "$work/nosweep.json" \
  "$duration" "$transient" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
c.pop("campaign", None)
c.pop("sweep", None)
json.dump(c, open(sys.argv[3], "w"))
c["sweep"] = {"speeds": {"from": 280, "to": 340, "count": 3}, "duration": float(sys.argv[4]),
              "transient": float(sys.argv[5]),
              "damping": {"rayleigh": {"alpha": 30, "beta": 0}, "projected_rayleigh": True},
              "runs": [{"method": "full"}, {"method": "cb", "modes": [10], "time_step": ["own"]}]}
json.dump(c, open(sys.argv[2], "w"))
PY

"$rsi" sweep "$work/case.json" --jobs 1 --quiet --out "$work/one" >"$work/log1" 2>&1
status=$?
[ "$status" -eq 0 ] || { fail "--jobs 1 exited $status"; cat "$work/log1"; }
"$rsi" sweep "$work/case.json" --jobs 2 --quiet --no-report --out "$work/two" >"$work/log2" 2>&1
status=$?
[ "$status" -eq 0 ] || { fail "--jobs 2 exited $status"; cat "$work/log2"; }
cmp -s "$work/one/sweep.csv" "$work/two/sweep.csv" || fail "sweep.csv differs between --jobs 1 and --jobs 2"
cmp -s "$work/one/interaction_lines.csv" "$work/two/interaction_lines.csv" ||
  fail "interaction_lines.csv differs between --jobs 1 and --jobs 2"
rows=$(($(wc -l <"$work/one/sweep.csv") - 1))
[ "$rows" -eq 6 ] || fail "sweep.csv has $rows rows, 6 expected (3 speeds x 2 runs)"
order=$(tail -n +2 "$work/one/sweep.csv" | cut -d, -f2 | tr '\n' ' ')
[ "$order" = "full cb-10-dt-own full cb-10-dt-own full cb-10-dt-own " ] ||
  fail "rows not in (speed, run) order: $order"
grep -q ",failed," "$work/one/sweep.csv" && fail "a run failed without a cause"
for f in sweep_report.md sweep_map.png sweep_campbell.png sweep_summary.json; do
  [ -s "$work/one/$f" ] || fail "$f missing after a sweep with its report"
done
[ -e "$work/two/sweep_report.md" ] && fail "--no-report wrote sweep_report.md"

# A failed speed: its rows failed, the others the same bytes, exit 3.
RSI_SWEEP_FAIL_SPEED=1 "$rsi" sweep "$work/case.json" --quiet --no-report --out "$work/failed" \
  >"$work/log3" 2>&1
status=$?
[ "$status" -eq 3 ] || fail "a failed speed exited $status, 3 expected"
grep -q "rsi: error: numerical failure: 2 run(s) of the sweep failed" "$work/log3" ||
  fail "no rsi: error line for the failed speed"
[ "$(grep -c ',failed,' "$work/failed/sweep.csv")" -eq 2 ] || fail "not 2 failed rows"
diff <(sed -n '1,3p;6,7p' "$work/one/sweep.csv") <(sed -n '1,3p;6,7p' "$work/failed/sweep.csv") >/dev/null ||
  fail "the rows of the other speeds changed when speed 2 failed"
grep -q '"speed 310 rad/s, run full' "$work/failed/sweep_summary.json" ||
  fail "sweep_summary.json does not name the failed speed"

# Bad input: exit 2, --out untouched.
mkdir -p "$work/keep" && echo mine >"$work/keep/notes.txt"
expect2() { # DESCRIPTION ARGS...
  local what=$1
  shift
  "$rsi" sweep "$@" --quiet --no-report --out "$work/keep" >"$work/log" 2>&1
  local s=$?
  [ "$s" -eq 2 ] || fail "$what: exit $s, 2 expected"
  grep -q "^rsi: error: " "$work/log" || fail "$what: no rsi: error line"
  [ "$(ls -A "$work/keep")" = "notes.txt" ] || fail "$what: --out changed: $(ls -A "$work/keep")"
}
expect2 "speeds descending" "$work/case.json" --speeds 340:280:3
expect2 "speeds not a number" "$work/case.json" --speeds 280,abc
expect2 "--modes without --method" "$work/case.json" --modes 10
expect2 "--casing-modes with --method full" "$work/case.json" --method full --casing-modes 10
expect2 "cb with more modes than interior dofs" "$work/case.json" --method cb --modes 700
expect2 "a case without sweep" "$work/nosweep.json"
/usr/bin/python3 - "$work/case.json" "$work/late.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
# 12 rows of 2.5e-5 s (output_every 50 of 5e-7 s) after it: fewer than the 16 the spectrum needs
c["sweep"]["transient"] = round(c["sweep"]["duration"] - 12 * 2.5e-5, 10)
json.dump(c, open(sys.argv[2], "w"))
PY
expect2 "transient leaving too few rows" "$work/late.json"
grep -q "at least 16" "$work/log" || fail "transient leaving too few rows: not the 16-row message: $(cat "$work/log")"

[ "$failures" -eq 0 ] && echo "sweep_runs: all checks passed (6 rows, jobs 1 = jobs 2, failed speed exit 3, 7 bad inputs exit 2)"
[ "$failures" -eq 0 ]
