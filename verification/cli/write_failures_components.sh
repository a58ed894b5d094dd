#!/usr/bin/env bash
# A write that fails is an error, never a truncated file published with
# exit 0 (issue 13, class 3), for the commands of a component case, which
# share the writers of cli/output_files with the paper's (write_failures.sh
# checks those): `modes`, `modal-campaign`, and the rubbing `simulate` and
# `campaign` on the gmsh blade (data/cases/blade3d*.json). As there, the
# file-size limit stands in for a full disk (SIGXFSZ ignored: write() fails
# with EFBIG as with ENOSPC). Each command must exit 2 with one `rsi:
# error:` line naming the file, leave no temporary or staging file, and
# leave the previous output of the same names as it was (or, on a fresh
# --out, no --out at all). The ccx cache is filled before any limit.
# About 20 s in Release (17-20 s measured on a shared 2-core machine).
# SANITIZED = 1 (an ASan/UBSan build): the blade's coarser mesh (element
# size 20, 2,091 dofs; the writers and the limits' arithmetic are the same:
# the files' sizes follow the counts, the rows and the columns, not the
# mesh): 192 s there on the default mesh (this session's sanitizer suite).
# Skipped (exit 77) without gmsh or ccx.
# Usage: write_failures_components.sh RSI SOURCE_DIR CCX_CACHE [SANITIZED]
set -u
rsi=$1
src=$2
cache=$3
sanitized=${4:-0}
. "$(dirname "$0")/skip_without_gmsh_ccx.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
variant() { /usr/bin/python3 "$src/verification/cli/case_variant.py" "$@"; }
mesh=()
[ "$sanitized" = 1 ] && mesh=('component.source.gmsh_blade.element_size=20.0')
blade=$work/blade.json
variant "$src/data/cases/blade3d.json" "$blade" "${mesh[@]}"
variant "$blade" "$work/modal.json" \
  'modal_campaign={"methods": ["cb", "macneal"], "modes": [5, 10], "frequencies": 20}'
# Rubbing: the reference over 0.05 revolution (its history about 23 kB), the
# runs over 0.1 (about 46 kB).
variant "$src/data/cases/blade3d-rubbing.json" "$work/rubbing.json" rubbing.revolutions=0.1 \
  rubbing.campaign.full_revolutions=0.05 'rubbing.campaign.runs=[{"method": "cb", "modes": [10]}]' \
  "${mesh[@]}"
cache_args=(--ccx-cache "$cache")
failures=0
fail() {
  echo "FAIL $*"
  failures=$((failures + 1))
}
# shellcheck source=file_size_limit.sh
source "$src/verification/cli/file_size_limit.sh"
check() { # NAME EXPECTED_FILE_PATTERN STATUS DIR
  local name=$1 pattern=$2 status=$3 dir=$4
  if [ "$status" -ne 2 ]; then
    fail "$name: exit $status, expected 2; stderr: $(cat "$work/err")"
  elif [ "$(grep -c '^rsi: error:' "$work/err")" -ne 1 ] ||
    ! grep -q "^rsi: error: .*$pattern.*cannot write" "$work/err"; then
    fail "$name: not one 'rsi: error:' line naming $pattern: $(cat "$work/err")"
  elif [ -n "$(find "$work" \( -name '*.tmp[0-9]*' -o -name '.rsi-*' \) 2>/dev/null)" ]; then
    fail "$name: temporary files left: $(find "$work" \( -name '*.tmp[0-9]*' -o -name '.rsi-*' \))"
  else
    echo "ok   $name: exit 2, $(head -c 160 "$work/err")"
  fi
}
# NAME DIR: DIR is as DIR.before was.
untouched() {
  if diff -r "$2" "$2.before" >/dev/null; then
    echo "ok   $1: the previous output untouched ($(cd "$2" && find . -type f | sort | tr '\n' ' '))"
  else
    fail "$1: the previous output changed: $(diff -r "$2" "$2.before" | head -n 5)"
  fi
}
# NAME DIR ARGS...: runs rsi ARGS --out DIR without a limit, keeps a copy.
previous() {
  local name=$1 dir=$2
  shift 2
  "$rsi" "$@" --out "$dir" >"$work/log" 2>&1 || fail "$name without a limit failed: $(tail -n 2 "$work/log")"
  cp -r "$dir" "$dir.before"
}

# 1. modes: modes.csv of 100 modes (1.8 kB) over a 1 kB limit; on an
# existing --out, then on a fresh one.
previous modes "$work/modes" modes "$blade" --count 100 "${cache_args[@]}"
limited 1 modes "$blade" --count 100 "${cache_args[@]}" --out "$work/modes"
check "modes over the file-size limit" "modes.csv" $? "$work/modes"
untouched modes "$work/modes"
limited 1 modes "$blade" --count 100 "${cache_args[@]}" --out "$work/modes-fresh"
check "modes over the file-size limit, fresh --out" "modes.csv" $? "$work/modes-fresh"
[ -e "$work/modes-fresh" ] && fail "modes: the fresh --out was left: $(find "$work/modes-fresh")"

# 2. modal-campaign: modal_errors.csv (4 kB) over a 2 kB limit, after
# modal_convergence.csv (0.5 kB) was written.
previous modal-campaign "$work/modal" modal-campaign "$work/modal.json" --no-report "${cache_args[@]}"
limited 2 modal-campaign "$work/modal.json" --no-report "${cache_args[@]}" --out "$work/modal"
check "modal-campaign over the file-size limit" "modal_errors.csv" $? "$work/modal"
untouched modal-campaign "$work/modal"

# 3. simulate (the full reference): the streamed history (46 kB) over 20 kB.
previous simulate "$work/simulate" simulate "$work/rubbing.json" "${cache_args[@]}"
limited 20 simulate "$work/rubbing.json" "${cache_args[@]}" --out "$work/simulate"
check "simulate over the file-size limit" "history.csv" $? "$work/simulate"
untouched simulate "$work/simulate"

# 4. campaign: the reference's history (23 kB) fits a 30 kB limit, CB-10's
# (46 kB, written after its run) does not: the campaign ends with exit 2,
# the reference's staged files are not published.
previous campaign "$work/campaign" campaign "$work/rubbing.json" --no-report "${cache_args[@]}"
limited 30 campaign "$work/rubbing.json" --no-report "${cache_args[@]}" --out "$work/campaign"
check "campaign over the file-size limit" "runs/cb-10/history.csv" $? "$work/campaign"
untouched campaign "$work/campaign"

if [ "$failures" -ne 0 ]; then
  echo "$failures failure(s)"
  exit 1
fi
echo "all write failures reported"
