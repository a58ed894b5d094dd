#!/usr/bin/env bash
# rsi runs on glibc's huge-page heap (cli/support/huge_page_heap.hpp): it
# executes itself (its own path, so the process keeps its name) once more
# with glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES, and not when
# GLIBC_TUNABLES already sets that tunable; the second start gives the
# user's GLIBC_TUNABLES back to the programs rsi starts (the report
# script's python3 here), and malloc then asks for huge pages (madvise
# MADV_HUGEPAGE, checked where the kernel's THP setting is "madvise", the
# one glibc acts on, and not in the sanitizer build, whose allocator is
# AddressSanitizer's). Seen by strace. Skipped (77) without strace or where
# ptrace is not permitted.
# Usage: huge_page_heap.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
command -v strace >/dev/null || { echo "SKIP: strace is not on PATH (Debian package strace)"; exit 77; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! strace -o "$work/probe" true 2>"$work/err"; then
  echo "SKIP: strace cannot trace here: $(head -1 "$work/err")"
  exit 77
fi
exe=$(readlink -f "$rsi")
# LeakSanitizer cannot run under ptrace (it stops the process, exit 1): off
# for these traced runs of the sanitizer build; the rest of its suite checks leaks.
asan=0
if ldd "$rsi" | grep -q libasan; then
  asan=1
  export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
fi
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
# NAME EXPECTED_EXECVES EXPECTED_TUNABLES [VAR=VALUE | -u VAR]: rsi --help under strace.
check() {
  local name=$1 expected=$2 tunables=$3
  shift 3
  env "$@" strace -f -v -s 400 -e trace=execve -o "$work/$name.trace" "$rsi" --help >"$work/$name.out" 2>&1 ||
    fail "$name: rsi --help exited $?: $(cat "$work/$name.out")"
  local calls
  calls=$(grep -c 'execve(' "$work/$name.trace")
  [ "$calls" -eq "$expected" ] || fail "$name: $calls execve calls, expected $expected: $(cat "$work/$name.trace")"
  if [ "$expected" -eq 2 ]; then
    sed -n 2p "$work/$name.trace" | grep "execve(\"$exe\"" | grep -q "\"GLIBC_TUNABLES=$tunables\"" ||
      fail "$name: the second execve is not of $exe with GLIBC_TUNABLES=$tunables: $(cat "$work/$name.trace")"
  fi
  grep -q . "$work/$name.out" || fail "$name: rsi --help printed nothing"
  echo "$name: $calls execve calls"
}
check unset 2 glibc.malloc.hugetlb=1 -u GLIBC_TUNABLES
check other_tunable 2 glibc.malloc.arena_max=4:glibc.malloc.hugetlb=1 GLIBC_TUNABLES=glibc.malloc.arena_max=4
check user_off 1 "" GLIBC_TUNABLES=glibc.malloc.hugetlb=0
check user_on 1 "" GLIBC_TUNABLES=glibc.malloc.hugetlb=1

# A campaign of the paper's case (2 ms, CB-10) with its report: the heap's
# madvise calls, and the report script's environment.
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/batailly2007.json" "$work/tiny.json" \
  time.duration=0.002 'campaign=[{"method": "cb", "modes": [10]}]'
GLIBC_TUNABLES=glibc.malloc.arena_max=4 strace -f -v -s 400 -e trace=execve,madvise -o "$work/campaign.trace" \
  "$rsi" campaign "$work/tiny.json" --out "$work/campaign" >"$work/campaign.out" 2>&1 ||
  fail "campaign exited $?: $(cat "$work/campaign.out")"
grep -q "execve(\"$exe\".*\"RSI_USER_GLIBC_TUNABLES==glibc.malloc.arena_max=4\"" "$work/campaign.trace" ||
  fail "campaign: the second execve does not carry the user's GLIBC_TUNABLES in RSI_USER_GLIBC_TUNABLES"
python_calls=$(grep -c 'execve("/usr/bin/python3"' "$work/campaign.trace")
[ "$python_calls" -ge 1 ] || fail "campaign: no report script started"
if grep 'execve("/usr/bin/python3"' "$work/campaign.trace" | grep -q 'hugetlb\|RSI_USER_GLIBC_TUNABLES'; then
  fail "campaign: the report script got rsi's tunable or marker: $(grep 'execve("/usr/bin/python3"' "$work/campaign.trace")"
fi
grep 'execve("/usr/bin/python3"' "$work/campaign.trace" | grep -q '"GLIBC_TUNABLES=glibc.malloc.arena_max=4"' ||
  fail "campaign: the report script did not get the user's GLIBC_TUNABLES"
advised=$(grep -c MADV_HUGEPAGE "$work/campaign.trace")
thp=/sys/kernel/mm/transparent_hugepage/enabled
if [ "$asan" -eq 1 ]; then
  echo "campaign: madvise not checked (AddressSanitizer's allocator replaces glibc's malloc); $python_calls python3 starts"
elif [ -r "$thp" ] && grep -q '\[madvise\]' "$thp"; then
  [ "$advised" -ge 1 ] || fail "campaign: no madvise(MADV_HUGEPAGE) with the kernel's THP on madvise"
  echo "campaign: $advised madvise(MADV_HUGEPAGE) calls, $python_calls python3 starts with the user's GLIBC_TUNABLES"
else
  echo "campaign: madvise not checked (THP setting: $(cat "$thp" 2>/dev/null || echo unreadable)); $python_calls python3 starts"
fi
[ "$failures" -eq 0 ] && echo "huge_page_heap: all checks passed"
[ "$failures" -eq 0 ]
