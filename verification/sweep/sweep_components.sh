#!/usr/bin/env bash
# rsi sweep on a component case: the project's gmsh blade rubbing on the
# oval rigid casing (data/cases/blade3d-rubbing.json), MacNeal-10 and -20,
# 4 speeds x 1 revolution. Checked:
# - sweep.csv and interaction_lines.csv the same bytes with --jobs 1, --jobs
#   2, and under mpirun -n 2 (a row depends only on its speed and
#   run); one row per (speed, run) in order; the report's files written;
# - a failed speed (RSI_SWEEP_FAIL_SPEED) is 2 failed rows, the others the
#   same bytes, exit 3;
# - bad input (a speed 0, a change of sign, an empty or descending range, a
#   method or option a component case does not take, a missing sweep, a
#   transient leaving too few rows): exit 2, the message names the option or
#   key, --out left as it was;
# - the indicators against their definitions: a gap that never closes
#   (constant, 50 mm) leaves the blade at rest from rest, so contact fraction
#   0, contact force 0, tip displacement 0 (the free response from rest with
#   no force is 0) and the energy ratio undefined (empty); and on a constant
#   interference (-0.02 mm, contacts closing) every indicator of one speed
#   recomputed by a few lines of Python from the history.csv of `rsi
#   simulate` at that speed (the same run) equals sweep.csv's row.
# Skipped (exit 77) without gmsh or ccx; the MPI part needs mpirun (without
# it the other checks run and the test reports skipped, saying so).
# Usage: sweep_components.sh RSI SOURCE_DIR [CCX_CACHE]
set -u
rsi=$1
src=$2
. "$(dirname "$0")/../cli/skip_without_gmsh_ccx.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cache=${3:-$work/ccx}
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

/usr/bin/python3 - "$src/data/cases/blade3d-rubbing.json" "$work" <<'PY'
import copy, json, sys
c = json.load(open(sys.argv[1]))
out = sys.argv[2]
c.pop("sweep", None)
c["rubbing"].pop("campaign", None)
json.dump(c, open(out + "/nosweep.json", "w"))
c["sweep"] = {"speeds": {"from": 1000, "to": 1600, "count": 4}, "revolutions": 1,
              "transient_revolutions": 0.25,
              "runs": [{"method": "macneal", "modes": [10, 20]}]}
json.dump(c, open(out + "/case.json", "w"))
def variant(name, change):
    v = copy.deepcopy(c)
    change(v)
    json.dump(v, open(out + "/" + name + ".json", "w"))
variant("zero", lambda v: v["sweep"].update(speeds=[0, 1000]))
variant("signs", lambda v: v["sweep"].update(speeds=[-1000, 1000]))
variant("range_signs", lambda v: v["sweep"].update(speeds={"from": -1000, "to": 1000, "count": 3}))
variant("empty", lambda v: v["sweep"].update(speeds=[]))
variant("lanczos", lambda v: v["sweep"].update(runs=[{"method": "lanczos", "modes": [10]}]))
variant("late", lambda v: v["sweep"].update(transient_revolutions=0.99))  # 10 rows after it
def open_gap(v):
    v["rubbing"]["gap"] = {"constant": 50.0}
    v["sweep"].update(speeds=[1000, 1344], runs=[{"method": "macneal", "modes": [10]}])
variant("open", open_gap)
def interference(v):
    v["rubbing"]["gap"] = {"constant": -0.02}
    v["sweep"].update(speeds=[1000, 1200], runs=[{"method": "macneal", "modes": [10]}])
variant("interference", interference)
# The same case as a single run at 1200 rad/s, for rsi simulate.
v = copy.deepcopy(c)
v.pop("sweep")
v["rubbing"]["gap"] = {"constant": -0.02}
v["rubbing"]["rotation_speed"] = 1200.0
json.dump(v, open(out + "/single.json", "w"))
PY

sweep() { "$rsi" sweep "$@" --quiet --ccx-cache "$cache"; }
sweep "$work/case.json" --jobs 1 --out "$work/one" >"$work/log1" 2>&1
status=$?
[ "$status" -eq 0 ] || { fail "--jobs 1 exited $status"; cat "$work/log1"; }
sweep "$work/case.json" --jobs 2 --no-report --out "$work/two" >"$work/log2" 2>&1
status=$?
[ "$status" -eq 0 ] || { fail "--jobs 2 exited $status"; cat "$work/log2"; }
for f in sweep.csv interaction_lines.csv; do
  cmp -s "$work/one/$f" "$work/two/$f" || fail "$f differs between --jobs 1 and --jobs 2"
