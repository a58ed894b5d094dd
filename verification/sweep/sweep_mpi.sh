#!/usr/bin/env bash
# Issue 15: `mpirun --oversubscribe -n 3 rsi sweep` against the single
# process: sweep.csv and interaction_lines.csv the same bytes; a failed
# speed on a rank is a failed row, the other rows unchanged, exit 3.
# Skipped (exit 77, said) without mpirun. In an ASan build LeakSanitizer is
# off for the MPI processes (OpenMPI's own allocations at MPI_Finalize);
# sweep_runs checks the same code paths with it on.
# Usage: sweep_mpi.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
if ! command -v mpirun >/dev/null; then
  echo "skipped: no mpirun on PATH (Debian openmpi-bin)"
  exit 77
fi
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }
/usr/bin/python3 - "$src/data/cases/batailly2007.json" "$work/case.json" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
c.pop("campaign", None)
c["sweep"] = {"speeds": [250, 280, 310, 340, 370], "duration": 0.01, "transient": 0.004,
              "damping": {"rayleigh": {"alpha": 30, "beta": 0}, "projected_rayleigh": True},
              "runs": [{"method": "full"}, {"method": "cb", "modes": [10], "time_step": ["own"]}]}
json.dump(c, open(sys.argv[2], "w"))
PY
"$rsi" sweep "$work/case.json" --quiet --no-report --out "$work/serial" >"$work/log0" 2>&1 ||
  { fail "the single process exited $?"; cat "$work/log0"; }
mpirun --oversubscribe -n 3 "$rsi" sweep "$work/case.json" --quiet --no-report --out "$work/mpi" \
  >"$work/log1" 2>&1
status=$?
[ "$status" -eq 0 ] || { fail "mpirun -n 3 exited $status"; tail -20 "$work/log1"; }
for f in sweep.csv interaction_lines.csv; do
  cmp -s "$work/serial/$f" "$work/mpi/$f" || fail "$f differs between 1 process and 3 ranks"
done
grep -q '"ranks": 3' "$work/mpi/sweep_summary.json" || fail "the summary does not say 3 ranks"

RSI_SWEEP_FAIL_SPEED=3 mpirun --oversubscribe -x RSI_SWEEP_FAIL_SPEED -n 3 "$rsi" sweep \
  "$work/case.json" --quiet --no-report --out "$work/failed" >"$work/log2" 2>&1
status=$?
[ "$status" -eq 3 ] || fail "a failed speed under mpirun exited $status, 3 expected"
[ "$(grep -c ',failed,' "$work/failed/sweep.csv")" -eq 2 ] || fail "not 2 failed rows"
diff <(grep -v '^340,' "$work/serial/sweep.csv") <(grep -v '^340,' "$work/failed/sweep.csv") \
  >/dev/null || fail "the other speeds' rows changed"
grep -q 'speed 340 rad/s, run full (rank ' "$work/failed/sweep_summary.json" ||
  fail "the summary does not name the failed speed and its rank"
[ "$failures" -eq 0 ] && echo "sweep_mpi: 3 ranks = 1 process byte for byte; a failed speed on a rank: exit 3, other rows kept"
[ "$failures" -eq 0 ]
