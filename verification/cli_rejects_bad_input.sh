#!/usr/bin/env bash
# Bad input to the CLI: exit status 2, one message line starting
# "rsi: error:" that names the file, key or option and what is allowed, and
# no output left behind: neither a file nor the (empty) --out directory
# (SPEC §2, §5). Every subcommand gets every category that applies to it:
# case file missing, a directory, unreadable, truncated or empty, an unknown
# key, a missing key, a wrong type, a value out of range; an unwritable
# --out; an unknown option; and the options of each subcommand with a
# non-numeric, out-of-range or unknown value.
# Usage: cli_rejects_bad_input.sh RSI SOURCE_DIR [TABLE.md]
# Prints one line per case (exit status and message); with TABLE.md, also
# writes them there as a Markdown table.
set -u
rsi=$1
src=$2
table=${3:-}
work=$(mktemp -d)
trap 'chmod -R u+rwx "$work" 2>/dev/null; rm -rf "$work"' EXIT
failures=0
passes=0
rows=()

# Command line as shown in the table: scratch and source paths shortened.
shown() {
  local text="$*"
  text=${text//$rsi/rsi}
  text=${text//$work/WORK}
  text=${text//$src/SRC}
  printf '%s' "$text"
}

# expect STATUS FRAGMENT -- COMMAND...: runs the command, checks the exit
# status, that stderr is one line starting "rsi: error:" (for status 2) and
# contains FRAGMENT, and that $work/out does not exist afterwards.
expect() {
  local status=$1 fragment=$2
  shift 3
  rm -rf "$work/out"
  "$@" >"$work/stdout" 2>"$work/stderr"
  local got=$?
  local message lines
  message=$(head -c 600 "$work/stderr" | tr '\n' ' ' | sed 's/ *$//')
  lines=$(wc -l <"$work/stderr")
  local problem=""
  [ "$got" -eq "$status" ] || problem="exit $got, expected $status"
  if [ "$status" -eq 2 ]; then
    [ "$lines" -eq 1 ] || problem="$problem; $lines lines on stderr, expected 1"
    case "$message" in "rsi: error: "*) ;; *) problem="$problem; no 'rsi: error:' prefix" ;; esac
  fi
  cat "$work/stdout" "$work/stderr" | grep -qF -- "$fragment" || problem="$problem; no \"$fragment\""
  if [ -e "$work/out" ]; then
    local left
    left=$(find "$work/out" | head -3 | tr '\n' ' ')
    problem="$problem; left behind: $left"
  fi
  local command
  command=$(shown "$@")
  if [ -z "$problem" ]; then
    passes=$((passes + 1))
    printf 'ok   exit %d | %s | %s\n' "$got" "$command" "$(shown "$message")"
  else
    failures=$((failures + 1))
    printf 'FAIL exit %d | %s | %s\n     %s\n' "$got" "$command" "$(shown "$message")" "$problem"
  fi
  rows+=("| \`$command\` | $got | $(shown "$message" | sed 's/|/\\|/g') |")
}

skip() {
  printf 'skip %s\n' "$*"
  rows+=("| (skipped) | - | $* |")
}

good=$src/data/cases/batailly2007.json
printf '{"material": {"young_modulus": 2' >"$work/truncated.json"
: >"$work/empty.json"
mkdir "$work/a-directory.json"
printf 'not a directory\n' >"$work/regular-file"
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
variant("no-campaign", lambda d: d.pop("campaign"))
variant("campaign-too-many", lambda d: d.update(campaign=[{"method": "cb", "modes": [0, 700]}]))
variant("campaign-guyan-modes", lambda d: d.update(campaign=[{"method": "guyan", "modes": [3]}]))
variant("campaign-method", lambda d: d.update(campaign=[{"method": "modal", "modes": [0]}]))
PY
cp "$good" "$work/unreadable.json"
chmod 000 "$work/unreadable.json"

# The arguments each subcommand needs besides the case file.
declare -A needs=(
  [modes]="" [export]="" [calibrate]="" [reduce]="--method cb" [simulate]="" [campaign]=""
)
for cmd in modes export calibrate reduce simulate campaign; do
  # shellcheck disable=SC2206
  extra=(${needs[$cmd]})
  out=(--out "$work/out")
  [ "$cmd" = calibrate ] && out=()  # calibrate writes nothing
  expect 2 "no-such-file.json': no such file" -- "$rsi" "$cmd" "$work/no-such-file.json" "${extra[@]}" "${out[@]}"
  expect 2 "a-directory.json' is a directory" -- "$rsi" "$cmd" "$work/a-directory.json" "${extra[@]}" "${out[@]}"
  if [ -r "$work/unreadable.json" ]; then
    skip "$cmd, case file chmod 000: running as uid $(id -u), which reads it anyway (the directory case above stands in)"
  else
    expect 2 "unreadable.json: cannot open the case file" -- "$rsi" "$cmd" "$work/unreadable.json" "${extra[@]}" "${out[@]}"
  fi
  expect 2 "truncated.json: malformed JSON" -- "$rsi" "$cmd" "$work/truncated.json" "${extra[@]}" "${out[@]}"
  expect 2 "empty.json: malformed JSON" -- "$rsi" "$cmd" "$work/empty.json" "${extra[@]}" "${out[@]}"
  expect 2 "casing.n_nodes': unknown key" -- "$rsi" "$cmd" "$work/unknown.json" "${extra[@]}" "${out[@]}"
  expect 2 "bladed_disk.tip_radius': missing" -- "$rsi" "$cmd" "$work/missing.json" "${extra[@]}" "${out[@]}"
  expect 2 "material.density': must be a number" -- "$rsi" "$cmd" "$work/type.json" "${extra[@]}" "${out[@]}"
  expect 2 "bladed_disk.blade_section.thickness': must be in (0, inf) m" -- "$rsi" "$cmd" "$work/range.json" "${extra[@]}" "${out[@]}"
  expect 2 "--bogus" -- "$rsi" "$cmd" "$good" "${extra[@]}" --bogus 1 "${out[@]}"
  expect 2 "case is required" -- "$rsi" "$cmd" "${extra[@]}" "${out[@]}"
  if [ "$cmd" != calibrate ]; then
    expect 2 "--out $work/regular-file/out: cannot create the output directory" -- "$rsi" "$cmd" "$good" "${extra[@]}" --out "$work/regular-file/out"
    expect 2 "--out /proc/rsi-cannot-write-here" -- "$rsi" "$cmd" "$good" "${extra[@]}" --out /proc/rsi-cannot-write-here
    expect 2 "--out: must be a directory path that can be created and written, got ''" -- "$rsi" "$cmd" "$good" "${extra[@]}" --out ""
  fi
done

# A directory that exists but cannot be written (not for root, who can).
mkdir "$work/read-only"
chmod 555 "$work/read-only"
if touch "$work/read-only/probe" 2>/dev/null; then
  rm -f "$work/read-only/probe"
  skip "--out in a chmod 555 directory: running as uid $(id -u), which writes there anyway (/proc above stands in)"
else
  expect 2 "cannot create a file in the output directory" -- "$rsi" modes "$good" --out "$work/read-only"
  expect 2 "read-only/out: cannot create the output directory" -- "$rsi" simulate "$good" --out "$work/read-only/out"
fi

# modes
expect 2 "clearance must be positive" -- "$rsi" modes "$work/clearance.json" --out "$work/out"
expect 2 "--count: must be in [1, 682]" -- "$rsi" modes "$good" --count 1000 --out "$work/out"
expect 2 "--count: must be in [1, 156]" -- "$rsi" modes "$good" --part casing --count 157 --out "$work/out"
expect 2 "--count: must be an integer in [1, the part's number of dofs], got '0'" -- "$rsi" modes "$good" --count 0 --out "$work/out"
expect 2 "--count: must be an integer in [1, the part's number of dofs], got 'many'" -- "$rsi" modes "$good" --count many --out "$work/out"
expect 2 "--count: must be an integer in [1, the part's number of dofs], got '2.5'" -- "$rsi" modes "$good" --count 2.5 --out "$work/out"
expect 2 "--part: must be bladed-disk or casing, got 'rotor'" -- "$rsi" modes "$good" --part rotor --out "$work/out"

# calibrate
expect 2 "--target-hz: must be a finite number of Hz above 0, got 'abc'" -- "$rsi" calibrate "$good" --target-hz abc
expect 2 "--target-hz: must be a finite number of Hz above 0, got '-44'" -- "$rsi" calibrate "$good" --target-hz -44
expect 2 "--target-hz: must be a finite number of Hz above 0, got 'inf'" -- "$rsi" calibrate "$good" --target-hz inf

# reduce
expect 2 "--method is required: cb, ccm, guyan or macneal" -- "$rsi" reduce "$good" --out "$work/out"
expect 2 "--method: must be cb, ccm, guyan or macneal, got 'mac'" -- "$rsi" reduce "$good" --method mac --out "$work/out"
expect 2 "--method: must be cb, ccm, guyan or macneal, got 'full'" -- "$rsi" reduce "$good" --method full --out "$work/out"
expect 2 "--modes: Craig-Bampton takes 0 to 638" -- "$rsi" reduce "$good" --method cb --modes 639 --out "$work/out"
expect 2 "--modes: Craig-Chang-Martinez takes 0 to 638" -- "$rsi" reduce "$good" --method ccm --modes 639 --out "$work/out"
expect 2 "--modes: Guyan reduction keeps no modes" -- "$rsi" reduce "$good" --method guyan --modes 3 --out "$work/out"
expect 2 "--modes: MacNeal takes 1 to 638" -- "$rsi" reduce "$good" --method macneal --modes 0 --out "$work/out"
expect 2 "--modes: must be an integer in [0, the method's maximum]" -- "$rsi" reduce "$good" --method cb --modes ten --out "$work/out"
expect 2 "--modes: must be an integer in [0, the method's maximum]" -- "$rsi" reduce "$good" --method cb --modes -1 --out "$work/out"

# simulate
expect 2 "time.step = 3e-06 s is not below the central-difference stability limit 2/omega_max = 2.50711e-06 s" -- "$rsi" simulate "$work/unstable.json" --out "$work/out"
expect 2 "--method: must be full, cb, ccm or guyan, got 'modal'" -- "$rsi" simulate "$good" --method modal --out "$work/out"
expect 2 "--modes: Craig-Bampton takes 0 to 638" -- "$rsi" simulate "$good" --method cb --modes 639 --out "$work/out"
expect 2 "--modes: Craig-Chang-Martinez takes 0 to 638" -- "$rsi" simulate "$good" --method ccm --modes 700 --out "$work/out"
expect 2 "--modes: Guyan reduction keeps no modes" -- "$rsi" simulate "$good" --method guyan --modes 2 --out "$work/out"
expect 2 "--modes: must be an integer in [0, the method's maximum]" -- "$rsi" simulate "$good" --method cb --modes 1e3 --out "$work/out"
expect 2 "--full-field: only for the reduced methods" -- "$rsi" simulate "$good" --method full --full-field --out "$work/out"

# campaign
expect 2 "--jobs: must be an integer in [1, 64], got '0'" -- "$rsi" campaign "$good" --jobs 0 --out "$work/out"
expect 2 "--jobs: must be an integer in [1, 64], got '65'" -- "$rsi" campaign "$good" --jobs 65 --out "$work/out"
expect 2 "--jobs: must be an integer in [1, 64], got 'two'" -- "$rsi" campaign "$good" --jobs two --out "$work/out"
expect 2 "--target-e2: must be a finite number above 0, got 'small'" -- "$rsi" campaign "$good" --target-e2 small --out "$work/out"
expect 2 "--target-e2: must be a finite number above 0, got '-0.1'" -- "$rsi" campaign "$good" --target-e2 -0.1 --out "$work/out"
expect 2 "key 'campaign': missing or empty" -- "$rsi" campaign "$work/no-campaign.json" --out "$work/out"
expect 2 "key 'campaign': cb with 700 modes: must be in [0, 638]" -- "$rsi" campaign "$work/campaign-too-many.json" --out "$work/out"
expect 2 "key 'campaign': guyan with 3 modes: must be in [0, 0]" -- "$rsi" campaign "$work/campaign-guyan-modes.json" --out "$work/out"
expect 2 "campaign[0].method': must be \"cb\", \"ccm\" or \"guyan\"" -- "$rsi" campaign "$work/campaign-method.json" --out "$work/out"

# no or unknown subcommand; help
expect 2 "frobnicate" -- "$rsi" frobnicate "$good"
expect 2 "a subcommand is required" -- "$rsi"
expect 0 "--count" -- "$rsi" modes --help

echo "$passes passed, $failures failed"
if [ -n "$table" ]; then
  {
    echo "| command | exit | message (stderr) |"
    echo "|---|---|---|"
    printf '%s\n' "${rows[@]}"
  } >"$table"
fi
[ "$failures" -eq 0 ]