done
rows=$(($(wc -l <"$work/one/sweep.csv") - 1))
[ "$rows" -eq 8 ] || fail "sweep.csv has $rows rows, 8 expected (4 speeds x 2 runs)"
order=$(tail -n +2 "$work/one/sweep.csv" | cut -d, -f1,2 | tr '\n' ' ')
[ "$order" = "1000,macneal-10 1000,macneal-20 1200,macneal-10 1200,macneal-20 1400,macneal-10 1400,macneal-20 1600,macneal-10 1600,macneal-20 " ] ||
  fail "rows not in (speed, run) order: $order"
[ "$(grep -c ',completed,' "$work/one/sweep.csv")" -eq 8 ] || fail "not every run completed"
# 2 runs x 5 natural frequencies x engine orders 1..10, and the header.
[ "$(wc -l <"$work/one/interaction_lines.csv")" -eq 101 ] ||
  fail "interaction_lines.csv: $(wc -l <"$work/one/interaction_lines.csv") lines, 101 expected"
for f in sweep_report.md sweep_map.png sweep_campbell.png sweep_summary.json; do
  [ -s "$work/one/$f" ] || fail "$f missing after a sweep with its report"
done
[ -e "$work/two/sweep_report.md" ] && fail "--no-report wrote sweep_report.md"

# A failed speed: its 2 rows failed, the others the same bytes, exit 3.
RSI_SWEEP_FAIL_SPEED=1 sweep "$work/case.json" --no-report --out "$work/failed" >"$work/log3" 2>&1
status=$?
[ "$status" -eq 3 ] || fail "a failed speed exited $status, 3 expected"
[ "$(grep -c ',failed,' "$work/failed/sweep.csv")" -eq 2 ] || fail "not 2 failed rows"
diff <(grep -v '^1200,' "$work/one/sweep.csv") <(grep -v '^1200,' "$work/failed/sweep.csv") >/dev/null ||
  fail "the rows of the other speeds changed when speed 1200 failed"
grep -q '"speed 1200 rad/s, run macneal-10' "$work/failed/sweep_summary.json" ||
  fail "sweep_summary.json does not name the failed speed"

# Bad input: exit 2, the option or key named, --out untouched.
mkdir -p "$work/keep" && echo mine >"$work/keep/notes.txt"
expect2() { # DESCRIPTION WORD-THE-MESSAGE-NAMES ARGS...
  local what=$1 names=$2
  shift 2
  "$rsi" sweep "$@" --quiet --no-report --ccx-cache "$cache" --out "$work/keep" >"$work/log" 2>&1
  local s=$?
  [ "$s" -eq 2 ] || fail "$what: exit $s, 2 expected"
  grep -q "^rsi: error: .*$names" "$work/log" || { fail "$what: no rsi: error line naming $names"; cat "$work/log"; }
  [ "$(ls -A "$work/keep")" = "notes.txt" ] || fail "$what: --out changed: $(ls -A "$work/keep")"
}
expect2 "--speeds with 0" "--speeds" "$work/case.json" --speeds 0,1000
expect2 "--speeds changing sign" "--speeds" "$work/case.json" --speeds=-1000,1000
expect2 "--speeds range through 0" "--speeds" "$work/case.json" --speeds=-1000:1000:3
expect2 "--speeds descending" "--speeds" "$work/case.json" --speeds 1600:1000:3
expect2 "--speeds empty" "--speeds" "$work/case.json" --speeds ""
expect2 "--speeds count 0" "--speeds" "$work/case.json" --speeds 1000:1600:0
expect2 "sweep.speeds with 0" "sweep.speeds" "$work/zero.json"
expect2 "sweep.speeds changing sign" "sweep.speeds" "$work/signs.json"
expect2 "sweep.speeds range through 0" "sweep.speeds" "$work/range_signs.json"
expect2 "sweep.speeds empty" "sweep.speeds" "$work/empty.json"
expect2 "sweep.runs method lanczos" "sweep.runs\[0\].method" "$work/lanczos.json"
expect2 "--method not a method" "--method" "$work/case.json" --method lanczos
expect2 "--method macneal without --modes" "--modes" "$work/case.json" --method macneal
expect2 "--time-step on a component" "--time-step" "$work/case.json" --method macneal --modes 10 --time-step own
expect2 "--casing-modes on a component" "--casing-modes" "$work/case.json" --method macneal --modes 10 --casing-modes 4
expect2 "macneal with more modes than the blade has" "--modes" "$work/case.json" --method macneal --modes 100000
expect2 "no sweep object" "sweep" "$work/nosweep.json"
expect2 "transient leaving too few rows" "sweep.transient_revolutions" "$work/late.json"

