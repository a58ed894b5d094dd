#!/usr/bin/env bash
# Issue 14 goals: the speedup of the fastest reduced run with e2 <= TARGET
# over the full reference, each ratio taken within one campaign (SPEC §6),
# over REPEATS campaigns of CASE, and their median. Wall times are rsi's
# own (convergence.csv wall_s: the solver's time, the history output
# measured apart as output_seconds). Run it on an otherwise idle machine.
# Usage: bench/frontier_speedup.sh RSI CASE [REPEATS] [TARGET] [JOBS]
# e.g. bench/frontier_speedup.sh build/cli/rsi data/cases/batailly2007-72el.json 3 0.05
set -eu
rsi=$1
case_file=$2
repeats=${3:-3}
target=${4:-0.05}
jobs=${5:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
ratios=()
for r in $(seq "$repeats"); do
  "$rsi" campaign "$case_file" --jobs "$jobs" --no-report --out "$work/c" >"$work/log" 2>&1 ||
    { echo "rsi campaign failed:"; tail -5 "$work/log"; exit 1; }
  line=$(/usr/bin/python3 - "$work/c/convergence.csv" "$target" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
target = float(sys.argv[2])
full = next(r for r in rows if r["method"] == "full")
ok = [r for r in rows if r["method"] != "full" and float(r["e2"]) <= target]
if not ok:
    print(f"none 0 no run with e2 <= {target}")
    sys.exit(0)
best = min(ok, key=lambda r: float(r["wall_s"]))
ratio = float(full["wall_s"]) / float(best["wall_s"])
print(f"{ratio:.1f} {best['run']} e2 {float(best['e2']):.4f} wall {float(best['wall_s']) * 1e3:.2f} ms, "
      f"reference {float(full['wall_s']):.3f} s")
PY
)
  ratios+=("${line%% *}")
  echo "campaign $r: ${line#* } -> ${line%% *}x"
done
/usr/bin/python3 - "${ratios[*]}" <<'PY'
import statistics, sys
values = [float(x) for x in sys.argv[1].split() if x != "none"]
print(f"median speedup over {len(values)} campaigns: {statistics.median(values):.1f}x"
      if values else "no campaign reached the target")
PY
