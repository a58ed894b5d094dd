#!/usr/bin/env bash
# rsi sweep on the paper's system in 3D (issue 27 item 6): the 6-sector
# bladed disk against the flexible casing of
# data/cases/bladed-disk3d-casing-ci.json, MacNeal-20 (the casing in its 30
# modes plus static correction) and characteristic constraint modes CC
# 20 + 96 (cc-96: CB-20 with its 288 boundary dofs in their 96 lowest
# characteristic constraint modes), 2 speeds x 0.3 revolution, --jobs 2,
# indicators after 0.2 revolution (past the 2e-4 s load at both speeds).
# Checked:
# - exit 0; sweep.csv a row per speed and run, all completed, its column 8
#   max_abs_response (against a flexible casing the gap is the two
#   bodies': no tip radial displacement is read from it); the report's
#   files written (make_system_sweep_report.py);
# - nodal_diameters.csv and interaction_lines.csv: the rows rsi campaign
#   wrote for the same model (reports/campaign-system3d-ci, written at
#   2203c99), integers equal, frequencies and speeds to 1e-7 relative: the
#   campaign factored K on two BLAS threads, the sweep on one
#   (blas_threads.hpp), and a shift-invert operator perturbed by round-off
#   moves the eigenvalues by up to eps cond_2(K) = 2.2e-16 x 5.6e8 (the CI
#   disk's, BladedDisk3dRows) = 1.2e-7; a speed is a sum of two
#   frequencies over n, the same relative bound;
# - the cc-96 row at 6474 rad/s against `rsi simulate` of the same run (the
#   case at that speed, 0.3 revolution, --method cc --modes 20
#   --boundary-modes 96): rows, max |u_7020_1|, the largest
#   lambda_n, the contact fraction, the energy ratio and the balance
#   residual recomputed in Python from its history.csv and summary.json
#   equal to the last bit (the same doubles through the same operations;
#   the sweep's run shared its bases with the other speed's thread; the
#   simulation with OPENBLAS_NUM_THREADS=1, as rsi sweep sets its BLAS), the
#   spectral peaks to 1e-9 (numpy's FFT against GSL's, as sweep_components).
#   The macneal-20 row was checked so too until session 32: the same sweep
#   and simulate code with another basis, 35-50 s of the test's time.
# Release only (the sweep's MacNeal-20 basis of the 29,484-dof disk, about
# 35 s, and the two CC 20 + 96 bases, the sweep's and simulate's): the sweep's code runs under the sanitizers in sweep_rotating and
# the indicators' flexible-casing form in test_rubbing_indicators.
# Skipped (exit 77) without gmsh or ccx.
# Usage: sweep_system3d.sh RSI SOURCE_DIR CCX_CACHE
set -u
rsi=$1
src=$2
cache=$3
. "$(dirname "$0")/../cli/skip_without_gmsh_ccx.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

case=$src/data/cases/bladed-disk3d-casing-ci.json
/usr/bin/python3 - "$case" "$work" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
out = sys.argv[2]
c["rubbing"].pop("campaign", None)
single = json.loads(json.dumps(c))
c["sweep"] = {"speeds": [5000, 6474], "revolutions": 0.3, "transient_revolutions": 0.2,
              "runs": [{"method": "macneal", "modes": [20]},
                       {"method": "cc", "modes": [96], "fixed_interface_modes": 20}]}
json.dump(c, open(out + "/case.json", "w"))
single["rubbing"]["rotation_speed"] = 6474
single["rubbing"]["revolutions"] = 0.3
json.dump(single, open(out + "/single.json", "w"))
PY

"$rsi" sweep "$work/case.json" --jobs 2 --quiet --ccx-cache "$cache" --out "$work/out" \
  >"$work/sweep.log" 2>&1
status=$?
if [ "$status" -ne 0 ]; then
  fail "rsi sweep exited $status: $(tail -n 5 "$work/sweep.log")"
else
  missing=""
  for f in sweep.csv nodal_diameters.csv interaction_lines.csv sweep_summary.json sweep_map.png \
    nodal_diameter_map.png sweep_report.md; do
    [ -s "$work/out/$f" ] || missing="$missing $f"
  done
  [ -z "$missing" ] && echo "ok   the sweep's files written" || fail "missing:$missing"
fi

/usr/bin/python3 - "$work/out" "$src/reports/campaign-system3d-ci" <<'PY' || fail "sweep.csv or the map"
import csv, sys
out, campaign = sys.argv[1], sys.argv[2]
bad = 0
rows = list(csv.DictReader(open(out + "/sweep.csv")))
header = open(out + "/sweep.csv").readline().strip().split(",")
if header[7] != "max_abs_response" or "max_tip_radial" in header:
    print("FAIL column 8:", header[7]); bad += 1
expected = sorted((w, run, "completed") for w in ("5000", "6474") for run in ("macneal-20", "cc-96"))
if sorted((r["speed_rad_s"], r["run"], r["status"]) for r in rows) != expected or any(
        r["modes"] != ("96" if r["run"] == "cc-96" else "20") for r in rows):
    print("FAIL rows:", [(r["speed_rad_s"], r["run"], r["modes"], r["status"]) for r in rows]); bad += 1
else:
    print("ok   4 rows completed:", ", ".join(f"{r['speed_rad_s']} rad/s {r['run']} max |u| "
                                             f"{float(r['max_abs_response']):.4g} mm, "
                                             f"contact {float(r['contact_fraction']):.3f}" for r in rows))
for name, exact in (("nodal_diameters.csv", ("part", "index", "nodal_diameter")),
                    ("interaction_lines.csv", ("family", "nodal_diameter", "casing_lobes", "casing_mode"))):
    mine = list(csv.DictReader(open(f"{out}/{name}")))
    theirs = list(csv.DictReader(open(f"{campaign}/{name}")))
    worst = 0.0
    if len(mine) != len(theirs) or (mine and list(mine[0]) != list(theirs[0])):
        print(f"FAIL {name}: {len(mine)} rows against the campaign's {len(theirs)}"); bad += 1
        continue
    for a, b in zip(mine, theirs):
        for k in a:
            if k in exact:
                if a[k] != b[k]:
                    print(f"FAIL {name}: {k} {a[k]} against the campaign's {b[k]}"); bad += 1
            else:
                worst = max(worst, abs(float(a[k]) - float(b[k])) / abs(float(b[k])))
    if worst > 1e-7:
        print(f"FAIL {name}: relative difference {worst:.1e} > 1e-7"); bad += 1
    else:
        print(f"ok   {name}: {len(mine)} rows = the campaign's (integers equal, numbers within {worst:.1e})")
sys.exit(1 if bad else 0)
PY

OPENBLAS_NUM_THREADS=1 "$rsi" simulate "$work/single.json" --method cc --modes 20 --boundary-modes 96 \
  --ccx-cache "$cache" --out "$work/single-cc" >"$work/simulate-cc.log" 2>&1 ||
  { fail "simulate --method cc exited $?"; cat "$work/simulate-cc.log"; }
/usr/bin/python3 "$(dirname "$0")/sweep_row_from_history.py" "$work/out/sweep.csv" 6474 cc-96 \
  "$work/single-cc/history.csv" "$work/single-cc/summary.json" 1000 1 0.2 u_7020_1 flexible ||
  fail "the 6474 rad/s cc-96 row against rsi simulate --method cc's history.csv"

[ "$failures" -eq 0 ] || { echo "sweep_system3d: $failures failure(s)"; exit 1; }
echo "sweep_system3d: all checks passed"
