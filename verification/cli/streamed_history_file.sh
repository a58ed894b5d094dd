#!/usr/bin/env bash
# Streamed history.csv (issue 6): `rsi simulate` writes its history row by
# row to a temporary file renamed at the end; `rsi campaign` formats the
# in-memory History whole. For the same runs the two files must be
# byte-identical (cmp). Also: no temporary file is left behind, a run stopped
# by a blow-up (exit 3) still writes its history, and a run refused before
# it starts (exit 2) leaves an existing history.csv untouched.
# The default case shortened to 5 ms (contact from 3.96 ms) with a row every
# 7 steps (so the last row comes from the final-step rule) keeps it quick.
# Usage: streamed_history_file.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" "$work/short.json" \
  time.duration=0.005 time.output_every=7 'campaign=[{"method": "cb", "modes": [10]}]'
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" "$work/sprag.json" \
  time.duration=0.008 time.output_every=7 bladed_disk.kink_angle_deg=-1.0
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" "$work/unstable.json" \
  time.step=1e-5
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
no_temporary() { # DIR: nothing but the named outputs
  local left
  left=$(find "$1" -name '*.tmp*')
  [ -z "$left" ] || fail "$1: temporary files left behind: $left"
}

if ! "$rsi" campaign "$work/short.json" --jobs 1 --no-report --out "$work/campaign" >"$work/log" 2>&1; then
  echo "FAIL rsi campaign failed:"
  cat "$work/log"
  exit 1
fi
for method in "full" "cb --modes 10"; do
  name=${method// /}
  # shellcheck disable=SC2086
  if ! "$rsi" simulate "$work/short.json" --method $method --out "$work/$name" >"$work/log" 2>&1; then
    echo "FAIL rsi simulate --method $method failed:"
    cat "$work/log"
    exit 1
  fi
  kept=$work/campaign/runs/$(echo "$method" | awk '{print $1 "-" ($3 == "" ? 0 : $3)}')/history.csv
  if cmp "$work/$name/history.csv" "$kept"; then
    echo "ok   --method $method: streamed history.csv = in-memory one ($(($(wc -l <"$kept") - 1)) rows, $(wc -c <"$kept") bytes)"
  else
    fail "--method $method: streamed history.csv differs from the campaign's in-memory one"
  fi
  no_temporary "$work/$name"
done

# A history row at every step (issue 13, class 2): the energy monitor
# compared E_1 with the round-off external work of step 1 and ignored E_0,
# so every such run "blew up" at step 1 when the forcing had nodal diameter
# 0 or 3. These ordinary runs must complete.
for nd in 0 3; do
  /usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" "$work/every-$nd.json" \
    time.duration=0.0002 time.output_every=1 forcing.nodal_diameter=$nd
  for method in "full" "cb --modes 10"; do
    # shellcheck disable=SC2086
    if "$rsi" simulate "$work/every-$nd.json" --method $method --out "$work/every" >"$work/log" 2>&1; then
      echo "ok   output_every 1, nodal diameter $nd, --method $method: completed"
    else
      fail "output_every 1, nodal diameter $nd, --method $method: $(tail -n 1 "$work/log")"
    fi
  done
done

"$rsi" simulate "$work/sprag.json" --method full --out "$work/sprag" >"$work/log" 2>"$work/err"
status=$?
if [ "$status" -ne 3 ]; then
  fail "sprag case: exit $status, expected 3 (blow-up)"
  cat "$work/log" "$work/err"
elif ! grep -q "^rsi: error: numerical failure: the run stopped: .*blow-up" "$work/err"; then
  fail "sprag case: exit 3 without the 'rsi: error:' line on stderr saying why"
  cat "$work/err"
elif ! [ -s "$work/sprag/history.csv" ] || ! grep -q blow-up "$work/sprag/summary.json"; then
  fail "sprag case: history.csv or the blow-up status in summary.json missing"
else
  last=$(tail -n 1 "$work/sprag/history.csv" | cut -d, -f1)
  echo "ok   stopped run (exit 3): history.csv written, $(($(wc -l <"$work/sprag/history.csv") - 1)) rows, last t = $last s"
fi
no_temporary "$work/sprag"

mkdir -p "$work/kept"
echo "previous" >"$work/kept/history.csv"
"$rsi" simulate "$work/unstable.json" --method full --out "$work/kept" >"$work/log" 2>&1
status=$?
if [ "$status" -eq 2 ] && [ "$(cat "$work/kept/history.csv")" = "previous" ] && [ "$(ls -A "$work/kept")" = "history.csv" ]; then
  echo "ok   refused run (exit 2): the existing history.csv untouched, nothing else written"
else
  fail "refused run: exit $status (expected 2), directory now holds: $(ls -A "$work/kept")"
fi
[ "$failures" -eq 0 ]
