#!/usr/bin/env bash
# The energy monitor on refined meshes sampled every step (issue 13, class 2:
# a monitor must not fail a valid run; streamed_history_file.sh checks the
# default 9-element mesh at output_every 1). The 36-element case (full and
# CB-44) and the 72-element case (full) with time.output_every = 1 over
# 2 ms, which includes the first contact (step 4507 of 3.125e-7 s, 14087 of
# 1e-7 s: 1.41 ms), must complete: exit 0, summary status "completed", every
# step a history row, contact reached. And their energy balance must stay at
# round-off:
#   |E - E_0 - W_ext - W_contact + W_damp| <= N eps R x energy_scale,
# the bound of test_reference_contact: E = E_0 + W is an identity of the
# scheme (central_difference.hpp, reduced_integrator.hpp), and each of the
# N steps perturbs it by about eps |u| / |u_{n+1} - u_n| relative (the
# rounding of u_{n+1} = 2 u_n - u_{n-1} + ... against the increment the
# works are made of). R = |u| / |u_{n+1} - u_n| is measured on the run's
# own history: the largest move of a blade tip's gap from its start over
# its largest change in one step (about 1/(omega dt): 3.4e3 at 3.125e-7 s,
# 1.1e4 at 1e-7 s). Measured errors are 1e-3 of the bound; leaving E_0 out
# of the balance (7.8e-7 and 8.4e-8 of the scale) exceeds it.
# Release: about 2.5 s of CPU, 4.4 s wall (72-element full run 1.4 s; its
# CB-44 basis alone would add 5 s, and the reduced monitor is the
# 36-element CB-44's); the AddressSanitizer build: 20 s.
# Usage: refined_energy_monitor.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}

for elements in 36 72; do
  /usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007-${elements}el.json" \
    "$work/every-$elements.json" time.duration=0.002 time.output_every=1
done
for run in "36 full" "36 cb --modes 44" "72 full"; do
  read -r elements method <<<"$run"
  name="$elements elements, --method $method, output_every 1"
  out=$work/out-$elements
  # shellcheck disable=SC2086
  "$rsi" simulate "$work/every-$elements.json" --method $method --out "$out" >"$work/log" 2>&1
  status=$?
  if [ "$status" -ne 0 ]; then
    fail "$name: exit $status: $(grep "^rsi: error" "$work/log" | head -c 400)"
    continue
  fi
  /usr/bin/python3 - "$out" "$name" <<'PY' || failures=$((failures + 1))
import csv, json, sys
out, name = sys.argv[1], sys.argv[2]
s = json.load(open(f"{out}/summary.json"))
rows = list(csv.reader(open(f"{out}/history.csv")))
header, data = rows[0], [[float(x) for x in r] for r in rows[1:]]
gaps = [i for i, h in enumerate(header) if h.startswith("gap_")]
start = data[0]
moved = max(abs(r[i] - start[i]) for r in data for i in gaps)
step = max(abs(b[i] - a[i]) for a, b in zip(data, data[1:]) for i in gaps)
eps = 2.0 ** -52
n = s["steps"]
ratio = moved / step
bound = n * eps * ratio * s["energy_scale"]
print(f"{name}: {s['status']}, {n} of {s['steps_requested']} steps, {len(data)} rows, "
      f"first contact at step {s['first_contact_step']}; balance error {s['energy_balance_error']:.3e} J, "
      f"bound N eps R scale = {n} x {eps:.3e} x {ratio:.3e} x {s['energy_scale']:.3e} J = {bound:.3e} J")
problems = []
if s["status"] != "completed" or not s["completed"]:
    problems.append(f"status {s['status']!r}")
if n != s["steps_requested"] or len(data) != n + 1:
    problems.append(f"{len(data)} rows for {n} of {s['steps_requested']} steps, expected one a step and the start")
if not 0 < s["first_contact_step"] < n:
    problems.append(f"first contact at step {s['first_contact_step']}: the window has no contact")
if not s["energy_balance_error"] <= bound:
    problems.append(f"balance error {s['energy_balance_error']:.3e} J above the round-off bound {bound:.3e} J")
for p in problems:
    print(f"FAIL {name}: {p}")
if not problems:
    print(f"ok   {name}")
sys.exit(1 if problems else 0)
PY
done

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "refined meshes at output_every 1: completed, energy balance at round-off"
