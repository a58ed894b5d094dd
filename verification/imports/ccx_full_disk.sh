#!/usr/bin/env bash
# A ccx run cut short by a full disk is never cached as a model. ccx 2.20
# exits 0 when its writes fail: on a tmpfs too small for its files it
# leaves job.sti (or job.mas) cut at a page boundary and the files after it
# empty (measured with the deck of brick_deck.py: 447,192-byte .sti and
# .mas; a 300 kB disk cuts the .sti, a 700 kB one the .mas; the .dof,
# written last, is empty). The binary before this test called that a
# failure of the model ("ccx failed on the model (exit status 0 ...)",
# a ".failed" entry), and where the files were cut but not empty (ccx
# stand-in below: job.mas cut mid-line, exit 0) cached them as a complete
# model, so that every later run failed on them ("... are not a component:
# job.mas:N: ...").
#
# Checked: `rsi modes` with --ccx-cache on a small tmpfs (a real ENOSPC)
# and with a ccx stand-in that cuts job.mas after a whole run: exit 2, one
# `rsi: error:` line saying ccx's output was cut short and the disk may be
# full, no cache entry at all (neither whole, ".failed" nor ".tmpPID"), no
# --out. Then with space: ccx runs again and the command succeeds; and an
# entry cut after it was made (its job.mas truncated by hand) is run again,
# giving the same modes.csv, not read as it is.
#
# The tmpfs is mounted in a private mount namespace (`unshare -rm`: a user
# namespace, no root needed where unprivileged user namespaces are
# allowed). `ulimit -f` is no stand-in here: ccx would die of SIGXFSZ
# (its own process), which the tests of rsi's own writes use instead.
# Skipped (exit 77, said) without ccx or unshare, or where the namespace
# or the mount is refused. About 3 s.
# Usage: ccx_full_disk.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
for tool in ccx unshare; do
  if ! command -v "$tool" >/dev/null; then
    echo "skipped: $tool is not on PATH (Debian packages calculix-ccx, util-linux)"
    exit 77
  fi
done
if ! unshare -rm true 2>/dev/null; then
  echo "skipped: unshare -rm (a private user and mount namespace) is refused here"
  exit 77
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
/usr/bin/python3 "$src/verification/imports/brick_deck.py" "$work/brick.inp"
printf '{"component": {"name": "brick", "source": {"calculix_deck": "%s"}, "boundary": {"node_set": "TIP"}, "units": "N, mm, t, s"}}\n' \
  "$work/brick.inp" >"$work/case.json"
cache=$work/cache
mkdir -p "$cache"

# NAME: checks what rsi left after the run whose files are $work/NAME.*.
check_refused() {
  local name=$1 what=$2 status entries
  status=$(cat "$work/$name.status")
  entries=$(tr '\n' ' ' <"$work/$name.entries")
  if [ "$status" -ne 2 ]; then
    fail "$name: exit $status $what, expected 2: $(tail -n 3 "$work/$name.err")"
  elif [ "$(grep -c '^rsi: error:' "$work/$name.err")" -ne 1 ] ||
    ! grep -q "^rsi: error: ccx's output for .* is cut short .*may be full" "$work/$name.err"; then
    fail "$name: not one 'rsi: error: ccx's output ... is cut short ... may be full' line: $(cat "$work/$name.err")"
  elif [ -n "$entries" ]; then
    fail "$name: the cache kept entries: $entries"
  elif [ -e "$work/out-$name" ]; then
    fail "$name: --out left behind"
  else
    echo "ok   $name: $what -> exit 2, $(head -c 170 "$work/$name.err")..., nothing cached"
  fi
}

# SIZE_KB NAME: `rsi modes` with the cache folder on a tmpfs of SIZE_KB.
full_disk_run() {
  local size=$1 name=$2
  unshare -rm bash -c '
    mount -t tmpfs -o size='"$size"'k tmpfs "$1" || exit 90
    "$2" modes "$3" --count 3 --ccx-cache "$1" --out "$4" >"$5.log" 2>"$5.err"
    echo $? >"$5.status"
    ls -A "$1" >"$5.entries"
  ' _ "$cache" "$rsi" "$work/case.json" "$work/out-$name" "$work/$name"
  if [ "$?" -eq 90 ]; then
    echo "skipped: mounting a tmpfs is refused in the namespace"
    exit 77
  fi
  check_refused "$name" "on a $size kB cache disk"
}
full_disk_run 300 sti-cut
full_disk_run 700 mas-cut

# A ccx that cuts job.mas mid-line after a whole run and exits 0: the
# files are all there and not empty, one is cut.
mkdir -p "$work/bin"
cat >"$work/bin/ccx" <<SH
#!/bin/sh
$(command -v ccx) "\$@" || exit \$?
truncate -s 200001 job.mas
SH
chmod +x "$work/bin/ccx"
PATH="$work/bin:$PATH" "$rsi" modes "$work/case.json" --count 3 --ccx-cache "$cache" \
  --out "$work/out-stand-in" >"$work/stand-in.log" 2>"$work/stand-in.err"
echo $? >"$work/stand-in.status"
ls -A "$cache" >"$work/stand-in.entries"
check_refused stand-in "with job.mas cut mid-line by a ccx stand-in (exit 0)"

# Space again: ccx runs, it works.
if "$rsi" modes "$work/case.json" --count 3 --ccx-cache "$cache" --out "$work/out-ok" \
  >"$work/ok.log" 2>"$work/ok.err"; then
  echo "ok   with space: exit 0, $(($(grep -c . "$work/out-ok/modes.csv") - 1)) modes in modes.csv"
else
  fail "with space: exit $? ($(tail -n 2 "$work/ok.err"))"
fi
# An entry cut after it was made: run again, not read.
entry=$(find "$cache" -maxdepth 1 -name '*-matrices' | head -n 1)
if [ -z "$entry" ]; then
  fail "no -matrices entry in the cache after the run with space"
else
  size=$(stat -c %s "$entry/job.mas")
  truncate -s $((size / 2 + 7)) "$entry/job.mas"
  if "$rsi" modes "$work/case.json" --count 3 --ccx-cache "$cache" --out "$work/out-again" \
    >"$work/again.log" 2>"$work/again.err" &&
    [ "$(stat -c %s "$entry/job.mas")" -eq "$size" ] &&
    cmp -s "$work/out-ok/modes.csv" "$work/out-again/modes.csv"; then
    echo "ok   entry cut later: ccx ran again (job.mas $size bytes again), modes.csv the same bytes"
  else
    fail "entry cut later: not rebuilt (job.mas $(stat -c %s "$entry/job.mas") bytes): $(tail -n 2 "$work/again.err")"
  fi
fi
if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "ccx_full_disk: nothing cut short is cached; an entry cut later is rebuilt"
