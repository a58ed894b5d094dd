#!/usr/bin/env bash
# Fuzz the case loader for SECONDS seconds with libFuzzer (one worker).
#
#   fuzz/run-fuzz.sh SECONDS
#
# Configures build-fuzz/ with clang (-DRSI_FUZZ=ON, RelWithDebInfo), builds
# only fuzz_case_loader, copies fuzz/corpus/ to build-fuzz/fuzz/corpus-run/
# (the committed corpus never grows) and runs the fuzzer there. Crashing
# inputs land in build-fuzz/fuzz/artifacts/. Prints the number of executions
# and whether a crash occurred; exits non-zero on a crash.
set -euo pipefail

seconds=${1:?usage: fuzz/run-fuzz.sh SECONDS}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-fuzz
work=$build/fuzz

CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DRSI_FUZZ=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target fuzz_case_loader -j 1

rm -rf "$work/corpus-run"
mkdir -p "$work/corpus-run" "$work/artifacts"
cp "$root"/fuzz/corpus/* "$work/corpus-run/"
rm -f "$work"/fuzz-0.log "$work"/fuzz-parent.log

# -jobs=1: one worker process (the machine's other core is in use); libFuzzer
# writes the worker's output to fuzz-0.log in the current directory, and the
# parent echoes the whole of it at the end (kept in fuzz-parent.log).
cd "$work"
echo "fuzzing for $seconds s; progress: tail -f $work/fuzz-0.log"
set +e
./fuzz_case_loader -max_total_time="$seconds" -jobs=1 -timeout=10 -print_final_stats=1 \
  -dict="$root/fuzz/case.dict" -artifact_prefix="$work/artifacts/" corpus-run \
  >"$work/fuzz-parent.log" 2>&1
status=$?
set -e
log=$work/fuzz-0.log

echo "---- fuzz_case_loader: $seconds s requested, log $log"
grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)' "$log" | tail -2 || true
grep -E '^stat::(average_exec_per_sec|new_units_added|peak_rss_mb)' "$log" || true
crashes=$(grep -cE 'ERROR: (libFuzzer|AddressSanitizer|UndefinedBehaviorSanitizer)|runtime error:|^fuzz_case_loader: ' "$log" || true)
echo "executions: $(grep -oP '^stat::number_of_executed_units: \K[0-9]+' "$log" || echo '?')"
if [ "$status" -ne 0 ] || [ "$crashes" -ne 0 ]; then
  echo "CRASH: exit status $status; see $log and $work/artifacts/"
  grep -E '^fuzz_case_loader: |ERROR: |runtime error:|Test unit written' "$log" | head -20
  exit 1
fi
echo "no crash"
