#!/usr/bin/env bash
# Out of memory is an error like any other (issue 13, classes 5 and 8):
# under a sweep of memory limits every command either completes (exit 0)
# or stops with exit 1 and one line `rsi: error: out of memory ...`, never
# dies by a signal (std::terminate from a thread, a double free, a
# destructor throwing during the unwinding), never prints a sanitizer
# report, and leaves --out byte for byte as it was (the staged-output
# rule, README).
#
# The limits: in the sanitizer build, AddressSanitizer's own allocator
# (allocator_may_return_null=1, max_allocation_size_mb=N: every single
# allocation above N MB fails; AddressSanitizer reserves terabytes of
# address space, so `ulimit -v` cannot be used with it; its expected
# "WARNING: AddressSanitizer failed to allocate" line is no report, an
# "ERROR:" or "SUMMARY:" line or a UBSan "runtime error:" is; a command
# with no allocation above 1 MB cannot fail there and is only noted, and
# so is a failed operator new, which GCC's AddressSanitizer reports and
# exits on instead of throwing std::bad_alloc); in any other
# build, verification/cli/heap_limit.c preloaded: one allocation above N MB,
# or the live heap above N MB, fails. Not `ulimit -v`: the address-space
# limit fails OpenBLAS's and libgomp's reservations first, and those
# libraries hang or exit without a status (heap_limit.c says which).
#
# A command that completes under a one-allocation limit with no allocation
# refused is not run again under the larger ones: each would make the same
# allocations, none above the limit, and run the same (the whole-heap
# limits are swept to the end: the live heap depends on the threads).
#
# Commands: `rsi campaign` of the paper's case shortened to 5 ms, with
# one reduced run of each kind the case's campaign holds (Guyan, CB, CCM,
# the families, forced and participation selections, a reduced casing, a
# run at its own step: 8 runs and the reference on 2 threads; the whole
# 164-run list repeats the same allocations 20 times over and made this
# the longest test of the suite), `rsi simulate` (full, CB-10), `rsi modes`,
# `rsi reduce` (CCM-20), on the paper's case and on a refined one (casing
# n_elements 1000, 4,000 dofs: allocations of up to 131 MB, the reduced
# integrator's dense casing-plus-basis matrix), and a short
# rubbing campaign of the gmsh blade when its matrices can be made (gmsh,
# ccx on PATH; else that part is skipped, and says so). Every command must
# fail at least once in the sweep (else the sweep tests nothing) and
# complete at its largest limit or without one. No out-of-memory stop may
# print `std::bad_alloc`: a campaign worker that reported its run failed
# for lack of memory (`cb-8 std::bad_alloc`) and went on made exit 3 with
# its output published whenever the rest of the campaign found memory
# again; the campaign is swept with heap limits of 5-7 MB too, where its
# two workers run out in the middle of their runs.
# Usage: memory_limits.sh RSI SOURCE_DIR HEAP_LIMIT_LIBRARY CCX_CACHE
set -u
rsi=$1
src=$2
heap_limit_library=$3
ccx_cache=$4
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ldd "$rsi" | grep -q libasan; then
  mode=asan
elif [ -f "$heap_limit_library" ]; then
  mode=preload
else
  echo "skipped: $rsi is not sanitized and the heap-limit library $heap_limit_library was not built"
  exit 77
fi
echo "memory limits by $([ $mode = asan ] && echo "AddressSanitizer's allocator" || echo "$heap_limit_library")"

variant() { # NAME BASE KEY=JSON...
  local name=$1 base=$2
  shift 2
  /usr/bin/python3 "$src/verification/cli/case_variant.py" "$base" "$work/$name.json" "$@"
}
paper=$src/data/cases/batailly2007.json
variant short "$paper" time.duration=0.005
variant short_campaign "$work/short.json" 'campaign=[{"method": "guyan", "modes": [0]}, {"method": "cb", "modes": [10]}, {"method": "ccm", "modes": [20]}, {"method": "cb", "modes": [44], "selection": "families"}, {"method": "ccm", "modes": [44], "selection": "forced"}, {"method": "cb", "modes": [44], "selection": "participation"}, {"method": "ccm", "modes": [44], "casing_modes": [20]}, {"method": "cb", "modes": [44], "casing_modes": [40], "time_step": ["own"]}]'
variant refined "$paper" time.step=1e-8 time.duration=1e-5 time.output_every=10 casing.n_elements=1000 'campaign=[{"method": "cb", "modes": [10]}]'

failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
# Every path under DIR with the checksum of each file (hidden ones too).
listing() {
  (cd "$1" && find . | LC_ALL=C sort | while read -r p; do
    if [ -f "$p" ]; then echo "$p $(sha256sum <"$p" | cut -c1-64)"; else echo "$p"; fi
  done)
}
# KIND MB COMMAND...: the command under the limit (KIND: allocation or heap).
limited() {
  local kind=$1 mb=$2
  shift 2
  if [ "$mode" = asan ]; then
    ASAN_OPTIONS="allocator_may_return_null=1:max_allocation_size_mb=$mb${ASAN_OPTIONS:+:$ASAN_OPTIONS}" "$@"
  elif [ "$kind" = allocation ]; then
    LD_PRELOAD=$heap_limit_library RSI_HEAP_LIMIT_REPORT=$work/refused RSI_MAX_ALLOCATION_MB=$mb "$@"
  else
    LD_PRELOAD=$heap_limit_library RSI_HEAP_LIMIT_REPORT=$work/refused RSI_HEAP_LIMIT_MB=$mb "$@"
  fi
}
# Whether the last limited run had an allocation refused (AddressSanitizer
# says so on stderr; heap_limit.c in $work/refused).
limit_met() {
  if [ "$mode" = asan ]; then
    grep -q 'AddressSanitizer failed to allocate' "$work/err"
  else
    [ -s "$work/refused" ]
  fi
}

# NAME OUT COMMAND...: the command once without a limit (it must complete:
# its output is what a failed run must leave), then under each limit of
# $limits (MB).
limits="1 2 4 8 16 32 64 128 256"
sweep() {
  local name=$1 out=$2
  shift 2
  mkdir -p "$out"
  echo "my notes" >"$out/notes.txt"
  if ! "$@" --out "$out" >"$work/log" 2>"$work/err"; then
    fail "$name without a limit: $(tail -n 2 "$work/err")"
    return
  fi
  local before failures_before=$failures
  before=$(listing "$out")
  local kinds=(allocation)
  [ "$mode" = preload ] && kinds+=(heap)
  local kind mb failed=0 completed_last=0
  for kind in "${kinds[@]}"; do
    for mb in $limits; do
      rm -f "$work/refused"
      limited "$kind" "$mb" "$@" --out "$out" >"$work/log" 2>"$work/err"
      local status=$?
      local what="$name, $kind limit $mb MB"
      completed_last=0
      if [ "$status" -eq 0 ]; then
        completed_last=1
        before=$(listing "$out") # a completed run publishes its set
        if [ "$kind" = allocation ] && ! limit_met; then
          # No allocation was refused, so none was above $mb MB: under any
          # larger one-allocation limit the command makes the same
          # allocations, none refused, and runs as it just did (it
          # completes at the largest limit). The whole-heap limit depends
          # on the threads' interleaving and is swept to the end.
          echo "note $what: completed with no allocation refused; the larger allocation limits run the same"
          break
        fi
        continue
      fi
      if [ "$mode" = asan ] && grep -q 'ERROR: AddressSanitizer: allocator is out of memory' "$work/err" &&
        grep -A1 'allocator is out of memory' "$work/err" | grep -q '#0 .* in operator new' &&
        [ "$(grep -c 'ERROR: .*Sanitizer' "$work/err")" -eq 1 ]; then
        # GCC's AddressSanitizer reports a failed throwing operator new and
        # exits instead of throwing std::bad_alloc (allocator_may_return_null
        # covers malloc and nothrow new only): no unwinding happens, so this
        # run tests nothing of rsi's; its staging folder and lock file are
        # left as after a kill and removed by the next command (README).
        echo "note $what: AddressSanitizer's operator new exits instead of throwing"
        rm -rf "$out"/.rsi-*
        continue
      fi
      failed=$((failed + 1))
      if [ "$status" -ge 128 ]; then
        fail "$what: killed by signal $((status - 128)): $(tail -n 3 "$work/err")"
      elif grep -q 'ERROR: .*Sanitizer\|SUMMARY: .*Sanitizer\|runtime error:' "$work/err"; then
        fail "$what: sanitizer report: $(grep -m 3 'Sanitizer\|runtime error:\|#[0-9]' "$work/err")"
      elif [ "$status" -ne 1 ]; then
        fail "$what: exit $status, expected 1 (out of memory): $(tail -n 2 "$work/err")"
      elif [ "$(grep -c '^rsi: error:' "$work/err")" -ne 1 ]; then
        fail "$what: not one 'rsi: error:' line: $(cat "$work/err")"
      elif ! grep -q '^rsi: error: out of memory' "$work/err"; then
        fail "$what: the error does not name memory: $(grep '^rsi: error:' "$work/err")"
      elif grep -q 'bad_alloc' "$work/err"; then
        fail "$what: a run reported failed for lack of memory, and the command went on: $(grep -m 3 'bad_alloc' "$work/err")"
      elif [ "$(listing "$out")" != "$before" ]; then
        fail "$what: --out changed: $(diff <(echo "$before") <(listing "$out") | head -n 5)"
      fi
    done
    [ "$completed_last" -eq 1 ] || fail "$name: did not complete at the largest $kind limit (exit $status)"
  done
  if [ "$failed" -eq 0 ] && [ "$mode" = asan ]; then
    # AddressSanitizer limits single allocations (1 MB at least), and this
    # command makes none above 1 MB: the Release build's whole-heap limit
    # sweeps it.
    echo "note $name: no allocation above 1 MB, nothing to fail under AddressSanitizer's limit"
  elif [ "$failed" -eq 0 ]; then
    fail "$name: no limit of the sweep made it fail: the sweep tests nothing"
  elif [ "$failures" -eq "$failures_before" ]; then
    echo "ok   $name: $failed limits failed cleanly (exit 1, one out-of-memory line, --out untouched)"
  fi
}

