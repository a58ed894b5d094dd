#!/usr/bin/env bash
# The paper's system in 3D, reduced against full (issue 27 item 4): the
# 6-sector bladed disk and the flexible casing of
# data/cases/bladed-disk3d-casing-ci.json with the casing at 270.9 mm
# (0.1 mm clearance at the least, so that the paper's load closes it within
# the window) over 0.015 revolution (7,185 full steps of 9.8e-9 s):
#  1. `rsi campaign` with rubbing.campaign = full over the window, then
#     CB-20 and MacNeal-20 (the 96 tip nodes physical; the rotor's two
#     integrators, mass-carrying and massless boundary: CCM-20 is CB's
#     integrator on another T, whose rows BladedDisk3dRows checks on this
#     disk, and its run is in reports/campaign-system3d-ci), the casing
#     in its 30 lowest modes plus the static correction for its load
#     (rubbing.casing.modes' default), each at its own stable step: every
#     run completed, in contact (max lambda > 0), the Coulomb certificate
#     at round-off (cone violation <= 64 eps x the largest normal force;
#     stick/slip residual <= 1e-12 scaled), the penetration left <= 64 eps
#     x 1 mm (the rounding of g = g~ + W lambda on gaps below 1 mm), the
#     energy balance within 1e-8 of the energy scale (the monitor's own
#     test, which would stop the run), casing_basis modal-30+s;
#  2. e_2 of the 96 tips' gap histories against the full run's (rows at
#     the same instants: every method samples at T/N), recomputed here from
#     runs/*/history.csv: equal to convergence.csv's e2_gap to its 10
#     significant digits (1e-9 relative) and
#     <= 0.05 (the issue's accuracy target for a reduced run); measured
#     0.0118 (CB), 0.0118 (MacNeal) when written;
#  3. nodal_diameters.csv: the disk's first family has the diameters of a
#     6-fold disk (0, 1, 1, 2, 2, 3); interaction_lines.csv: each speed
#     2 pi (f_b + f_c) / n of its modes' rows, n the casing mode's lobes
#     and f_b the disk's at k = n mod 6 folded to 0 .. 3 (the pattern 6
#     tips see), a line of family 1 for every lobe count of the casing's
#     modes but 0;
#  4. --casing-modes takes the place of rubbing.casing.modes (refused
#     naming --casing-modes at 100000, before any basis is built), is
#     refused for a rigid casing (exit 2); rubbing.casing.modes at the
#     casing's dofs or more is refused naming the key (exit 2).
# SANITIZED = 1 (an ASan/UBSan build): `rsi simulate --method cb` alone
# over 0.002 revolution with the casing at 270.6 mm (pressed: in contact
# from the first step) and the refusals, the checks of 1 (no full run).
# Skipped (exit 77) without gmsh or ccx.
# Usage: system3d_reduced_run.sh RSI SOURCE_DIR CCX_CACHE [SANITIZED]
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
near=$work/near.json
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$case" "$near" \
  rubbing.revolutions=0.015 rubbing.casing.gmsh_casing.inner_radius=270.9 \
  'rubbing.campaign={"runs": [{"method": "cb", "modes": [20]}, {"method": "macneal", "modes": [20]}], "full_revolutions": 0.015}' \
  >/dev/null
if [ "$sanitized" = 1 ]; then
  /usr/bin/python3 "$src/verification/cli/case_variant.py" "$near" "$near" \
    rubbing.revolutions=0.002 rubbing.campaign.full_revolutions=0.002 \
    rubbing.casing.gmsh_casing.inner_radius=270.6 >/dev/null
  mkdir -p "$work/c/runs"
  "$rsi" simulate "$near" --method cb --modes 20 --ccx-cache "$cache" --out "$work/c/runs/cb-20" \
    >"$work/run.log" 2>&1 || fail "cb: rsi simulate exited $?: $(tail -3 "$work/run.log")"
else
  "$rsi" campaign "$near" --no-report --ccx-cache "$cache" --out "$work/c" >"$work/run.log" 2>&1 ||
    fail "rsi campaign exited $?: $(tail -3 "$work/run.log")"
fi
cat "$work/run.log"

