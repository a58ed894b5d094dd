#!/usr/bin/env bash
# `rsi sweep` under mpirun when a rank is stopped, or mpirun itself: rank 0
# publishes what it has or leaves --out clean, within 60 s (and its own
# runs' time, which go on after rank 1 stopped), and says so in
# one `rsi: error:` line. A sweep of 12 speeds of the paper's case (full
# runs of 0.05 s, about 2 s each) on 2 ranks, 6 runs a rank, --out created
# by the run. The signal goes when rank 0 first reports 4 runs done; its
# report comes every 2 s, so each rank has 1 or more runs done (unless the
# other did 4 alone) and at most 2 s of runs more than 4 (3 or more left).
# (With 6 speeds, 3 a rank, and the signal at 2 runs done, CI once stopped
# rank 1 after its last run under load: nothing lost, the case untested.)
#  - SIGTERM to rank 1 alone (its run polls the signal, rank 1 reports the
#    interruption to rank 0 and ends): rank 0 writes its own rows and a
#    failed row for each of rank 1's runs that never came, publishes, and
#    mpirun exits non-zero (3 or 143); sweep.csv holds the 12 rows, 1 to 5
#    of them failed (rank 1 had sent a row and had one left), the summary
#    names rank 1 as stopped. Before: rank 0 counted a row rank 1
#    had sent and it had written as lost too, waited for a 7th of 6 rows
#    forever (a hang; mpirun killed here after 60 s).
#  - SIGKILL to rank 1 (no word from it): mpirun ends the job, rank 0 gets
#    SIGTERM: --out is removed (no lock, no staging folder), exit non-zero.
#    Before: rank 0 waited in MPI_Finalize before removing its staging
#    folder, mpirun's SIGKILL came first: --out held .rsi-lock and
#    .rsi-stage-PID.
#  - Ctrl-C to mpirun (SIGINT to its process group, setsid here): the
#    same, nothing left.
# Skipped (exit 77, said) without mpirun or setsid. About 42 s in Release
# with both cores busy elsewhere, 109 s in the sanitizer build (idle).
# SANITIZED = 1 (an ASan/UBSan build): runs of 0.01 s instead of 0.05 s,
# the same signals at the same point (both ranks past their first run);
# the test took 196-262 s there with 0.05 s (CI, session 18) and 226 s with
# 0.02 s (CI, session 31, 60 s of it the wait that failed), its time the
# runs', not the stops'.
# Usage: sweep_mpi_interrupted.sh RSI SOURCE_DIR [SANITIZED]
set -u
rsi=$1
src=$2
duration=0.05
[ "${3:-0}" = 1 ] && duration=0.01
for tool in mpirun setsid; do
  if ! command -v "$tool" >/dev/null; then
    echo "skipped: $tool is not on PATH (Debian packages openmpi-bin, util-linux)"
    exit 77
  fi
done
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0
work=$(mktemp -d)
mpirun_pid=""
cleanup() {
  [ -n "$mpirun_pid" ] && kill -KILL -- "-$mpirun_pid" 2>/dev/null
  rm -rf "$work"
}
trap cleanup EXIT
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
/usr/bin/python3 - "$src/data/cases/batailly2007.json" "$work/case.json" "$duration" <<'PY'
import json, sys
c = json.load(open(sys.argv[1]))
c.pop("campaign", None)
c["sweep"] = {"speeds": [250 + 15 * k for k in range(12)], "duration": float(sys.argv[3]), "transient": 0.004,
              "damping": {"rayleigh": {"alpha": 30, "beta": 0}, "projected_rayleigh": True},
              "runs": [{"method": "full"}]}
json.dump(c, open(sys.argv[2], "w"))
PY
now_ms() { echo $(($(date +%s%N) / 1000000)); }

# The pid of rank RANK among mpirun's children (OMPI_COMM_WORLD_RANK).
rank_pid() {
  local p
  for p in $(pgrep -P "$mpirun_pid"); do
    if tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$1"; then
      echo "$p"
      return
    fi
  done
}

