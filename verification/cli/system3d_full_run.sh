#!/usr/bin/env bash
# The paper's system in 3D, full order (issue 27 items 2-4): the 6-sector
# bladed disk and the flexible casing of data/cases/bladed-disk3d-casing-ci.json
# (51,261 dofs, 96 tip nodes, 1.26 mm clearance at the least, the paper's
# two-diameter load on the casing), `rsi simulate --method full`:
#  1. a pressed start (the casing at 270.6 mm, 0.01 mm inside tip 1 at
#     rest; no forcing) over 0.002 revolution (958 steps of 9.8e-9 s):
#     completed, the contact reached at the first step (the first row's
#     gap_1 < 0); the Coulomb certificate at round-off, as
#     blade3d_rubbing.sh: cone violation <= 64 eps x the largest normal
#     force, stick/slip residual <= 1e-12 (scaled); no penetration left:
#     max -g <= 64 eps x 0.6 mm (the largest predicted gap the solve
#     corrects, in the rounding of g = g~ + W lambda);
#  2. the case's forced start over its first 0.005 revolution (2,395 steps,
#     2.3e-5 s of the 2e-4 s load): completed,
#     W_ext > 0 (the load works on the casing), the least gap smaller at the
#     end than at rest (the inward lobes come in), no contact yet;
#  in both the energy balance |E - W_ext - W_contact| <= 1e-8 of the
#  energy scale (the monitor's own test, which would stop the run);
#  3. a case with both rubbing.gap and rubbing.casing refused (exit 2,
#     naming rubbing.gap). The reduced runs and the campaign:
#     system3d_reduced_run.sh; the sweep: sweep/sweep_system3d.sh.
# SANITIZED = 1 (an ASan/UBSan build): 0.0005 and 0.001 revolution (240
# and 479 steps), the same checks on the same code.
# Skipped (exit 77) without gmsh or ccx.
# Usage: system3d_full_run.sh RSI SOURCE_DIR CCX_CACHE [SANITIZED]
set -u
rsi=$1
src=$2
cache=$3
sanitized=${4:-0}
. "$(dirname "$0")/skip_without_gmsh_ccx.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

case=$src/data/cases/bladed-disk3d-casing-ci.json
# The case names no file (gmsh builds both decks): its variants live in $work.
pressed=$work/pressed.json
forced=$work/forced.json
bad=$work/bad.json
pressed_revolutions=0.002
forced_revolutions=0.005
if [ "$sanitized" = 1 ]; then
  pressed_revolutions=0.0005
  forced_revolutions=0.001
fi
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$case" "$pressed" \
  rubbing.revolutions=$pressed_revolutions rubbing.campaign.full_revolutions=0 \
  'rubbing.casing={"gmsh_casing": {"inner_radius": 270.6, "thickness": 5.0, "width": 60.0, "element_size": 15.0, "clamped_flanges": 1}}' >/dev/null
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$case" "$forced" \
  rubbing.revolutions=$forced_revolutions rubbing.campaign.full_revolutions=0 >/dev/null
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$case" "$bad" 'rubbing.gap={"constant": 0.1}' >/dev/null

for run in pressed forced; do
  "$rsi" simulate "$work/$run.json" --method full --ccx-cache "$cache" --out "$work/$run" \
    >"$work/$run.log" 2>&1 || fail "$run: rsi simulate --method full exited $?: $(tail -3 "$work/$run.log")"
  cat "$work/$run.log"
  /usr/bin/python3 - "$work/$run" "$run" <<'PY' || failures=$((failures + 1))
import csv, json, sys
d, run = sys.argv[1], sys.argv[2]
s = json.load(open(d + "/summary.json"))
eps = 2.0 ** -52
bad = []
if s["status"] != "completed" or s["steps"] != s["steps_requested"]:
    bad.append(f"status {s['status']}, {s['steps']} of {s['steps_requested']} steps")
if s["energy_balance_error"] > 1e-8 * s["energy_scale"]:
    bad.append(f"energy balance {s['energy_balance_error']:.3e} > 1e-8 x {s['energy_scale']:.3e}")
with open(d + "/history.csv") as f:
    rows = list(csv.DictReader(f))
gaps = [k for k in rows[0] if k.startswith("gap_")]
if run == "pressed":
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
    if not float(rows[0]["gap_1"]) < 0.0:
        bad.append(f"the first row's gap_1 = {rows[0]['gap_1']}, expected < 0 (pressed)")
else:
    first = min(float(rows[0][k]) for k in gaps)
    last = min(float(rows[-1][k]) for k in gaps)
    if not s["final_external_work"] > 0.0:
        bad.append(f"W_ext = {s['final_external_work']:.3e}, expected > 0 (the load on the casing)")
    if not last < first:
        bad.append(f"the least gap {last:.6f} mm at the end, not below {first:.6f} at rest")
    if s["max_lambda"] != 0.0:
        bad.append(f"contact within the first {len(rows)} samples (max lambda {s['max_lambda']:.3e})")
for b in bad:
    print("FAIL", run + ":", b)
if not bad:
    print(f"ok   {run}: {s['steps']} steps, {s['dofs']} dofs, max lambda {s['max_lambda']:.3e} N, "
          f"W_ext {s['final_external_work']:.3e}, penetration {s['max_penetration']:.1e} mm, "
          f"balance {s['energy_balance_error']:.1e} of {s['energy_scale']:.1e}, "
          f"least gap {min(float(rows[0][k]) for k in gaps):.4f} -> {min(float(rows[-1][k]) for k in gaps):.4f} mm")
sys.exit(1 if bad else 0)
PY
done

"$rsi" simulate "$bad" --method full --ccx-cache "$cache" --out "$work/bad" >"$work/bad.log" 2>&1
status=$?
if [ "$status" -ne 2 ] || ! grep -q "rubbing.gap" "$work/bad.log"; then
  fail "rubbing.gap with rubbing.casing: exit $status, expected 2 naming rubbing.gap: $(cat "$work/bad.log")"
else
  echo "ok   rubbing.gap with rubbing.casing refused: $(grep -m1 'rubbing.gap' "$work/bad.log")"
fi

[ "$failures" -eq 0 ] || { echo "system3d_full_run: $failures failure(s)"; exit 1; }
echo "system3d_full_run: all checks passed"