# The heap limits of 5-7 MB stop the campaign's workers mid-run; under
# AddressSanitizer (single allocations only) they add nothing but time.
# Under AddressSanitizer every other power of two (1, 4, ..., 256 MB): a
# limit fails a command at its first allocation above it, and the limits
# left out fail it at other allocations of the same calls; all nine took
# 341 s there (session 19's rehearsal). The Release build sweeps them all.
campaign_limits="1 2 4 8 16 32 64 128 256"
if [ "$mode" = preload ]; then
  campaign_limits="1 2 4 5 6 7 8 16 32 64 128 256"
else
  limits="1 4 16 64 256"
  campaign_limits=$limits
fi
limits=$campaign_limits sweep "campaign" "$work/campaign" "$rsi" campaign "$work/short_campaign.json" --no-report
sweep "simulate full" "$work/simulate-full" "$rsi" simulate "$work/short.json" --method full
sweep "simulate cb-10" "$work/simulate-cb" "$rsi" simulate "$work/short.json" --method cb --modes 10
sweep "modes" "$work/modes" "$rsi" modes "$paper" --count 20
sweep "reduce ccm-20" "$work/reduce" "$rsi" reduce "$paper" --method ccm --modes 20
sweep "refined simulate cb-10" "$work/refined-cb" "$rsi" simulate "$work/refined.json" --method cb --modes 10
sweep "refined modes" "$work/refined-modes" "$rsi" modes "$work/refined.json" --part casing --count 10

if command -v gmsh >/dev/null && command -v ccx >/dev/null; then
  variant rubbing "$src/data/cases/blade3d-rubbing.json" rubbing.revolutions=0.02 \
    'rubbing.campaign={"runs": [{"method": "macneal", "modes": [10]}, {"method": "cb", "modes": [10]}], "full_revolutions": 0.02}'
  sweep "rubbing campaign" "$work/rubbing" "$rsi" campaign "$work/rubbing.json" --no-report \
    --ccx-cache "$ccx_cache"
else
  echo "skipped: the rubbing campaign (gmsh or ccx not on PATH)"
fi

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "every out-of-memory stop was clean"
