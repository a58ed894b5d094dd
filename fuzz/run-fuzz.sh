#!/usr/bin/env bash
# Fuzz one target for SECONDS seconds with libFuzzer (one worker).
#
#   fuzz/run-fuzz.sh SECONDS [TARGET]
#
# TARGET: fuzz_case_loader (default; seeds fuzz/corpus/), fuzz_component_loader
# or fuzz_matrix_market (seeds fuzz/corpus-TARGET/). Configures build-fuzz/
# with clang (-DRSI_FUZZ=ON, RelWithDebInfo), builds only TARGET, copies its
# seeds to build-fuzz/fuzz/run-TARGET/corpus-run/ (the committed corpus never
# grows) and runs the fuzzer there. Crashing inputs land in
# build-fuzz/fuzz/run-TARGET/artifacts/. Prints the number of executions and
# whether a crash occurred; exits non-zero on a crash.
set -euo pipefail

seconds=${1:?usage: fuzz/run-fuzz.sh SECONDS [TARGET]}
target=${2:-fuzz_case_loader}
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-fuzz
work=$build/fuzz/run-$target
seeds=$root/fuzz/corpus-$target
dict=()
if [ "$target" = fuzz_case_loader ]; then
  seeds=$root/fuzz/corpus
  dict=(-dict="$root/fuzz/case.dict")
fi

CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DRSI_FUZZ=ON \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$build" --target "$target" -j 1

rm -rf "$work/corpus-run"
mkdir -p "$work/corpus-run" "$work/artifacts"
cp "$seeds"/* "$work/corpus-run/"
rm -f "$work"/fuzz-0.log "$work"/fuzz-parent.log

# -jobs=1: one worker process (the machine's other core is in use); libFuzzer
# writes the worker's output to fuzz-0.log in the current directory, and the
# parent echoes the whole of it at the end (kept in fuzz-parent.log).
cd "$work"
echo "fuzzing for $seconds s; progress: tail -f $work/fuzz-0.log"
set +e
"$build/fuzz/$target" -max_total_time="$seconds" -jobs=1 -timeout=10 -print_final_stats=1 \
  "${dict[@]}" -artifact_prefix="$work/artifacts/" corpus-run \
  >"$work/fuzz-parent.log" 2>&1
status=$?
set -e
log=$work/fuzz-0.log

echo "---- $target: $seconds s requested, log $log"
grep -E '^#[0-9]+[[:space:]]+(INITED|DONE)' "$log" | tail -2 || true
grep -E '^stat::(average_exec_per_sec|new_units_added|peak_rss_mb)' "$log" || true
crashes=$(grep -cE "ERROR: (libFuzzer|AddressSanitizer|UndefinedBehaviorSanitizer)|runtime error:|^$target: " "$log" || true)
echo "executions: $(grep -oP '^stat::number_of_executed_units: \K[0-9]+' "$log" || echo '?')"
if [ "$status" -ne 0 ] || [ "$crashes" -ne 0 ]; then
  echo "CRASH: exit status $status; see $log and $work/artifacts/"
  grep -E "^$target: |ERROR: |runtime error:|Test unit written" "$log" | head -20
  exit 1
fi
echo "no crash"