# A gap that never closes: at rest from rest.
sweep "$work/open.json" --no-report --out "$work/open" >"$work/log4" 2>&1 || { fail "open gap exited $?"; cat "$work/log4"; }
/usr/bin/python3 - "$work/open/sweep.csv" <<'PY' || fail "open gap indicators"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
bad = 0
for r in rows:
    # No contact closes (gap 50 mm against tip displacements of 0): nothing moves.
    print(f"open gap {r['speed_rad_s']} rad/s: contact_fraction {r['contact_fraction']}, "
          f"max_contact_force {r['max_contact_force']}, max_tip_radial {r['max_tip_radial']}, "
          f"energy_ratio '{r['energy_ratio']}'")
    if not (float(r["contact_fraction"]) == 0.0 and float(r["max_contact_force"]) == 0.0
            and float(r["max_tip_radial"]) == 0.0 and r["energy_ratio"] == ""):
        bad += 1
sys.exit(1 if bad or len(rows) != 2 else 0)
PY

# Every indicator of one speed from the history of the same run.
sweep "$work/interference.json" --no-report --out "$work/inter" >"$work/log5" 2>&1 ||
  { fail "interference sweep exited $?"; cat "$work/log5"; }
"$rsi" simulate "$work/single.json" --method macneal --modes 10 --ccx-cache "$cache" \
  --out "$work/single" >"$work/log6" 2>&1 || { fail "simulate exited $?"; cat "$work/log6"; }
/usr/bin/python3 - "$work/single.json" "$work/case.json" "$work/oval.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
c["rubbing"]["gap"] = json.load(open(sys.argv[2]))["rubbing"]["gap"]
json.dump(c, open(sys.argv[3], "w"))
PY
"$rsi" simulate "$work/oval.json" --method macneal --modes 10 --ccx-cache "$cache" \
  --out "$work/single_oval" >"$work/log7" 2>&1 || { fail "simulate (oval) exited $?"; cat "$work/log7"; }
# CSV ROW_RUN HISTORY SUMMARY G0 (g0 of a constant gap; "oval": the tip
# displacement is not recomputed, its g0 needing the nodes' angles): the
# row at 1200 rad/s (1000 samples a revolution, every one, 0.25 revolution
# of transient) recomputed by sweep_row_from_history.py.
check_row() {
  /usr/bin/python3 "$(dirname "$0")/sweep_row_from_history.py" "$1" 1200 "$2" "$3" "$4" 1000 1 0.25 \
    u_11_2 "$5"
}
check_row "$work/inter/sweep.csv" macneal-10 "$work/single/history.csv" "$work/single/summary.json" -0.02 ||
  fail "indicators recomputed from history.csv differ from sweep.csv's row (constant interference)"
check_row "$work/one/sweep.csv" macneal-10 "$work/single_oval/history.csv" "$work/single_oval/summary.json" oval ||
  fail "indicators recomputed from history.csv differ from sweep.csv's row (oval casing)"

if ! command -v mpirun >/dev/null; then
  echo "MPI part skipped: no mpirun on PATH (Debian openmpi-bin); the other checks ran ($failures failed)"
  [ "$failures" -eq 0 ] && exit 77
  exit 1
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0
for n in 2; do
  mpirun --oversubscribe -n $n "$rsi" sweep "$work/case.json" --quiet --no-report --ccx-cache "$cache" \
    --out "$work/mpi$n" >"$work/logm$n" 2>&1
  status=$?
  [ "$status" -eq 0 ] || { fail "mpirun -n $n exited $status"; tail -20 "$work/logm$n"; }
  for f in sweep.csv interaction_lines.csv; do
    cmp -s "$work/one/$f" "$work/mpi$n/$f" || fail "$f differs between 1 process and $n ranks"
  done
  grep -q "\"ranks\": $n" "$work/mpi$n/sweep_summary.json" || fail "the summary does not say $n ranks"
done

[ "$failures" -eq 0 ] && echo "sweep_components: all checks passed (8 rows; jobs 1 = jobs 2 = 2 ranks byte for byte; failed speed exit 3; 18 bad inputs exit 2; open gap at rest; indicators = their definitions on history.csv)"
[ "$failures" -eq 0 ]
