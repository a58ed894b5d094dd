#!/usr/bin/env bash
# `rsi campaign` shows its progress and checks cheap limits before its runs
# (issue 13, classes 9 and 8; cli/support/campaign_progress.hpp).
#  1. Every finished run's line on stderr carries the runs done out of the
#     total (a 1 ms campaign of 6 runs), in order 1..N, the time elapsed
#     and, but for the last, the estimated time left (logs and pipes too:
#     these lines were printed before, without the counts).
#  2. On a terminal (util-linux `script` gives one; skipped without it) a
#     campaign of more than a second redraws the live line
#     `campaign: k/N runs done, P% (E s, about L s left)`.
#  3. A step at or above the cheap bound of 2/omega_max (a Rayleigh
#     quotient's, run_monitor.hpp: 2.50711e-6 s for the bladed disk, its
#     exact limit to 1e-6) is refused before any run: exit 2, one line, no
#     --out. The old campaign ran all 23 runs, each refusing it, and exited
#     3 "numerical failure: the reference run failed" (5e-6 s, above the
#     old one-dof bound, and 3e-6 s, between that and the exact limit). A
#     step between the bound and the exact limit (a window of 1e-6
#     relative) is refused by the reference run, also exit 2.
# Usage: campaign_progress.sh RSI SOURCE_DIR
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
variant() { # NAME KEY=JSON...
  local name=$1
  shift
  /usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" \
    "$work/$name.json" "$@"
}
variant short time.duration=0.001 'campaign=[{"method": "guyan", "modes": [0]}, {"method": "cb", "modes": [0, 10]}, {"method": "ccm", "modes": [0, 10]}]'
# The terminal's campaign must last a few seconds: 8 runs of 40 ms (80,000
# steps) in Release, 2 runs of 5 ms under AddressSanitizer (about 10 times
# slower; the Release campaign took 116 s there).
if ldd "$rsi" | grep -q libasan; then
  variant tty time.duration=0.005 'campaign=[{"method": "cb", "modes": [10]}]'
else
  variant tty time.duration=0.04 'campaign=[{"method": "guyan", "modes": [0]}, {"method": "cb", "modes": [10, 40, 88]}, {"method": "ccm", "modes": [10, 40, 88]}]'
fi
variant step-5e-06 time.duration=0.005 time.step=5e-6
variant step-3e-06 time.duration=0.005 time.step=3e-6

# 1. The lines of the finished runs (stderr not a terminal).
if ! "$rsi" campaign "$work/short.json" --no-report --out "$work/short" >"$work/log" 2>"$work/err"; then
  fail "campaign of the short case: $(tail -n 2 "$work/err")"
else
  total=$(($(grep -c . <(/usr/bin/python3 -c "
import json, sys
c = json.load(open(sys.argv[1]))
print('\n'.join(str(m) for r in c['campaign'] for m in r['modes']))" "$work/short.json")) + 1))
  expected=$(seq 1 "$total" | sed "s|.*|&/$total|")
  got=$(grep -o '\[[0-9]*/[0-9]* runs' "$work/err" | tr -d '[' | sed 's/ runs//')
  if [ "$got" != "$expected" ]; then
    fail "the runs' lines do not count 1..$total in order: $(head -n 3 "$work/err")"
  elif [ "$(grep -c 'done in .* runs, [0-9.]* s elapsed, about [0-9]* s left\]$' "$work/err")" -ne $((total - 1)) ]; then
    fail "not every line but the last has elapsed and left: $(head -n 3 "$work/err")"
  elif ! tail -n 1 "$work/err" | grep -q "\[$total/$total runs, [0-9.]* s elapsed\]$"; then
    fail "the last line: $(tail -n 1 "$work/err")"
  else
    echo "ok   $total run lines with [k/$total runs, elapsed, left]: $(head -n 1 "$work/err")"
  fi
fi

# 2. On a terminal: the live line, drawn from the second second on (the
# tty campaign on one thread: 3-4 s).
if command -v script >/dev/null; then
  script -qec "'$rsi' campaign '$work/tty.json' --jobs 1 --no-report --out '$work/tty'" \
    /dev/null >"$work/tty.log" 2>&1
  status=$?
  if [ "$status" -ne 0 ]; then
    fail "campaign on a terminal: exit $status: $(tail -c 300 "$work/tty.log")"
  elif ! grep -aq 'campaign: [0-9]*/[0-9]* runs done, *[0-9.]*% ([0-9.]* s, about [0-9]* s left)' "$work/tty.log"; then
    fail "no live progress line on a terminal: $(tail -c 300 "$work/tty.log")"
  else
    echo "ok   on a terminal: $(grep -ao 'campaign: [0-9]*/[0-9]* runs done[^)]*)' "$work/tty.log" | tail -n 1)"
  fi
else
  echo "skipped: the terminal part (no util-linux script)"
fi

# 3. Steps refused before the runs, exit 2.
refused() { # NAME CASE FRAGMENT: exit 2, one 'rsi: error:' line naming FRAGMENT, no --out
  local name=$1 case_file=$2 fragment=$3
  rm -rf "$work/out"
  "$rsi" campaign "$case_file" --no-report --out "$work/out" >"$work/log" 2>"$work/err"
  local status=$?
  if [ "$status" -ne 2 ]; then
    fail "$name: exit $status, expected 2: $(tail -n 2 "$work/err")"
  elif [ "$(grep -c '^rsi: error:' "$work/err")" -ne 1 ] || ! grep -qF -- "$fragment" "$work/err"; then
    fail "$name: not one 'rsi: error:' line with \"$fragment\": $(cat "$work/err")"
  elif [ -e "$work/out" ]; then
    fail "$name: --out created"
  else
    echo "ok   $name: exit 2, $(wc -l <"$work/err") line(s): $(cut -c 1-150 "$work/err" | tail -n 1)"
  fi
}
for step in 5e-06 3e-06; do
  refused "a step of $step s" "$work/step-$step.json" \
    "time.step = $step s is not below the central-difference stability limit of the bladed disk: 2/omega_max <= 2.50711e-06 s"
  [ "$(wc -l <"$work/err")" -eq 1 ] || fail "a step of $step s: runs were made: $(head -n 2 "$work/err")"
done

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "the campaign shows its progress and refuses a bad step before its runs"