/usr/bin/python3 - "$work/c" "$sanitized" <<'PY' || failures=$((failures + 1))
import csv, json, math, os, sys
d, sanitized = sys.argv[1], sys.argv[2] == "1"
eps = 2.0 ** -52
names = ["cb-20"] if sanitized else ["full", "cb-20", "macneal-20"]
bad = []
for name in names:
    s = json.load(open(f"{d}/runs/{name}/summary.json"))
    mine = []
    if s["status"] != "completed" or s["steps"] != s["steps_requested"]:
        mine.append(f"status {s['status']}, {s['steps']} of {s['steps_requested']} steps")
    if not s["max_lambda"] > 0.0:
        mine.append("no contact force")
    if s["max_cone_violation"] > 64 * eps * s["max_lambda"]:
        mine.append(f"cone violation {s['max_cone_violation']:.3e} > 64 eps x {s['max_lambda']:.3e}")
    if s["max_stick_slip_residual"] > 1e-12:
        mine.append(f"stick/slip residual {s['max_stick_slip_residual']:.3e} > 1e-12")
    if s["max_penetration"] > 64 * eps * 1.0:
        mine.append(f"penetration {s['max_penetration']:.3e} > 64 eps x 1 mm")
    if s["energy_balance_error"] > 1e-8 * s["energy_scale"]:
        mine.append(f"energy balance {s['energy_balance_error']:.3e} > 1e-8 x {s['energy_scale']:.3e}")
    # The casing load's work in the history's last row is the run's W_ext (a
    # reduced run's rows wrote 0 until session 31): the same double, the
    # csv's 17 digits, and > 0 (p0 cos 2 theta pushes the casing inward).
    with open(f"{d}/runs/{name}/history.csv") as f:
        last = list(csv.DictReader(f))[-1]
    w_ext = float(last["external_work"])
    if not (w_ext > 0.0 and w_ext == s["final_external_work"]):
        mine.append(f"history's external_work {w_ext!r} against the summary's "
                    f"{s['final_external_work']!r}")
    expected = "full" if name == "full" else "modal-30+s"
    if s.get("casing_basis") != expected:
        mine.append(f"casing basis {s.get('casing_basis')}, expected {expected}")
    bad += [f"{name}: {m}" for m in mine]
    if not mine:
        print(f"ok   {name}: {s['steps']} steps of {s['dt']:.3e} s, {s['dofs']} coordinates, "
              f"max lambda {s['max_lambda']:.3e} N, penetration {s['max_penetration']:.1e} mm, "
              f"cone {s['max_cone_violation']:.1e}, balance {s['energy_balance_error']:.1e} of "
              f"{s['energy_scale']:.1e}")
