#!/usr/bin/env bash
# The abradable liner in the rubbing runs (rubbing.liner; SPEC §9), the
# full-order solver's (reference/contact/liner_surface.hpp) and the reduced
# one's (reduced/liner_contact_solve.hpp), each on its own: the gmsh blade of
# data/cases/blade3d-rubbing.json over half a revolution (lumped mass, 16
# contact nodes on the oval casing). Per method (full, cb 20, macneal 20)
# three runs: the rigid casing, a liner with huge E and sigma_y
# (E = sigma_y = 1e12 MPa), and a soft liner (E = 1e4, sigma_y = 10,
# H = 1e3 MPa, h = 2 mm, 200 cells around).
#  1. The stiff liner is the rigid casing up to its compliance. Its bar is
#     elastic (never yields): a contact node carrying lambda_n sits at the
#     bar's compression lambda_n / k past the surface, row by row (every
#     method's row holds lambda with the gap it enforces: rubbing_run.hpp),
#     to the round-off of a gap: g = g0 + e_n . u is three products and three
#     sums rounded at eps = 2.2e-16 of terms at most U (the largest |value|
#     among the gap and response columns), at most 6 eps U: bound 8 eps U.
#     (The reduced solve stops when a sweep changes lambda by 1e-14 of its
#     largest: lambda / k moves by 1e-14 of F_max / k, far below eps U.)
#     Each step the compliant solve puts a node F / k from where the rigid
#     solve puts it; the undamped blade carries such a perturbation without
#     growing it, so the gaps of the method's two runs differ by a few
#     F_max / k: bound n_contacts x F_max / k (16: every node's perturbation
#     added, none cancelling; an estimate, not a proof: the contact is
#     nonlinear). Without the liner's compliance the penetration would be
#     round-off (about 5e-16 in the rigid run), so the first check fails on
#     a build that ignores the key.
#  2. The soft liner: the energy balance E = E0 + W_ext + W_contact - W_damp
#     - W_plastic (E with the bars' elastic energy) closes to the rigid run's
#     tolerance (1e-8 of its scale) — this is the blade's discrete identity
#     with the liner's terms in it — and the plastic work summed step by
#     step equals its closed form from the final wear alone,
#     W_p = sum over cells A (sigma_y p + H p^2 / (2 h)) (alpha = p / h, W_p
#     telescopes), to 1e-10 relative (the sum of about 1e5 step terms, each
#     rounded at eps = 2.2e-16: 1e5 x eps = 2.2e-11, times a few). The
#     cell area and bar stiffness each solver derived from the case agree to
#     4 eps (the same products in another order).
#  3. The wear: some cell worn, W_plastic in the rows never decreasing, the
#     summary's max depth equal to wear.csv's largest depth and its lobe
#     count equal to the count of data/README.md's rule, recomputed here
#     (peaks standing out a tenth of the deepest cell).
#  4. A blade that starts inside the liner (a constant gap of -0.05 mm, 0.1
#     revolution): MacNeal's massless boundary is in balance with loaded
#     bars at t = 0, whose energy is in E0; the balance closes to the same
#     1e-8 for every method (it was broken at step 1 until session 18, a
#     Rotor 37 map above 1640 rad/s where the tips' growth closes the gap).
#  5. A liner that the tips wear through (h = 0.02 mm, sigma_y = 0.01 MPa,
#     H = 0: the bar yields at once and flows; a thinner soft liner does not
#     do it, its bar stiffer by 1/h and its wear about 4 % of h at any h):
#     each method's run stops where a cell's wear reaches h (the model has no
#     backing to meet), exit 3, summary not completed, its status naming the
#     liner worn through and its thickness. Measured: full, cb 20, macneal 20
#     all stop at sector 38 at t = 8.41e-4 s (wear 0.02006, 0.02021, 0.02098).
#     `rsi sweep` of the same MacNeal-20 run at the case's speed exits 0 (a
#     map goes on past a worn-through speed) with the row's status
#     `worn_through`, diverged 0, and the wear of `rsi simulate`'s run (the
#     same run: equal to the last digit).
# The reduced runs' wear against the full run's is liner_campaign's
# (data/thresholds/blade3d-rubbing-liner.json).
# Skipped (exit 77) without gmsh or ccx. About 20 s in Release.
# SANITIZED = 1 (an ASan/UBSan build): the soft liner alone on the blade's
# coarser mesh (element_size 20: 2,091 dofs), full, cb 20 and macneal 20,
# over 0.3 revolution (the first contacts come at a quarter), checks 2 and
# 3, and the pressed start (4); the comparison with the rigid casing (1)
# runs in Release.
# Usage: liner_rubbing.sh RSI SOURCE_DIR CACHE [SANITIZED]
set -u
rsi=$1
src=$2
cache=$3
sanitized=${4:-0}
length=0.5
runs="rigid stiff soft"
methods="full cb macneal"
mesh=()
if [ "$sanitized" = 1 ]; then
  length=0.3
  runs=soft
  mesh=(component.source.gmsh_blade.element_size=20.0)
  echo "sanitizer build: the soft liner on element_size 20, full, cb 20 and macneal 20, over 0.3 revolution (checks 2-4; check 1 in Release)"
