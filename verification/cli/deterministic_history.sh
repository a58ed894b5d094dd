#!/usr/bin/env bash
# Determinism: the same case on the same build gives a byte-identical
# history.csv (17 significant digits, so any difference in any bit shows).
# Runs `rsi simulate` twice for the full reference and twice for CB with 10
# modes, each into its own directory, and compares with cmp. The default
# case is shortened to 5 ms (time.duration; contact starts at 3.96 ms, so
# the contact solver is exercised) to keep the test short.
# Damping (issue 12): the same case with the damping keys present but zero
# ("damping": {"rayleigh": {"alpha": 0, "beta": 0}, "modal_ratio": 0}) must
# give the same bytes as with the keys absent (zero damping is the
# undamped scheme, operation for operation).
# Usage: deterministic_history.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" "$work/short.json" \
  time.duration=0.005
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$work/short.json" "$work/zero-damping.json" \
  'damping={"rayleigh": {"alpha": 0, "beta": 0}, "modal_ratio": 0}'
failures=0
for method in "full" "cb --modes 10"; do
  name=${method// /}
  for run in 1 2; do
    # shellcheck disable=SC2086
    if ! "$rsi" simulate "$work/short.json" --method $method --out "$work/$name-$run" >"$work/log" 2>&1; then
      echo "FAIL rsi simulate --method $method (run $run) failed:"
      cat "$work/log"
      exit 1
    fi
  done
  rows=$(($(wc -l <"$work/$name-1/history.csv") - 1))
  if cmp "$work/$name-1/history.csv" "$work/$name-2/history.csv"; then
    echo "ok   --method $method: history.csv byte-identical over two runs ($rows rows, $(wc -c <"$work/$name-1/history.csv") bytes)"
  else
    echo "FAIL --method $method: history.csv differs between two runs of the same case"
    failures=$((failures + 1))
  fi
  # shellcheck disable=SC2086
  if ! "$rsi" simulate "$work/zero-damping.json" --method $method --out "$work/$name-zero" >"$work/log" 2>&1; then
    echo "FAIL rsi simulate --method $method with zero damping failed:"
    cat "$work/log"
    exit 1
  fi
  if cmp "$work/$name-1/history.csv" "$work/$name-zero/history.csv"; then
    echo "ok   --method $method: damping keys present but zero give the same history.csv bytes as keys absent"
  else
    echo "FAIL --method $method: zero damping changes history.csv"
    failures=$((failures + 1))
  fi
done
[ "$failures" -eq 0 ]
