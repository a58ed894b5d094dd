#!/usr/bin/env bash
# history.csv and summary.json of a Coulomb run (issue 12 item 2): the
# default case shortened to 5 ms (contact from 3.96 ms), whose Coulomb law
# is the default (no operating_point.friction_law key), has the columns lambda_t_1..22 after
# lambda_22, and on every row |lambda_t_k| <= mu lambda_k up to the solver's
# stopping test ((1 + mu) eta Lambda, eta = 4 (m + 1) eps, m <= 44 unknowns,
# Lambda <= the row's largest multiplier; the file's 17 digits round each
# value by 1e-17 relative, far below). The same case with the sliding_sign
# law (named) has no lambda_t column. simulate prints the
# certificate line for the Coulomb run only.
# Usage: coulomb_history_columns.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
py=/usr/bin/python3
$py "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" "$work/short.json" time.duration=0.005
$py "$src/verification/cli/case_variant.py" "$work/short.json" "$work/sliding.json" 'operating_point.friction_law="sliding_sign"'
"$rsi" simulate "$work/sliding.json" --out "$work/sliding" >"$work/sliding.log" 2>&1 || { echo "FAIL sliding_sign run"; cat "$work/sliding.log"; exit 1; }
"$rsi" simulate "$work/short.json" --out "$work/coulomb" >"$work/coulomb.log" 2>&1 || { echo "FAIL coulomb (default) run"; cat "$work/coulomb.log"; exit 1; }
failures=0
if grep -q "coulomb certificate" "$work/sliding.log"; then echo "FAIL sliding_sign run prints a coulomb certificate"; failures=$((failures + 1)); fi
if ! grep -q "coulomb certificate: max cone violation" "$work/coulomb.log"; then echo "FAIL coulomb run prints no certificate"; failures=$((failures + 1)); fi
grep "coulomb certificate" "$work/coulomb.log"
$py - "$work" <<'PY' || failures=$((failures + 1))
import csv, json, sys
work = sys.argv[1]
eps = 2.0 ** -52
mu = 0.15
bad = 0
with open(f"{work}/sliding/history.csv") as f:
    header = next(csv.reader(f))
if any(h.startswith("lambda_t") for h in header):
    print("FAIL sliding_sign history has lambda_t columns"); bad += 1
with open(f"{work}/coulomb/history.csv") as f:
    reader = csv.reader(f)
    header = next(reader)
    expected = (["t"] + [f"gap_{k}" for k in range(1, 23)] + [f"lambda_{k}" for k in range(1, 23)]
                + [f"lambda_t_{k}" for k in range(1, 23)]
                + ["energy", "external_work", "contact_work", "damping_work"])
    if header != expected:
        print("FAIL coulomb header:", ",".join(header)); bad += 1
    eta = 4 * (44 + 1) * eps
    worst = 0.0
    closed = 0
    rows = 0
    for row in reader:
        rows += 1
        x = [float(v) for v in row]
        ln = x[23:45]
        lt = x[45:67]
        scale = max(max(abs(v) for v in ln), max(abs(v) for v in lt))
        for a, b in zip(ln, lt):
            if a > 0: closed += 1
            excess = abs(b) - mu * a
            if excess > (1 + mu) * eta * scale:
                bad += 1
            worst = max(worst, excess / scale if scale > 0 else 0.0)
    print(f"coulomb history: {rows} rows, {closed} closed (row, contact) pairs, "
          f"max (|lambda_t| - mu lambda_n) / Lambda = {worst:.3e} (bound {(1 + mu) * eta:.3e})")
    if closed == 0:
        print("FAIL no closed contact in the sampled rows"); bad += 1
summary = json.load(open(f"{work}/coulomb/summary.json"))
for key in ["max_cone_violation", "max_stick_slip_residual", "stick_slip_transitions",
            "stick_contact_steps", "slip_contact_steps", "sliding_reversals"]:
    if key not in summary:
        print("FAIL summary.json lacks", key); bad += 1
print("summary:", {k: summary[k] for k in ["max_cone_violation", "max_stick_slip_residual",
      "stick_slip_transitions", "stick_contact_steps", "slip_contact_steps"]})
sys.exit(1 if bad else 0)
PY
if [ "$failures" -eq 0 ]; then echo "ok   coulomb history columns, certificate line, summary keys"; fi
exit "$failures"