fi
. "$(dirname "$0")/skip_without_gmsh_ccx.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
variant() { /usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/blade3d-rubbing.json" "$@" "${mesh[@]}"; }
variant "$work/rigid.json" "rubbing.revolutions=$length" "rubbing.campaign.full_revolutions=$length"
variant "$work/stiff.json" "rubbing.revolutions=$length" "rubbing.campaign.full_revolutions=$length" \
  'rubbing.liner={"thickness": 2.0, "young_modulus": 1e12, "yield_stress": 1e12, "hardening_modulus": 0.0, "cells_around": 1000}'
variant "$work/pressed.json" "rubbing.revolutions=0.1" "rubbing.campaign.full_revolutions=0.1" \
  'rubbing.gap={"constant": -0.05}' \
  'rubbing.liner={"thickness": 2.0, "young_modulus": 10000.0, "yield_stress": 10.0, "hardening_modulus": 1000.0, "cells_around": 200}'
variant "$work/soft.json" "rubbing.revolutions=$length" "rubbing.campaign.full_revolutions=$length" \
  'rubbing.liner={"thickness": 2.0, "young_modulus": 10000.0, "yield_stress": 10.0, "hardening_modulus": 1000.0, "cells_around": 200}'
variant "$work/thin.json" "rubbing.revolutions=$length" "rubbing.campaign.full_revolutions=$length" \
  'rubbing.liner={"thickness": 0.02, "young_modulus": 10000.0, "yield_stress": 0.01, "hardening_modulus": 0.0, "cells_around": 200}' \
  "sweep={\"speeds\": [1344.0], \"revolutions\": $length, \"transient_revolutions\": 0.1, \"runs\": [{\"method\": \"macneal\", \"modes\": [20]}]}"
for method in $methods; do
  modes=()
  [ "$method" = full ] || modes=(--modes 20)
  for name in $runs pressed; do
    if ! "$rsi" simulate "$work/$name.json" --method "$method" "${modes[@]}" --ccx-cache "$cache" \
        --out "$work/$method-$name" >"$work/$method-$name.log" 2>&1; then
      echo "FAIL: the $method $name run: $(tail -n 3 "$work/$method-$name.log")"
      exit 1
    fi
  done
  "$rsi" simulate "$work/thin.json" --method "$method" "${modes[@]}" --ccx-cache "$cache" \
    --out "$work/$method-thin" >"$work/$method-thin.log" 2>&1
  status=$?
  if [ "$status" -ne 3 ]; then
    echo "FAIL: the $method run on a liner worn through exited $status (3 expected: worn through): $(tail -n 3 "$work/$method-thin.log")"
    exit 1
  fi
done
if ! "$rsi" sweep "$work/thin.json" --no-report --quiet --ccx-cache "$cache" --out "$work/sweep-thin" \
    >"$work/sweep-thin.log" 2>&1; then
  echo "FAIL: the sweep on a liner worn through did not exit 0: $(tail -n 3 "$work/sweep-thin.log")"
  exit 1
fi
/usr/bin/python3 - "$work" "$sanitized" "$methods" <<'PY'
import csv, json, sys
work = sys.argv[1]
sanitized = sys.argv[2] == "1"
methods = sys.argv[3].split()
eps = 2.220446049250313e-16
def load(name):
    rows = list(csv.reader(open(f"{work}/{name}/history.csv")))
    return rows[0], [[float(x) for x in r] for r in rows[1:]], json.load(open(f"{work}/{name}/summary.json"))
failures = 0
def check(ok, what):
    global failures
    print(("ok   " if ok else "FAIL ") + what)
    failures += 0 if ok else 1

# The rule of data/README.md, written again: per row, peaks (runs of equal
# depth deeper than both sides) that stand out at least a tenth of the
# deepest cell: walking each way to the first cell ranked above the peak
# (deeper, or as deep and earlier), the higher of the two least depths met
# is its base (the ring's least depth if none ranks above); the most over
# the rows.
def lobes(ring, deepest):
    n = len(ring)
    above = lambda a, b: ring[a] > ring[b] or (ring[a] == ring[b] and a < b)
    count = 0
    for s in range(n):
        if ring[s - 1] == ring[s]:
            continue
        e = s
        while ring[(e + 1) % n] == ring[s]:
            e += 1
        if ring[s - 1] > ring[s] or ring[(e + 1) % n] > ring[s]:
            continue
        top = min(i % n for i in range(s, e + 1))
        bases = []
        for cells in ([(s - k) % n for k in range(1, n)], [(e + k) % n for k in range(1, n)]):
            least = ring[s]
            for c in cells:
                if above(c, top):
                    bases.append(least)
                    break
                least = min(least, ring[c])
        base = max(bases) if bases else min(ring)
        count += ring[s] - base > 0 and ring[s] - base >= 0.1 * deepest
    return count

soft_full = json.load(open(f"{work}/full-soft/summary.json"))
for m in methods:
    if not sanitized:
        hr, rr, sr = load(f"{m}-rigid")
        hs, rs, ss = load(f"{m}-stiff")
        # 1. The stiff liner against the rigid casing.
        k = ss["liner"]["bar_stiffness"]
        f_max = ss["max_lambda"]
        check(ss["liner"]["plastic_work"] == 0.0, "%s stiff liner: never yields (W_plastic %g)" % (m, ss["liner"]["plastic_work"]))
        gaps = [c for c in hs if c.startswith("gap_")]
        U = max(abs(r[hs.index(c)]) for c in gaps + [hs[1]] for r in rs)
        worst, pairs = 0.0, 0
        for r in rs:
            for c in gaps:
                lam = r[hs.index("lambda_" + c[4:])]
                if lam > 0.0:
                    worst = max(worst, abs(-r[hs.index(c)] - lam / k))
                    pairs += 1
        check(pairs > 0 and worst <= 8 * eps * U,
              "%s stiff liner: -g = lambda / k in every row in contact (%d node-rows, worst %.2e <= 8 eps U = %.2e)" % (m, pairs, worst, 8 * eps * U))
        nc = len(gaps)
        check(len(rr) == len(rs), "%s stiff liner: %d rows against the rigid run's %d" % (m, len(rs), len(rr)))
        dgap = max(abs(a[hr.index(c)] - b[hs.index(c)]) for c in gaps for a, b in zip(rr, rs))
        check(dgap <= nc * f_max / k, "%s stiff liner: gaps within %.3e of the rigid run's (bound %d x F_max / k = %.3e)" % (m, dgap, nc, nc * f_max / k))
        print("%s stiff liner: response %s differs from the rigid run's by %.3e" % (m, hr[1], max(abs(a[1] - b[1]) for a, b in zip(rr, rs))))
    # 2. The soft liner's balance and plastic work.
    hl, rl, sl = load(f"{m}-soft")
    scale = sl["energy_scale"]
    check(sl["completed"], "%s soft liner: run completed (%s)" % (m, sl["status"]))
    check(sl["energy_balance_error"] <= 1e-8 * scale,
          "%s soft liner: balance with W_plastic %.3e of scale %.3e (%.2e; tolerance 1e-8)"
          % (m, sl["energy_balance_error"], scale, sl["energy_balance_error"] / scale))
    for key in ("cell_area", "bar_stiffness"):
        a, b = sl["liner"][key], soft_full["liner"][key]
        check(abs(a - b) <= 4 * eps * abs(b), "%s soft liner: %s %.17g, the full run's %.17g" % (m, key, a, b))
    wear = [(float(a), int(r), float(d)) for a, r, d in list(csv.reader(open(f"{work}/{m}-soft/wear.csv")))[1:]]
    A = sl["liner"]["cell_area"]
    sigma_y, H, h = 10.0, 1000.0, 2.0
    closed = sum(A * (sigma_y * p + H * p * p / (2 * h)) for _, _, p in wear)
    wp = sl["liner"]["plastic_work"]
    rel = abs(wp - closed) / closed if closed > 0 else float("inf")
    check(rel <= 1e-10, "%s soft liner: W_plastic %.12e against the closed form of the wear %.12e (relative %.2e <= 1e-10)" % (m, wp, closed, rel))
    col = hl.index("W_plastic")
    check(abs(rl[-1][col] - wp) <= 1e-12 * wp, "%s soft liner: the last row's W_plastic %.12e is the summary's" % (m, rl[-1][col]))
    # 3. The wear.
    depths = [d for _, _, d in wear]
    check(max(depths) > 0.0, "%s soft liner: worn, deepest cell %.6e" % (m, max(depths)))
    w = [r[col] for r in rl]
    drops = sum(1 for a, b in zip(w, w[1:]) if b < a)
    check(drops == 0, "%s soft liner: W_plastic never decreases over %d rows (%d drops)" % (m, len(w), drops))
    check(sl["liner"]["max_wear_depth"] == max(depths), "%s soft liner: summary max depth %.17g, wear.csv %.17g" % (m, sl["liner"]["max_wear_depth"], max(depths)))
    rows = sorted(set(r for _, r, _ in wear))
    deepest = max(depths)
    mine = max(lobes([d for _, r, d in wear if r == j], deepest) for j in rows)
    check(sl["liner"]["wear_lobes"] == mine, "%s soft liner: %d lobes, recomputed %d" % (m, sl["liner"]["wear_lobes"], mine))
    print("%s unmatched work (bars' work not done by the contact force): %.6e; W_plastic %.6e" % (m, sl["liner"]["unmatched_work"], wp))
    # 4. Loaded bars at t = 0.
    hp, rp, sp = load(f"{m}-pressed")
    check(sp["completed"] and sp["energy_balance_error"] <= 1e-8 * sp["energy_scale"],
          "%s pressed into the liner from t = 0: completed (%s), balance %.2e of scale %.3e"
          % (m, sp["status"][:60], sp["energy_balance_error"] / max(sp["energy_scale"], 1e-300), sp["energy_scale"]))
    check(rp[0][hp.index("lambda_1")] >= 0.0 and max(r[hp.index("lambda_1")] for r in rp) > 0.0,
          "%s pressed: node 1 carries a force (max %.4g)" % (m, max(r[hp.index("lambda_1")] for r in rp)))
    # 5. Worn through.
    st = json.load(open(f"{work}/{m}-thin/summary.json"))
    check(not st["completed"] and "worn through" in st["status"] and "thickness 0.02" in st["status"],
          "%s liner of 0.02 mm: stopped, %s" % (m, st["status"][:160]))
row = list(csv.DictReader(open(f"{work}/sweep-thin/sweep.csv")))
st = json.load(open(f"{work}/macneal-thin/summary.json"))
check(len(row) == 1 and row[0]["status"] == "worn_through" and row[0]["diverged"] == "0" and
      float(row[0]["max_wear_depth"]) == st["liner"]["max_wear_depth"],
      "sweep, liner of 0.02 mm: status %s, diverged %s, deepest wear %s (rsi simulate's %.17g)"
      % (row[0]["status"], row[0]["diverged"], row[0]["max_wear_depth"], st["liner"]["max_wear_depth"]) if row else "sweep: no row")
sys.exit(1 if failures else 0)
PY
