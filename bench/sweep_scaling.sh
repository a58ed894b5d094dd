#!/usr/bin/env bash
# Issue 15 goal: parallel efficiency of `mpirun -n 2 rsi sweep` against one
# process (--jobs 1), for CB-44 at its own step (the 5-minute map of the
# goal) over SPEEDS equally spaced speeds of the default range (default 200).
# Prints each wall time (rsi's own, sweep_summary.json wall_s), the medians
# of REPEATS (default 3) and E = T_1 / (2 T_2); checks the two sweep.csv
# are the same bytes. Run it on an otherwise idle machine.
# Usage: bench/sweep_scaling.sh RSI [SPEEDS] [REPEATS]
# (the full model's map costs about 10 times more a speed: see README)
set -eu
rsi=$1
speeds=${2:-200}
repeats=${3:-3}
src=$(cd "$(dirname "$0")/.." && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
wall() { /usr/bin/python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["wall_s"])' "$1/sweep_summary.json"; }
one=() two=()
for r in $(seq "$repeats"); do
  "$rsi" sweep "$src/data/cases/batailly2007.json" --speeds "150:550:$speeds" --method cb --modes 44 --time-step own --jobs 1 --quiet --no-report --out "$work/one" >/dev/null
  one+=("$(wall "$work/one")")
  mpirun -n 2 "$rsi" sweep "$src/data/cases/batailly2007.json" --speeds "150:550:$speeds" --method cb --modes 44 --time-step own --jobs 1 --quiet --no-report --out "$work/two" >/dev/null
  two+=("$(wall "$work/two")")
  cmp -s "$work/one/sweep.csv" "$work/two/sweep.csv" || { echo "sweep.csv differs"; exit 1; }
  echo "repeat $r: one process ${one[-1]} s, mpirun -n 2 ${two[-1]} s"
done
/usr/bin/python3 - "${one[*]}" "${two[*]}" <<'PY'
import statistics, sys
t1 = statistics.median(map(float, sys.argv[1].split()))
t2 = statistics.median(map(float, sys.argv[2].split()))
print(f"median: one process {t1:.2f} s, mpirun -n 2 {t2:.2f} s, speedup {t1/t2:.3f}, efficiency {t1/(2*t2):.3f}")
PY
