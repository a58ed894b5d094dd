#!/usr/bin/env bash
# component.rotation_axis acts on a rubbing run (issue "Hardening, third
# round", class 1: it was read and had no effect, both casing laws hard-coded
# the z axis, so a run about another axis gave the z-axis history byte for
# byte). A small 3D bar model (verification/cli/ring_model.py: 4 contact nodes on
# a ring about z, 2 interior nodes, 18 dofs) is built about z and built again
# turned so that its axis is x (the cyclic turn x -> y -> z -> x) and turned
# by 0.7 rad about (1, 2, 3)/sqrt(14), with rotation_axis the turned z. The
# turned model's run must be the first run turned: its gaps, multipliers,
# energy and works (scalars) equal, and the response (node 1 along the image
# of y) equal after the cyclic turn. The general turn moves the reference of
# the polar angle (reference/contact/rigid_surface_contact.hpp: e_1 follows
# the coordinate axis nearest to a), so it runs with a constant gap, which no
# polar angle enters; the cyclic turn keeps the polar angles and runs on the
# oval casing. Each for the full run (reference/contact/rigid_surface_contact)
# and CB-2 (reduced/rigid_casing), written independently.
#
# Tolerance: the turned runs do the same arithmetic on data rounded
# differently (coordinates turned in double precision, sums in another
# order), so they differ by rounding: at most a few eps = 2.2e-16 of each
# quantity's scale a step, adding up over the run's n steps. Bound:
# n x 64 x eps of the column's largest magnitude (64: a generous count of
# the rounded operations a row's value goes through in one step of an
# 18-dof model with 4 contacts). Before the axis acted (main), the x-axis
# runs measured the radii about z: differences of the order of the values.
# About 3 s in Release.
# Usage: rubbing_axis.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
model() { /usr/bin/python3 "$src/verification/cli/ring_model.py" "$@"; }

# DIR METHOD: runs the ring of DIR with METHOD into DIR/out-METHOD.
run() {
  local dir=$1 method=$2
  local args=(--method "$method")
  [ "$method" = cb ] && args+=(--modes 2)
  if ! "$rsi" simulate "$dir/ring.json" "${args[@]}" --out "$dir/out-$method" >"$dir/log-$method" 2>&1; then
    echo "FAIL $dir $method: $(tail -n 3 "$dir/log-$method")"
    failures=$((failures + 1))
    return 1
  fi
}

# NAME A B WITH_RESPONSE: compares two histories column by column.
compare() {
  /usr/bin/python3 - "$@" <<'PY'
import csv, json, sys
name, a, b, with_response = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4] == "1"
ra = list(csv.reader(open(a + "/history.csv")))
rb = list(csv.reader(open(b + "/history.csv")))
steps = json.load(open(a + "/summary.json"))["steps"]
eps = 2.220446049250313e-16
if len(ra) != len(rb) or len(ra[0]) != len(rb[0]):
    print("FAIL %s: %d x %d rows/columns against %d x %d" % (name, len(ra), len(ra[0]), len(rb), len(rb[0])))
    sys.exit(1)
rows = len(ra) - 1
worst_name, worst_ratio, failed = "", 0.0, []
for j, column in enumerate(ra[0]):
    if j == 1 and not with_response:
        continue
    x = [float(r[j]) for r in ra[1:]]
    y = [float(r[j]) for r in rb[1:]]
    finite = [(u, v) for u, v in zip(x, y) if u == u and v == v]  # energy is NaN between checks
    if len([u for u in x if u == u]) != len([v for v in y if v == v]):
        failed.append("%s: NaN rows differ" % column)
        continue
    scale = max([abs(u) for u, _ in finite] + [abs(v) for _, v in finite] + [0.0])
    diff = max([abs(u - v) for u, v in finite] + [0.0])
    bound = steps * 64 * eps * scale
    ratio = diff / bound if bound > 0 else (0.0 if diff == 0 else float("inf"))
    if ratio > worst_ratio:
        worst_name, worst_ratio = "%s (|diff| %.3e, scale %.3e, bound %.3e)" % (column, diff, scale, bound), ratio
    if diff > bound:
        failed.append("%s: |diff| %.3e > bound %.3e (scale %.3e)" % (column, diff, bound, scale))
print("%s %s: %d rows, %d steps, %d columns; worst %s, %.3g of the bound" %
      ("FAIL" if failed else "ok  ", name, rows, steps, len(ra[0]), worst_name, worst_ratio))
for f in failed[:6]:
    print("     " + f)
sys.exit(1 if failed else 0)
PY
  [ $? -eq 0 ] || failures=$((failures + 1))
}

# Contact must happen, or the frames would not be exercised.
contact() { # HISTORY
  /usr/bin/python3 - "$1" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
cols = [j for j, c in enumerate(rows[0]) if c.startswith("lambda_") and not c.startswith("lambda_t")]
peak = max(abs(float(r[j])) for r in rows[1:] for j in cols)
print("%.3e" % peak)
PY
}

# Oval gap: about z against the cyclic turn (axis x).
model "$work/z"
model "$work/x" cyclic
# Constant gap (an interference of 0.002 mm): about z against the general turn.
model "$work/zc" none 'gap={"constant": -0.002}'
model "$work/g" general 'gap={"constant": -0.002}'
echo "axis of the general turn: $(python3 -c "import json; print(json.load(open('$work/g/ring.json'))['component']['rotation_axis'])")"
for dir in z x zc g; do
  for method in full cb; do
    run "$work/$dir" "$method"
  done
done
[ "$failures" -eq 0 ] || exit 1
for method in full cb; do
  for dir in z zc; do
    peak=$(contact "$work/$dir/out-$method/history.csv")
    echo "$dir $method: largest normal multiplier $peak N"
    if python3 -c "import sys; sys.exit(0 if float('$peak') > 0 else 1)"; then :; else
      echo "FAIL $dir $method: no contact, the frames are not exercised"
      failures=$((failures + 1))
    fi
  done
  compare "$method, axis x (cyclic turn, oval gap) against z" \
    "$work/z/out-$method" "$work/x/out-$method" 1
  compare "$method, general axis (constant gap) against z" \
    "$work/zc/out-$method" "$work/g/out-$method" 0
done
echo "$failures failed"
[ "$failures" -eq 0 ]
