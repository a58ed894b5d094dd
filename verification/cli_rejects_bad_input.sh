#!/usr/bin/env bash
# Bad input to the CLI: exit status 2, a message naming the file, key or
# option, and no output file written (SPEC §2, §5).
# Usage: cli_rejects_bad_input.sh RSI SOURCE_DIR
set -u
rsi=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
passes=0

# expect STATUS FRAGMENT -- COMMAND...: runs the command in $work, checks the
# exit status, that stderr contains FRAGMENT, and that $work/out stays empty.
expect() {
  local status=$1 fragment=$2
  shift 3
  rm -rf "$work/out"
  "$@" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  local message
  message=$(head -c 400 "$work/stderr" | tr '\n' ' ')
  local leftover=""
  [ -d "$work/out" ] && leftover=$(find "$work/out" -type f | head -3)
  if [ "$got" -eq "$status" ] && cat "$work/stdout" "$work/stderr" | grep -qF -- "$fragment" && [ -z "$leftover" ]; then
    passes=$((passes + 1))
    printf 'ok   exit %d: %s\n' "$got" "$message"
  else
    failures=$((failures + 1))
    printf 'FAIL %s\n     expected exit %d and "%s"; got exit %d: %s; files left: %s\n' "$*" "$status" "$fragment" "$got" "$message" "$leftover"
  fi
}

good=$src/data/cases/batailly2007.json
printf '{"material": {"young_modulus": 2' >"$work/truncated.json"
/usr/bin/python3 - "$good" "$work" <<'PY'
import json, sys
good, work = sys.argv[1], sys.argv[2]
def variant(name, change):
    d = json.load(open(good)); change(d); json.dump(d, open(f"{work}/{name}.json", "w"))
variant("unknown", lambda d: d["casing"].update(n_nodes=40))
variant("missing", lambda d: d["bladed_disk"].pop("tip_radius"))
variant("type", lambda d: d["material"].update(density="steel"))
variant("range", lambda d: d["bladed_disk"]["blade_section"].update(thickness=-0.002))
variant("clearance", lambda d: d["casing"].update(radius=0.499))
variant("unstable", lambda d: d["time"].update(step=3e-6))
PY

expect 2 "no-such-file.json" -- "$rsi" modes "$work/no-such-file.json" --out "$work/out"
expect 2 "malformed JSON" -- "$rsi" modes "$work/truncated.json" --out "$work/out"
expect 2 "casing.n_nodes': unknown key" -- "$rsi" modes "$work/unknown.json" --out "$work/out"
expect 2 "bladed_disk.tip_radius': missing" -- "$rsi" export "$work/missing.json" --out "$work/out"
expect 2 "material.density': must be a number" -- "$rsi" modes "$work/type.json" --out "$work/out"
expect 2 "bladed_disk.blade_section.thickness': must be in (0, inf) m" -- "$rsi" export "$work/range.json" --out "$work/out"
expect 2 "clearance must be positive" -- "$rsi" modes "$work/clearance.json" --out "$work/out"
expect 2 "--count: must be in [1, 682]" -- "$rsi" modes "$good" --count 1000 --out "$work/out"
expect 2 "--count: must be in [1, 156]" -- "$rsi" modes "$good" --part casing --count 0 --out "$work/out"
expect 2 "--part: must be bladed-disk or casing" -- "$rsi" modes "$good" --part rotor --out "$work/out"
expect 2 "--count" -- "$rsi" modes "$good" --count many --out "$work/out"
expect 2 "frobnicate" -- "$rsi" frobnicate "$good"
expect 2 "case is required" -- "$rsi" modes
expect 2 "cannot create the output directory" -- "$rsi" modes "$good" --out /proc/rsi-cannot-write-here
expect 2 "a subcommand is required" -- "$rsi"
expect 2 "time.step = 3e-06 s is not below the central-difference stability limit 2/omega_max = 2.50711e-06 s" -- "$rsi" simulate "$work/unstable.json" --out "$work/out"
expect 2 "--method: must be full, cb, ccm or guyan" -- "$rsi" simulate "$good" --method modal --out "$work/out"
expect 2 "--modes: Craig-Bampton takes 0 to 638" -- "$rsi" reduce "$good" --method cb --modes 639 --out "$work/out"
expect 2 "--modes: Craig-Chang-Martinez takes 0 to 638" -- "$rsi" simulate "$good" --method ccm --modes 700 --out "$work/out"
expect 2 "--modes: Guyan reduction keeps no modes" -- "$rsi" reduce "$good" --method guyan --modes 3 --out "$work/out"
expect 2 "--method: must be full, cb, ccm or guyan" -- "$rsi" reduce "$good" --method mac --out "$work/out"
expect 0 "--count" -- "$rsi" modes --help

echo "$passes passed, $failures failed"
[ "$failures" -eq 0 ]