if not sanitized:
    def gaps(name):
        with open(f"{d}/runs/{name}/history.csv") as f:
            rows = list(csv.DictReader(f))
        keys = [k for k in rows[0] if k.startswith("gap_")]
        return [float(r["t"]) for r in rows], [[float(r[k]) for k in keys] for r in rows]
    with open(f"{d}/convergence.csv") as f:
        table = {f"{r['method']}-{r['modes']}": r for r in csv.DictReader(f)}
    t_full, full = gaps("full")
    for name in names[1:]:
        t, reduced = gaps(name)
        if len(t) != len(t_full) or max(abs(a - b) for a, b in zip(t, t_full)) > 1e-12:
            bad.append(f"{name}: its {len(t)} rows are not at the full run's {len(t_full)} instants")
            continue
        pairs = [(a, b) for ra, rb in zip(reduced, full) for a, b in zip(ra, rb)]
        e2 = math.sqrt(sum((a - b) ** 2 for a, b in pairs) / sum(b * b for _, b in pairs))
        einf = max(abs(a - b) for a, b in pairs) / max(abs(b) for _, b in pairs)
        listed = float(table[name]["e2_gap"])
        line = (f"{name} against full: gap e_2 {e2:.4f} (<= 0.05; convergence.csv {listed:.4f}), "
                f"e_inf {einf:.4f}, {len(t)} rows x {len(full[0])} tips")
        # convergence.csv's 10 significant digits: 1e-9 relative.
        if not (e2 <= 0.05 and abs(listed - e2) <= 1e-9 * e2):
            bad.append(line)
        else:
            print("ok  ", line)
    # The nodal-diameter map: the disk's first family holds the diameters of
    # ccx's cyclic symmetry of a 6-fold disk, 0 once, 1 and 2 twice, 3 once
    # (test_gmsh_bladed_disk); each line's speed is 2 pi (f_b + f_c) / n of
    # its row (csv's 17 digits: 1e-15), f_c the casing mode's of n lobes,
    # f_b the first frequency of the disk at k, the n-lobed pattern at the
    # 6 tips: k = n mod 6, folded (k and 6 - k are one pattern).
    with open(f"{d}/nodal_diameters.csv") as f:
        modes = list(csv.DictReader(f))
    disk = [(float(r["frequency_hz"]), int(r["nodal_diameter"])) for r in modes
            if r["part"] == "bladed-disk"]
    casing = [(float(r["frequency_hz"]), int(r["nodal_diameter"])) for r in modes
              if r["part"] == "casing"]
    first = [n for _, n in disk[:6]]
    if sorted(first) != [0, 1, 1, 2, 2, 3]:
        bad.append(f"the disk's first family has diameters {first}, not 0, 1, 1, 2, 2, 3")
    with open(f"{d}/interaction_lines.csv") as f:
        lines = list(csv.DictReader(f))
    wrong = 0
    for l in lines:
        k, n = int(l["nodal_diameter"]), int(l["casing_lobes"])
        fb, fc = float(l["blade_hz"]), float(l["casing_hz"])
        w = float(l["speed_rad_s"])
        if k != min(n % 6, 6 - n % 6):
            wrong += 1
        if abs(w - 2 * math.pi * (fb + fc) / n) > 1e-15 * w * 4:
            wrong += 1
        if l["family"] == "1" and fb != min(f for f, m in disk if m == k):
            wrong += 1
        if casing[int(l["casing_mode"]) - 1] != (fc, n):
            wrong += 1
    ns = sorted({int(l["casing_lobes"]) for l in lines if l["family"] == "1"})
    lobes = sorted({m for _, m in casing if m > 0})
    if wrong or ns != lobes:
        bad.append(f"interaction lines: {wrong} rows off their modes, family 1 at n = {ns}, "
                   f"the casing's lobes {lobes}")
    else:
        low = min(lines, key=lambda l: float(l["speed_rad_s"]))
        print(f"ok   nodal diameters: first family {first}; {len(lines)} interaction lines, "
              f"family 1 at n = {ns[0]} .. {ns[-1]} lobes, the lowest "
              f"{float(low['speed_rad_s']):.1f} rad/s (k = {low['nodal_diameter']}, n = "
              f"{low['casing_lobes']})")
for b in bad:
    print("FAIL", b)
sys.exit(1 if bad else 0)
PY

# --casing-modes in place of the case's key, and the refusals.
"$rsi" simulate "$near" --method cb --modes 4 --casing-modes 100000 --ccx-cache "$cache" \
  --out "$work/override" >"$work/override.log" 2>&1
status=$?
if [ "$status" -ne 2 ] || ! grep -q -- "--casing-modes" "$work/override.log"; then
  fail "--casing-modes 100000: exit $status, expected 2 naming it: $(cat "$work/override.log")"
else
  echo "ok   --casing-modes 100000 refused: $(grep -m1 -- '--casing-modes' "$work/override.log")"
fi
"$rsi" simulate "$src/data/cases/blade3d-rubbing.json" --method cb --modes 4 --casing-modes 12 \
  --ccx-cache "$cache" --out "$work/rigid" >"$work/rigid.log" 2>&1
status=$?
if [ "$status" -ne 2 ] || ! grep -q "casing-modes" "$work/rigid.log"; then
  fail "--casing-modes on a rigid casing: exit $status, expected 2: $(cat "$work/rigid.log")"
else
  echo "ok   --casing-modes refused on a rigid casing: $(grep -m1 'casing-modes' "$work/rigid.log")"
fi
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$near" "$work/many.json" \
  rubbing.casing.modes=100000 >/dev/null
"$rsi" simulate "$work/many.json" --method cb --modes 4 --ccx-cache "$cache" --out "$work/many" \
  >"$work/many.log" 2>&1
status=$?
if [ "$status" -ne 2 ] || ! grep -q "rubbing.casing.modes" "$work/many.log"; then
  fail "rubbing.casing.modes 100000: exit $status, expected 2 naming it: $(cat "$work/many.log")"
else
  echo "ok   rubbing.casing.modes 100000 refused: $(grep -m1 'rubbing.casing.modes' "$work/many.log")"
fi
[ -e "$work/many" ] && fail "the refused run left $work/many"

[ "$failures" -eq 0 ] || { echo "system3d_reduced_run: $failures failure(s)"; exit 1; }
echo "system3d_reduced_run: all checks passed"