# NAME WHAT: starts the sweep (its own session), waits until both ranks
# have a row done (rank 0 says 4 runs done), then WHAT: rank1-TERM,
# rank1-KILL or mpirun-INT; waits up to 60 s (rank1-TERM: and rank 0's runs).
stop_sweep() {
  local name=$1 what=$2 out=$work/out-$1
  local started
  started=$(now_ms)
  setsid mpirun -n 2 "$rsi" sweep "$work/case.json" --no-report --out "$out" \
    >"$work/$name.log" 2>"$work/$name.err" &
  mpirun_pid=$!
  for _ in $(seq 1 1200); do # up to 120 s (the first runs, a loaded machine)
    grep -qE 'sweep: ([4-9]|1[0-2])/12 runs done' "$work/$name.err" && break
    kill -0 "$mpirun_pid" 2>/dev/null || break
    sleep 0.1
  done
  local r1
  r1=$(rank_pid 1)
  if [ -z "$r1" ] || ! grep -qE 'sweep: ([4-9]|1[0-2])/12 runs done' "$work/$name.err"; then
    fail "$name: the sweep did not reach 4 runs with rank 1 running: $(tail -n 3 "$work/$name.err")"
    kill -KILL -- "-$mpirun_pid" 2>/dev/null
    wait "$mpirun_pid" 2>/dev/null
    mpirun_pid=""
    return 1
  fi
  local before
  before=$(now_ms)
  # How long the job may run on: 60 s to stop, and after rank1-TERM rank 0's
  # own runs, which go on: 60 s + 3 T. At the signal T = before - started
  # has seen 4 or more runs on 2 ranks: rank 0 runs at about 2 / T and has
  # at most 5 left (it did 1 or more), so 2.5 T, rounded up to 3 T. (CI, session 31, sanitizer build
  # under load: about 20 s a run, 4 left at the signal, 60 s was too few.)
  local limit_ds=600
  [ "$what" = rank1-TERM ] && limit_ds=$((600 + (before - started) * 3 / 100))
  case $what in
  rank1-TERM) kill -TERM "$r1" ;;
  rank1-KILL) kill -KILL "$r1" ;;
  mpirun-INT) kill -INT -- "-$mpirun_pid" ;;
  esac
  local ended=0
  for _ in $(seq 1 "$limit_ds"); do
    kill -0 "$mpirun_pid" 2>/dev/null || { ended=1; break; }
    sleep 0.1
  done
  if [ "$ended" -eq 0 ]; then
    # What each side said last, for the diagnosis of a hang (seen once in
    # session 23's rehearsal, under load; not reproduced in 2 runs after).
    fail "$name: mpirun still runs $((limit_ds / 10)) s after $what; stderr ends: $(tail -n 4 "$work/$name.err" | tr '\n' '|')"
    ps -o pid,stat,etime,args --ppid "$mpirun_pid" 2>/dev/null | head -n 5
    kill -KILL -- "-$mpirun_pid" 2>/dev/null
    wait "$mpirun_pid" 2>/dev/null
    mpirun_pid=""
    return 1
  fi
  wait "$mpirun_pid"
  status=$?
  mpirun_pid=""
  ms=$(($(now_ms) - before))
  hidden=$(find "$out" -name '.rsi-*' 2>/dev/null | head -n 3)
  errors=$(grep -c '^rsi: error:' "$work/$name.err")
  return 0
}

if stop_sweep rank-term rank1-TERM; then
  rows=$(($(grep -c . "$work/out-rank-term/sweep.csv" 2>/dev/null || echo 1) - 1))
  lost=$(grep -c ',failed,' "$work/out-rank-term/sweep.csv" 2>/dev/null)
  if [ "$status" -eq 0 ]; then
    fail "rank-term: mpirun exited 0 after SIGTERM to rank 1"
  elif [ -n "$hidden" ]; then
    fail "rank-term: left $hidden"
  elif [ "$rows" -ne 12 ]; then
    fail "rank-term: sweep.csv has $rows rows, 12 expected (rank 0's and rank 1's lost ones failed)"
  elif [ "${lost:-0}" -lt 1 ] || [ "${lost:-0}" -gt 5 ]; then
    fail "rank-term: $lost failed rows, 1 to 5 expected (rank 1 stopped after its first run, before its last)"
  elif ! grep -q 'rank 1 stopped: interrupted by SIGTERM' "$work/out-rank-term/sweep_summary.json"; then
    fail "rank-term: the summary does not say rank 1 was stopped by SIGTERM"
  elif [ "$errors" -ne 1 ]; then
    fail "rank-term: $errors 'rsi: error:' lines: $(grep '^rsi: error:' "$work/rank-term.err")"
  elif ! grep -q "^wrote $work/out-rank-term/sweep.csv" "$work/rank-term.log"; then
    fail "rank-term: no 'wrote' line for the published sweep.csv"
  else
    echo "ok   rank-term: mpirun exit $status $ms ms after SIGTERM to rank 1, $rows rows ($lost failed), $(grep '^rsi: error:' "$work/rank-term.err" | head -c 90)..."
  fi
fi

for stop in rank1-KILL mpirun-INT; do
  name=${stop,,}
  if stop_sweep "$name" "$stop"; then
    if [ "$status" -eq 0 ]; then
      fail "$name: mpirun exited 0 after $stop"
    elif [ -e "$work/out-$name" ]; then
      fail "$name: --out left behind: $(ls -A "$work/out-$name" | tr '\n' ' ')"
    elif [ "$errors" -ne 1 ]; then
      fail "$name: $errors 'rsi: error:' lines: $(grep '^rsi: error:' "$work/$name.err")"
    elif grep -q '^wrote ' "$work/$name.log"; then
      fail "$name: a 'wrote' line for files that are not there: $(grep '^wrote ' "$work/$name.log")"
    else
      echo "ok   $name: mpirun exit $status $ms ms after $stop, no --out, no lock, no staging folder; $(grep '^rsi: error:' "$work/$name.err" | head -c 90)"
    fi
  fi
done

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "sweep_mpi_interrupted: a stopped rank or mpirun leaves rank 0's rows or a clean --out"
