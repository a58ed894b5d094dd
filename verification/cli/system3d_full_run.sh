#!/usr/bin/env bash
# The paper's system in 3D, full order (issue 27 items 3-4): the 6-sector
# bladed disk and the flexible casing of data/cases/bladed-disk3d-casing-ci.json
# (51,231 dofs, 96 tip nodes, the casing's inner face 0.01 mm inside the
# first tip at rest: a pressed start, no forcing yet), `rsi simulate
# --method full` over 0.002 revolution (958 steps of 9.8e-9 s). Checked:
#  - the run completed (the monitor's energy balance, 1e-8 of the energy
#    scale, and its Coulomb solves each step), the contact reached at the
#    first step (tip 1 starts pressed: the first row's gap_1 < 0);
#  - the Coulomb certificate at round-off, as blade3d_rubbing.sh: cone
#    violation <= 64 eps x the largest normal force, stick/slip residual
#    <= 1e-12 (scaled);
#  - no penetration left: max over steps and tips of -g <= 64 eps x 0.6 mm
#    (the largest predicted gap |g~| the solve corrects, in the rounding of
#    g = g~ + W lambda);
#  - the reduced methods refused (exit 2, naming rubbing.casing: the
#    reduced solver's law against the flexible casing is not written yet),
#    a case with both rubbing.gap and rubbing.casing (exit 2, naming
#    rubbing.gap), and a campaign's reduced runs and a sweep (exit 2,
#    naming rubbing.campaign and sweep).
# Skipped (exit 77) without gmsh or ccx.
# Usage: system3d_full_run.sh RSI SOURCE_DIR CCX_CACHE
set -u
rsi=$1
src=$2
cache=$3
. "$(dirname "$0")/skip_without_gmsh_ccx.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

case=$src/data/cases/bladed-disk3d-casing-ci.json
# The case names no file (gmsh builds both decks): its variants live in $work.
short=$work/short.json
bad=$work/bad.json
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$case" "$short" rubbing.revolutions=0.002 >/dev/null
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$case" "$bad" 'rubbing.gap={"constant": 0.1}' >/dev/null

"$rsi" simulate "$short" --method full --ccx-cache "$cache" --out "$work/full" >"$work/full.log" 2>&1 ||
  fail "rsi simulate --method full exited $?: $(tail -3 "$work/full.log")"
cat "$work/full.log"
/usr/bin/python3 - "$work/full" <<'PY' || failures=$((failures + 1))
import csv, json, sys
d = sys.argv[1]
s = json.load(open(d + "/summary.json"))
eps = 2.0 ** -52
bad = []
if s["status"] != "completed" or s["steps"] != s["steps_requested"]:
    bad.append(f"status {s['status']}, {s['steps']} of {s['steps_requested']} steps")
if s["first_contact_step"] != 1:
    bad.append(f"first contact at step {s['first_contact_step']}, expected 1 (tip 1 pressed)")
if not s["max_lambda"] > 0.0:
    bad.append("no contact force")
if s["max_cone_violation"] > 64 * eps * s["max_lambda"]:
    bad.append(f"cone violation {s['max_cone_violation']:.3e} > 64 eps x {s['max_lambda']:.3e}")
if s["max_stick_slip_residual"] > 1e-12:
    bad.append(f"stick/slip residual {s['max_stick_slip_residual']:.3e} > 1e-12")
if s["max_penetration"] > 64 * eps * 0.6:
    bad.append(f"penetration {s['max_penetration']:.3e} > 64 eps x 0.6 mm")
if s["energy_balance_error"] > 1e-8:
    bad.append(f"energy balance {s['energy_balance_error']:.3e} > 1e-8")
with open(d + "/history.csv") as f:
    rows = list(csv.DictReader(f))
if not float(rows[0]["gap_1"]) < 0.0:
    bad.append(f"the first row's gap_1 = {rows[0]['gap_1']}, expected < 0 (pressed)")
for b in bad:
    print("FAIL", b)
if not bad:
    print(f"ok   full run: {s['steps']} steps, {s['dofs']} dofs, max lambda {s['max_lambda']:.3e} N, "
          f"penetration {s['max_penetration']:.1e} mm, balance {s['energy_balance_error']:.1e}, "
          f"cone {s['max_cone_violation']:.1e}, stick/slip {s['max_stick_slip_residual']:.1e}")
sys.exit(1 if bad else 0)
PY

"$rsi" simulate "$short" --method cb --modes 10 --ccx-cache "$cache" --out "$work/cb" >"$work/cb.log" 2>&1
status=$?
if [ "$status" -ne 2 ] || ! grep -q "rubbing.casing" "$work/cb.log"; then
  fail "--method cb: exit $status, expected 2 naming rubbing.casing: $(cat "$work/cb.log")"
else
  echo "ok   --method cb refused: $(grep -m1 'rubbing.casing' "$work/cb.log")"
fi
[ -e "$work/cb" ] && fail "--method cb left $work/cb"

"$rsi" simulate "$bad" --method full --ccx-cache "$cache" --out "$work/bad" >"$work/bad.log" 2>&1
status=$?
if [ "$status" -ne 2 ] || ! grep -q "rubbing.gap" "$work/bad.log"; then
  fail "rubbing.gap with rubbing.casing: exit $status, expected 2 naming rubbing.gap: $(cat "$work/bad.log")"
else
  echo "ok   rubbing.gap with rubbing.casing refused: $(grep -m1 'rubbing.gap' "$work/bad.log")"
fi

# A campaign's reduced runs and a sweep: refused when the case is read.
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$case" "$work/campaign.json" \
  'rubbing.campaign={"runs": [{"method": "cb", "modes": [10]}]}' >/dev/null
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$case" "$work/sweep.json" \
  'sweep={"speeds": [1000, 1100]}' >/dev/null
for refused in "campaign rubbing.campaign" "sweep sweep"; do
  set -- $refused
  "$rsi" "$1" "$work/$1.json" --ccx-cache "$cache" --out "$work/$1-out" >"$work/$1.log" 2>&1
  status=$?
  if [ "$status" -ne 2 ] || ! grep -q "key '$2'" "$work/$1.log"; then
    fail "rsi $1 with rubbing.casing: exit $status, expected 2 naming $2: $(cat "$work/$1.log")"
  else
    echo "ok   rsi $1 refused: $(grep -m1 "key '$2'" "$work/$1.log")"
  fi
done

[ "$failures" -eq 0 ] || { echo "system3d_full_run: $failures failure(s)"; exit 1; }
echo "system3d_full_run: all checks passed"
