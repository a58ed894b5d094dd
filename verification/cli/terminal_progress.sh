#!/usr/bin/env bash
# Progress on a terminal (issue 13, class 9): a stage without a step count
# (assembly and the Lanczos solve for omega_max, minutes on a large casing)
# is shown as "<stage>: <elapsed> s" redrawn every second, then the steps'
# "%" line; with stderr not a terminal nothing of it is written (logs stay
# clean). The terminal is a pseudo-terminal from util-linux `script`
# (skipped, exit 77, without it). The case: the default one with a
# 2,500-element casing (10,678 dofs; its omega_max takes about 3 s of
# Lanczos) at 2.5e-9 s, under the casing's 2/omega_max (about 4e-9 s: the
# 10,000-element casing's 2.64e-10 s times (10000/2500)^2), 20 steps.
# Usage: terminal_progress.sh RSI SOURCE_DIR    (about 7 s in Release)
set -u
rsi=$1
src=$2
if ! command -v script >/dev/null; then
  echo "skipped: no 'script' (util-linux) for a pseudo-terminal"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" "$work/big.json" \
  casing.n_elements=2500 time.step=2.5e-9 time.duration=5e-8 time.output_every=1 forcing.duration=5e-8
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
# On a pseudo-terminal: stderr and stdout both land in the typescript.
script -qefc "'$rsi' simulate '$work/big.json' --out '$work/tty'" "$work/typescript" >/dev/null 2>&1
status=$?
if [ "$status" -ne 0 ]; then
  fail "simulate on a terminal exited $status: $(tail -c 600 "$work/typescript")"
fi
stage=$(tr '\r' '\n' <"$work/typescript" | grep -c '^preparing the run (assembly, omega_max): [0-9]* s')
if [ "$stage" -lt 2 ]; then
  fail "fewer than 2 redraws of the stage line on a terminal ($stage): $(tr '\r' '\n' <"$work/typescript" | head -5)"
else
  echo "ok   stage line redrawn $stage times on a terminal"
fi
# The same run with stderr to a file: no stage line.
"$rsi" simulate "$work/big.json" --out "$work/file" >"$work/log" 2>"$work/err"
status=$?
if [ "$status" -ne 0 ]; then
  fail "simulate with stderr to a file exited $status: $(cat "$work/err")"
elif grep -q 'preparing the run' "$work/err"; then
  fail "the stage line was written to a file: $(head -c 300 "$work/err")"
else
  echo "ok   no stage line with stderr to a file"
fi
echo "$failures failed"
[ "$failures" -eq 0 ]
