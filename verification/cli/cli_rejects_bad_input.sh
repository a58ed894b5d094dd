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
variant("largest-casing", lambda d: d["casing"].update(n_elements=100000))
variant("fine-casing", lambda d: d["casing"].update(n_elements=4000))
variant("casing-2000", lambda d: (d["casing"].update(n_elements=2000), d["time"].update(step=5e-9, duration=5e-6), d.update(campaign=[{"method": "cb", "modes": [10, 20]}])))
variant("wide-disk", lambda d: (d["bladed_disk"].update(n_blades=200, n_blade_elements=72), d["time"].update(step=1e-7, duration=1e-5), d.update(campaign=[{"method": "cb", "modes": [1000]}])))
variant("largest-resolved-casing", lambda d: (d["casing"].update(n_elements=10000), d["time"].update(step=5e-10, duration=5e-9)))
variant("thin-blades", lambda d: d["bladed_disk"]["blade_section"].update(thickness=1e-8))
variant("thin-casing", lambda d: d["casing"]["section"].update(thickness=1e-7))
variant("curled", lambda d: d["bladed_disk"].update(n_blade_elements=1000, kink_angle_deg=1.8))
variant("no-campaign", lambda d: d.pop("campaign"))
variant("campaign-too-many", lambda d: d.update(campaign=[{"method": "cb", "modes": [0, 700]}]))
variant("campaign-guyan-modes", lambda d: d.update(campaign=[{"method": "guyan", "modes": [3]}]))
variant("campaign-method", lambda d: d.update(campaign=[{"method": "modal", "modes": [0]}]))
variant("damping-alpha", lambda d: d.update(damping={"rayleigh": {"alpha": -1.0, "beta": 0.0}}))
variant("damping-beta", lambda d: d.update(damping={"rayleigh": {"alpha": 1.0, "beta": "small"}}))
variant("damping-no-beta", lambda d: d.update(damping={"rayleigh": {"alpha": 1.0}}))
variant("damping-ratio", lambda d: d.update(damping={"modal_ratio": 1.0}))
variant("damping-ratio-negative", lambda d: d.update(damping={"modal_ratio": -0.01}))
variant("damping-unknown", lambda d: d.update(damping={"zeta": 0.01}))
variant("campaign-selection", lambda d: d.update(campaign=[{"method": "cb", "modes": [10], "selection": "best"}]))
variant("campaign-casing-many", lambda d: d.update(campaign=[{"method": "cb", "modes": [10], "casing_modes": [157]}]))
variant("campaign-casing-negative", lambda d: d.update(campaign=[{"method": "cb", "modes": [10], "casing_modes": [-1]}]))
variant("campaign-step-word", lambda d: d.update(campaign=[{"method": "cb", "modes": [10], "time_step": ["fast"]}]))
variant("campaign-step-divide", lambda d: d.update(campaign=[{"method": "cb", "modes": [10], "casing_modes": [20], "time_step": [4e-6]}]))
variant("campaign-safety", lambda d: d.update(campaign=[{"method": "cb", "modes": [10], "time_step": ["own"], "step_safety": 1.5}]))
variant("damping-number", lambda d: d.update(damping=0.01))
variant("friction-law", lambda d: d["operating_point"].update(friction_law="stick"))
# Counts beyond what a run holds (issue 13, class 1): 1e13 steps; 1e9 steps
# each written (about 1.2 TB of history).
# In range key by key, but the blade's length function overflows: GSL's
# root finder met a non-finite value and its default handler aborted (issue 13, class 5).
variant("gsl-overflow", lambda d: (d["bladed_disk"].update(tip_radius=1e300), d["casing"].update(radius=1.7e308)))
variant("too-many-steps", lambda d: d["time"].update(duration=1e4, step=1e-9))
variant("huge-history", lambda d: d["time"].update(duration=1.0, step=1e-9, output_every=1))
# JSON a parser accepts but no case means (issue 13, classes 5 and 7): a key
# twice in one object (the last would win silently), nesting 100,000 deep.
text = open(good).read()
assert '"friction_coefficient": 0.15' in text
open(f"{work}/duplicate-key.json", "w").write(
    text.replace('"friction_coefficient": 0.15', '"friction_coefficient": 0.15, "friction_coefficient": 0.3'))
open(f"{work}/deep.json", "w").write('{"a": ' + '[' * 100000 + ']' * 100000 + '}')
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
# The blade as a whole (issue 13, class 7): every key in range, 1000 elements
# at the default 1 degree kink turn it by 1000 degrees, a spiral.
expect 2 "$work/curled.json: bladed_disk.kink_angle_deg: the blade curls too much for its tip to reach tip_radius" -- "$rsi" modes "$work/curled.json" --out "$work/out"
expect 2 "keys 'bladed_disk.n_blade_elements' and 'bladed_disk.kink_angle_deg': the blade curls back" -- "$rsi" modes "$src/fuzz/corpus/spiral-blade.json" --out "$work/out"
expect 2 "--count: must be in [1, 682]" -- "$rsi" modes "$good" --count 1000 --out "$work/out"
expect 2 "--count: must be in [1, 156]" -- "$rsi" modes "$good" --part casing --count 157 --out "$work/out"
expect 2 "--count: must be an integer in [1, the part's number of dofs], got '0'" -- "$rsi" modes "$good" --count 0 --out "$work/out"
expect 2 "--count: must be an integer in [1, the part's number of dofs], got 'many'" -- "$rsi" modes "$good" --count many --out "$work/out"
expect 2 "--count: must be an integer in [1, the part's number of dofs], got '2.5'" -- "$rsi" modes "$good" --count 2.5 --out "$work/out"
expect 2 "--part: must be bladed-disk or casing for the paper's case, got 'rotor'" -- "$rsi" modes "$good" --part rotor --out "$work/out"

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
expect 2 "time.step = 3e-06 s is not below the central-difference stability limit of the bladed disk: 2/omega_max <= 2.50711e-06 s" -- "$rsi" simulate "$work/unstable.json" --out "$work/out"
# Cheap checks first (issue 13, class 9): a fine casing (4000 elements,
# 16000 dofs) cannot run at the default step; the one-dof Rayleigh bound
# says so before the Lanczos eigensolver and before a basis is built.
# timeout: the old code ran its eigensolver for minutes on the largest one.
expect 2 "not below the central-difference stability limit of the casing: 2/omega_max <= 1.65315e-09 s" -- timeout 60 "$rsi" simulate "$work/fine-casing.json" --out "$work/out"
expect 2 "not below the central-difference stability limit of the casing" -- timeout 60 "$rsi" simulate "$work/fine-casing.json" --method cb --modes 10 --out "$work/out"
# The largest casing the definiteness check accepts (10,000 elements) at
# 5e-10 s: above its 2/omega_max = 2.636e-10 s, below the one-dof bound
# 6.46e-10 s. The bound now includes the power method's Rayleigh quotient
# (2.64549e-10 s, 0.4 s); with the one-dof bound alone the Lanczos eigensolver
# ran 264 s before refusing it (issue 13, class 9).
expect 2 "not below the central-difference stability limit of the casing: 2/omega_max <= 2.64549e-10 s" -- timeout 60 "$rsi" simulate "$work/largest-resolved-casing.json" --method cb --modes 10 --out "$work/out"
# Memory before it is asked for (issue 13, class 1): a reduced run keeps the
# casing's inverse mass dense, 8 n_c^2 bytes (0.511 GB at 2000 elements,
# 7996 dofs). Under an address-space limit of 400 MB (ulimit -v; 900 MB for
# a campaign of two reduced runs on two threads, 1.02 GB) it is refused
# naming the key before the basis is built; it was exit 1 "out of memory"
# after the basis and the eigensolvers. Not under AddressSanitizer, which
# reserves terabytes of address space (no ulimit -v there).
if ldd "$rsi" | grep -q libasan; then
  skip "casing too large for the memory: ulimit -v cannot be used with AddressSanitizer"
else
  limited_v() { # KB COMMAND...: the command under ulimit -v KB
    local kb=$1
    shift
    bash -c 'ulimit -v "$0"; exec "$@"' "$kb" "$@"
  }
  expect 2 "key 'casing.n_elements' (2000): a reduced run keeps the casing's inverse mass dense, 8 n_c^2 = 0.511 GB for its 7996 dofs, more than the 0.41 GB" -- limited_v 400000 "$rsi" simulate "$work/casing-2000.json" --method cb --modes 10 --out "$work/out"
  expect 2 "2 runs at once: 1.02 GB, more than the 0.922 GB this process may use (physical memory, ulimit -v, ulimit -d); use at most 1898 casing elements or fewer --jobs" -- limited_v 900000 "$rsi" campaign "$work/casing-2000.json" --no-report --out "$work/out"
  # The bladed disk's dense basis (reduced/basis_memory.hpp): 200 blades of
  # 72 elements, 44,000 dofs and 400 boundary dofs. A reduced run holds T
  # twice at least, 16 n r bytes: CB-400 (r = 800) 0.563 GB against 0.41 GB,
  # most modes floor(0.4096e9 / (16 * 44000)) - 400 = 181; the campaign's
  # CB-1000 (r = 1400) 0.986 GB against 0.922 GB, most 1309 - 400 = 909.
  # Refused before the basis is built (it was exit 1 "out of memory" after
  # the fixed-interface modes).
  expect 2 "--modes: 400 modes: the reduced basis T is dense, 44000 x 800 (400 boundary dofs and the modes), and a reduced run holds it twice, 16 n r = 0.563 GB, more than the 0.41 GB this process may use (physical memory, ulimit -v, ulimit -d); use at most 181 modes" -- limited_v 400000 "$rsi" simulate "$work/wide-disk.json" --method cb --modes 400 --out "$work/out"
  expect 2 "key 'campaign': cb-1000: 1000 modes: the reduced basis T is dense, 44000 x 1400 (400 boundary dofs and the modes), and a reduced run holds it twice, 16 n r = 0.986 GB, more than the 0.922 GB this process may use (physical memory, ulimit -v, ulimit -d); use at most 909 modes" -- limited_v 900000 "$rsi" campaign "$work/wide-disk.json" --no-report --out "$work/out"
fi
# The model as a whole (issue 13, class 7): K positive definite to working
# precision (reference/model/part_definiteness). The largest casing, 100000
# elements, bends smoothly with an energy 2e16 times smaller than its terms,
# past the 1/gamma_p = 3.75e14 double precision resolves: refused when it
# is built, naming the keys, before any step check or eigensolver; so are
# blades 1e-8 m thick (the dense modal path printed negative frequencies)
# on every command, and a casing 1e-7 m thick.
expect 2 "the casing's stiffness K is not positive definite to working precision" -- timeout 60 "$rsi" simulate "$work/largest-casing.json" --out "$work/out"
expect 2 "change key 'casing.section.thickness' (0.01 m) or 'casing.n_elements' (100000)" -- timeout 60 "$rsi" simulate "$work/largest-casing.json" --method cb --modes 10 --out "$work/out"
expect 2 "the casing's stiffness K is not positive definite to working precision" -- "$rsi" modes "$work/largest-casing.json" --part casing --out "$work/out"
expect 2 "change key 'casing.section.thickness' (1e-07 m)" -- "$rsi" simulate "$work/thin-casing.json" --out "$work/out"
expect 2 "the bladed disk's stiffness K is not positive definite to working precision" -- "$rsi" modes "$work/thin-blades.json" --out "$work/out"
expect 2 "change key 'bladed_disk.blade_section.thickness' (1e-08 m) or 'bladed_disk.n_blade_elements' (9)" -- "$rsi" simulate "$work/thin-blades.json" --method cb --modes 10 --out "$work/out"
expect 2 "bladed_disk.blade_section.thickness" -- "$rsi" simulate "$work/thin-blades.json" --method full --out "$work/out"
expect 2 "bladed_disk.blade_section.thickness" -- "$rsi" reduce "$work/thin-blades.json" --method ccm --modes 10 --out "$work/out"
expect 2 "bladed_disk.blade_section.thickness" -- "$rsi" campaign "$work/thin-blades.json" --no-report --out "$work/out"
expect 2 "bladed_disk.blade_section.thickness" -- "$rsi" export "$work/thin-blades.json" --out "$work/out"
expect 2 "--method: must be full, cb, ccm, guyan, macneal or cc, got 'modal'" -- "$rsi" simulate "$good" --method modal --out "$work/out"
expect 2 "--method: must be full, cb, ccm or guyan for the paper's case (macneal, cc: component cases), got 'macneal'" -- "$rsi" simulate "$good" --method macneal --modes 10 --out "$work/out"
expect 2 "--modes: Craig-Bampton takes 0 to 638" -- "$rsi" simulate "$good" --method cb --modes 639 --out "$work/out"
expect 2 "--modes: Craig-Chang-Martinez takes 0 to 638" -- "$rsi" simulate "$good" --method ccm --modes 700 --out "$work/out"
expect 2 "--modes: Guyan reduction keeps no modes" -- "$rsi" simulate "$good" --method guyan --modes 2 --out "$work/out"
expect 2 "--modes: must be an integer in [0, the method's maximum]" -- "$rsi" simulate "$good" --method cb --modes 1e3 --out "$work/out"
expect 2 "--full-field: only for the reduced methods" -- "$rsi" simulate "$good" --method full --full-field --out "$work/out"
expect 2 "--boundary-modes: only for --method cc on a component case" -- "$rsi" simulate "$good" --method cb --modes 10 --boundary-modes 3 --out "$work/out"

# damping (issue 12): every key named with its range
expect 2 "damping.rayleigh.alpha': must be in [0, inf) 1/s, got -1.0" -- "$rsi" simulate "$work/damping-alpha.json" --out "$work/out"
expect 2 "damping.rayleigh.beta': must be a number in [0, inf) s, got \"small\"" -- "$rsi" simulate "$work/damping-beta.json" --out "$work/out"
expect 2 "damping.rayleigh.beta': missing (required)" -- "$rsi" simulate "$work/damping-no-beta.json" --out "$work/out"
expect 2 "damping.modal_ratio': must be in [0, 1), got 1.0" -- "$rsi" simulate "$work/damping-ratio.json" --method cb --modes 10 --out "$work/out"
expect 2 "damping.modal_ratio': must be in [0, 1), got -0.01" -- "$rsi" simulate "$work/damping-ratio-negative.json" --out "$work/out"
expect 2 "time.duration': over time.step gives 1e+13 steps, more than the 2147483647 a run can count" -- "$rsi" simulate "$work/too-many-steps.json" --out "$work/out"
expect 2 "time.duration': over time.step gives 1e+13 steps" -- "$rsi" campaign "$work/too-many-steps.json" --out "$work/out"
expect 2 "time.output_every': with time.duration / time.step = 1e+09 steps, history.csv would take about 1176 GB (limit 100 GB)" -- "$rsi" simulate "$work/huge-history.json" --out "$work/out"
# Options the method does not use are refused, not ignored (issue 13, class 7).
expect 2 "--modes: only for a reduced method (the full reference keeps no modes)" -- "$rsi" simulate "$good" --method full --modes 10 --out "$work/out"
# Issue 14 axes: steps that do not divide the output interval, unknown names, counts past the casing.
expect 2 "--time-step: only for a reduced method" -- "$rsi" simulate "$good" --method full --time-step own --out "$work/out"
expect 2 "--casing-modes: only for a reduced method" -- "$rsi" simulate "$good" --method full --casing-modes 20 --out "$work/out"
expect 2 "--step-safety: only with --time-step own" -- "$rsi" simulate "$good" --method cb --modes 10 --step-safety 0.5 --out "$work/out"
expect 2 "--time-step: must be case, own or a step in seconds > 0, got 'fast'" -- "$rsi" simulate "$good" --method cb --modes 10 --time-step fast --out "$work/out"
expect 2 "--time-step: a step of 4e-06 s must divide the output interval" -- "$rsi" simulate "$good" --method cb --modes 10 --casing-modes 20 --time-step 4e-6 --out "$work/out"
expect 2 "casing_modes: must be in [0, 156]" -- "$rsi" simulate "$good" --method cb --modes 10 --casing-modes 157 --out "$work/out"
expect 2 "--selection: must be" -- "$rsi" simulate "$good" --method cb --modes 10 --selection best --out "$work/out"
expect 2 "stability limit" -- "$rsi" simulate "$good" --method cb --modes 10 --time-step 2.5e-5 --out "$work/out"
expect 2 "campaign[0].selection': must be \"lowest\"" -- "$rsi" campaign "$work/campaign-selection.json" --out "$work/out"
expect 2 "casing_modes 157 of cb-10: must be in [0, 156]" -- "$rsi" campaign "$work/campaign-casing-many.json" --out "$work/out"
expect 2 "campaign[0].casing_modes': must hold integers in [0, 400000]" -- "$rsi" campaign "$work/campaign-casing-negative.json" --out "$work/out"
expect 2 "campaign[0].time_step': must hold \"case\", \"own\" or steps > 0" -- "$rsi" campaign "$work/campaign-step-word.json" --out "$work/out"
expect 2 "key 'campaign': time_step of cb-10-c20-dt-4e-06: a step of 4e-06 s must divide the output interval" -- "$rsi" campaign "$work/campaign-step-divide.json" --out "$work/out"
expect 2 "campaign[0].step_safety': must be in (0, 1)" -- "$rsi" campaign "$work/campaign-safety.json" --out "$work/out"
expect 2 "bladed_disk: no blade element length puts the tip at tip_radius (GSL root finder" -- "$rsi" modes "$work/gsl-overflow.json" --out "$work/out"
for cmd in simulate modes; do
  expect 2 "key 'friction_coefficient' appears twice in one object" -- "$rsi" "$cmd" "$work/duplicate-key.json" --out "$work/out"
  expect 2 "JSON nested deeper than 32 levels" -- "$rsi" "$cmd" "$work/deep.json" --out "$work/out"
done
expect 2 "operating_point.friction_law': must be \"sliding_sign\" or \"coulomb\", got \"stick\"" -- "$rsi" simulate "$work/friction-law.json" --out "$work/out"
expect 2 "damping.zeta': unknown key" -- "$rsi" simulate "$work/damping-unknown.json" --out "$work/out"
expect 2 "key 'damping': must be a JSON object" -- "$rsi" simulate "$work/damping-number.json" --out "$work/out"

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


# Component cases (issue 11): imported models with bad files. A 2-node,
# 6-dof model; each variant breaks one thing. The CalculiX variants name
# the matrices ccx would have written (calculix_matrices), so no ccx runs.
mkdir -p "$work/ccx"
printf '*NODE, NSET=NALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n*NSET, NSET=TIP\n2\n' >"$work/ccx/deck.inp"
printf '*NODE, NSET=NALL\n1, 5., 0., 0.\n2, 6., 0., 0.\n*NSET, NSET=TIP\n1\n' >"$work/ccx/other.inp"
good_dof='1.1\n1.2\n1.3\n2.1\n2.2\n2.3\n'
good_sti='1 1 4.0\n1 4 -1.0\n2 2 4.0\n3 3 4.0\n4 4 2.0\n5 5 2.0\n6 6 2.0\n'
good_mas='1 1 1.0\n2 2 1.0\n3 3 1.0\n4 4 1.0\n5 5 1.0\n6 6 1.0\n'
ccx_variant() { # NAME DOF STI MAS [BOUNDARY_JSON]
  local name=$1 boundary=${5:-'{"node_set": "TIP"}'}
  printf "$2" >"$work/ccx/$name.dof"
  printf "$3" >"$work/ccx/$name.sti"
  printf "$4" >"$work/ccx/$name.mas"
  printf '{"component": {"name": "tiny", "source": {"calculix_deck": "ccx/deck.inp", "calculix_matrices": "ccx/%s"}, "boundary": %s, "units": "N, mm, t, s"}}\n' \
    "$name" "$boundary" >"$work/ccx-$name.json"
}
ccx_variant good "$good_dof" "$good_sti" "$good_mas"
ccx_variant truncated "$good_dof" '1 1 4.0\n1 4\n' "$good_mas"
ccx_variant text "$good_dof" '1 1 4.0\n1 x -1.0\n' "$good_mas"
ccx_variant beyond "$good_dof" "${good_sti}7 7 1.0\n" "$good_mas"
ccx_variant asymmetric "$good_dof" "${good_sti}4 1 -1.5\n" "$good_mas"
ccx_variant nan "$good_dof" "$good_sti" '1 1 nan\n2 2 1.0\n3 3 1.0\n4 4 1.0\n5 5 1.0\n6 6 1.0\n'
ccx_variant inf "$good_dof" '1 1 inf\n6 6 1.0\n' "$good_mas"
ccx_variant zero-mass "$good_dof" "$good_sti" '1 1 1.0\n2 2 1.0\n3 3 0.0\n4 4 1.0\n5 5 1.0\n6 6 1.0\n'
ccx_variant negative-mass "$good_dof" "$good_sti" '1 1 1.0\n2 2 1.0\n3 3 1.0\n4 4 -1.0\n5 5 1.0\n6 6 1.0\n'
ccx_variant dof-count "${good_dof}3.1\n" "$good_sti" "$good_mas"
ccx_variant dof-text "1.1\n1.x\n" "$good_sti" "$good_mas"
ccx_variant no-node "$good_dof" "$good_sti" "$good_mas" '{"nodes": [2, 99]}'
ccx_variant no-set "$good_dof" "$good_sti" "$good_mas" '{"node_set": "HUB"}'
ccx_variant twice "$good_dof" "$good_sti" "$good_mas" '{"nodes": [2, 2]}'
printf '{"component": {"name": "tiny", "source": {"calculix_deck": "ccx/deck.inp"}, "boundary": {"node_set": "TIP"}, "units": "N, mm, t, s"}}\n' >"$work/ccx-run.json"
printf '{"component": {"name": "tiny", "source": {"calculix_deck": "ccx/no-deck.inp"}, "boundary": {"nodes": [2]}, "units": "N, mm, t, s"}}\n' >"$work/ccx-no-deck.json"
printf '{"component": {"name": "tiny", "source": {"abaqus": "x.inp"}, "units": "N"}}\n' >"$work/source-kind.json"
printf '{"component": {"name": "a/b", "source": {"matrix_market": "mm"}, "units": "N"}}\n' >"$work/name-slash.json"
printf '{"component": {"name": "tiny", "source": {"calculix_deck": "ccx/deck.inp"}, "units": "N"}}\n' >"$work/no-boundary.json"
printf '{"component": {"name": "tiny", "source": {"matrix_market": "mm"}, "units": "N", "rotation_axis": [0, 0, 0]}}\n' >"$work/axis.json"
printf '{"component": {"name": "tiny", "source": {"matrix_market": "mm"}, "units": "N", "colour": 1}}\n' >"$work/component-unknown.json"
for cmd in modes export reduce; do
  extra=()
  [ "$cmd" = reduce ] && extra=(--method cb)
  expect 2 "ccx/truncated.sti:2: expected a number as the third field" -- "$rsi" "$cmd" "$work/ccx-truncated.json" "${extra[@]}" --out "$work/out"
  expect 2 "ccx/text.sti:2: expected 'row col value' with integer row and col" -- "$rsi" "$cmd" "$work/ccx-text.json" "${extra[@]}" --out "$work/out"
  expect 2 "ccx/beyond.sti:8: index 7 outside [1, 6]" -- "$rsi" "$cmd" "$work/ccx-beyond.json" "${extra[@]}" --out "$work/out"
  expect 2 "ccx/asymmetric.sti:8: not symmetric: (4, 1) = -1.5 but (1, 4) = -1 at line 2" -- "$rsi" "$cmd" "$work/ccx-asymmetric.json" "${extra[@]}" --out "$work/out"
  expect 2 "ccx/nan.mas:1: value is not finite" -- "$rsi" "$cmd" "$work/ccx-nan.json" "${extra[@]}" --out "$work/out"
  expect 2 "ccx/inf.sti:1: value is not finite" -- "$rsi" "$cmd" "$work/ccx-inf.json" "${extra[@]}" --out "$work/out"
  expect 2 "ccx/zero-mass.mas:3: diagonal entry (3, 3) = 0: the mass diagonal must be positive" -- "$rsi" "$cmd" "$work/ccx-zero-mass.json" "${extra[@]}" --out "$work/out"
  expect 2 "ccx/negative-mass.mas:4: diagonal entry (4, 4) = -1: the mass diagonal must be positive" -- "$rsi" "$cmd" "$work/ccx-negative-mass.json" "${extra[@]}" --out "$work/out"
  expect 2 "ccx/dof-count.sti: the largest row index is 6 but the .dof file lists 7 dofs" -- "$rsi" "$cmd" "$work/ccx-dof-count.json" "${extra[@]}" --out "$work/out"
  expect 2 "ccx/dof-text.dof:2: expected 'node.direction'" -- "$rsi" "$cmd" "$work/ccx-dof-text.json" "${extra[@]}" --out "$work/out"
  expect 2 "boundary node 99 is not a node of the deck" -- "$rsi" "$cmd" "$work/ccx-no-node.json" "${extra[@]}" --out "$work/out"
  expect 2 "has no *NSET named HUB" -- "$rsi" "$cmd" "$work/ccx-no-set.json" "${extra[@]}" --out "$work/out"
  expect 2 "boundary node 2 is listed twice" -- "$rsi" "$cmd" "$work/ccx-twice.json" "${extra[@]}" --out "$work/out"
  expect 2 "ccx (CalculiX) not found on PATH" -- env PATH=/nonexistent "$rsi" "$cmd" "$work/ccx-run.json" "${extra[@]}" --ccx-cache "$work/out/cache" --out "$work/out"
  expect 2 "key 'component.source.calculix_deck': '$work/ccx/no-deck.inp' is not a file" -- "$rsi" "$cmd" "$work/ccx-no-deck.json" "${extra[@]}" --out "$work/out"
  expect 2 "key 'component.source': must be {\"calculix_deck\": file" -- "$rsi" "$cmd" "$work/source-kind.json" "${extra[@]}" --out "$work/out"
  expect 2 "key 'component.name': must be a plain folder name" -- "$rsi" "$cmd" "$work/name-slash.json" "${extra[@]}" --out "$work/out"
  expect 2 "key 'component.boundary': missing (required for a calculix_deck source)" -- "$rsi" "$cmd" "$work/no-boundary.json" "${extra[@]}" --out "$work/out"
  expect 2 "key 'component.rotation_axis': must be three finite numbers, not all zero" -- "$rsi" "$cmd" "$work/axis.json" "${extra[@]}" --out "$work/out"
  expect 2 "key 'component.colour': unknown key" -- "$rsi" "$cmd" "$work/component-unknown.json" "${extra[@]}" --out "$work/out"
  expect 2 "--source: only for a component case" -- "$rsi" "$cmd" "$good" "${extra[@]}" --source "$work/ccx/deck.inp" --out "$work/out"
done
expect 2 "--part: the case $work/ccx-good.json has one component, 'tiny', got 'casing'" -- "$rsi" modes "$work/ccx-good.json" --part casing --out "$work/out"

# A case naming stored matrices (calculix_matrices) and a --source deck:
# refused naming both, never that deck's nodes and sets with the other
# deck's matrices (they were mixed silently). Likewise a gmsh_blade case,
# whose blade deck --source would replace while its boundary stayed TIP.
for cmd in modes export reduce; do
  extra=()
  [ "$cmd" = reduce ] && extra=(--method cb)
  expect 2 "key 'component.source.calculix_matrices': the case reads the matrices $work/ccx/good.{sti,mas,dof} of a ccx run of $work/ccx/deck.inp, and --source names the deck $work/ccx/other.inp" -- "$rsi" "$cmd" "$work/ccx-good.json" "${extra[@]}" --source "$work/ccx/other.inp" --out "$work/out"
  expect 2 "key 'component.source.gmsh_blade': the case builds its blade deck from these parameters, and --source names $work/ccx/deck.inp" -- "$rsi" "$cmd" "$src/data/cases/blade3d.json" "${extra[@]}" --source "$work/ccx/deck.inp" --out "$work/out"
done

# Decks read as ccx reads them (reference/model/calculix_deck.hpp): what ccx
# refuses, crashes on or silently misreads is refused with file, line and
# keyword. Each names matrices, so no ccx runs. The GENERATE near the
# integer limit looped forever (32-bit overflow): here it must end, under
# a 60 s timeout.
deck_variant() { # NAME DECK_TEXT
  printf "$2" >"$work/ccx/$1.inp"
  printf '{"component": {"name": "tiny", "source": {"calculix_deck": "ccx/%s.inp", "calculix_matrices": "ccx/good"}, "boundary": {"node_set": "TIP"}, "units": "N, mm, t, s"}}\n' \
    "$1" >"$work/deck-$1.json"
}
deck_variant generate '*NODE, NSET=NALL\n1, 0., 0., 0.\n2147483647, 1., 0., 0.\n*NSET, NSET=TIP, GENERATE\n2147483600, 2147483647, 1000\n'
deck_variant forward '*NODE, NSET=NALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n*NSET, NSET=TIP\nEND\n*NSET, NSET=END\n2\n'
deck_variant node-zero '*NODE, NSET=NALL\n1, 0., 0., 0.\n0, 1., 0., 0.\n'
deck_variant long-coordinate '*NODE, NSET=NALL\n1, 0., 0., 0.\n2, -1.23456789012345E+02, 0., 0.\n'
deck_variant empty-field '*NODE, NSET=NALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n*NSET, NSET=TIP\n1,,2\n'
deck_variant include '*INCLUDE, INPUT=nowhere/mesh.inp\n'
deck_variant dropped '*NODE, NSET=NALL\n1, 0., 0., 0.\n2, 1., 0., 0.\n*NSET, NSET=TIP\n2, 3\n'
expect 2 "key 'component.boundary': boundary node 2147483600 is not a node of the deck $work/ccx/generate.inp" -- timeout 60 "$rsi" modes "$work/deck-generate.json" --out "$work/out"
expect 2 "ccx/forward.inp:5: *NSET TIP names the node set END before it is defined ($work/ccx/forward.inp:6): ccx reads that name as an empty set" -- "$rsi" modes "$work/deck-forward.json" --out "$work/out"
expect 2 "ccx/node-zero.inp:3: *NODE: node id 0" -- "$rsi" modes "$work/deck-node-zero.json" --out "$work/out"
expect 2 "ccx/long-coordinate.inp:3: *NODE: a coordinate '-1.23456789012345E+02' has more than 20 characters: ccx reads only its first 20 ('-1.23456789012345E+0')" -- "$rsi" modes "$work/deck-long-coordinate.json" --out "$work/out"
expect 2 "ccx/empty-field.inp:5: *NSET: an empty field between two commas" -- "$rsi" modes "$work/deck-empty-field.json" --out "$work/out"
expect 2 "ccx/include.inp:1: *INCLUDE: the file '$work/ccx/nowhere/mesh.inp' does not exist" -- "$rsi" modes "$work/deck-include.json" --out "$work/out"
expect 2 "key 'component.boundary.node_set': the *NSET TIP of $work/ccx/dropped.inp lists node 3, above the deck's largest node id 2: ccx drops it" -- "$rsi" modes "$work/deck-dropped.json" --out "$work/out"

# Rubbing runs of a component case (issue 12): every key of "rubbing" named.
rubbing_variant() { # NAME RUBBING_JSON [COMPONENT_EXTRA]
  printf '{"component": {"name": "tiny", "source": {"calculix_deck": "ccx/deck.inp", "calculix_matrices": "ccx/good"}, "boundary": {"node_set": "TIP"}, "units": "N, mm, t, s"%s}, "rubbing": %s}\n' \
    "${3:-}" "$2" >"$work/rubbing-$1.json"
}
rub='"gap": {"oval": {"g_m": 0.1, "width": 0.15}}, "rotation_speed": 100, "revolutions": 1, "steps_per_revolution": 100, "response": {"node": 2, "direction": 2}'
rubbing_variant mu "{$rub, \"friction_coefficient\": 3}"
rubbing_variant gap "{\"gap\": {\"elliptic\": 1}, \"friction_coefficient\": 0.1}"
rubbing_variant width "{\"gap\": {\"oval\": {\"g_m\": 0.1, \"width\": 1.5}}, \"friction_coefficient\": 0.1}"
rubbing_variant omega "{\"gap\": {\"constant\": 0}, \"friction_coefficient\": 0.1, \"rotation_speed\": 0}"
rubbing_variant omega-range "{\"gap\": {\"constant\": 0}, \"friction_coefficient\": 0.1, \"rotation_speed\": -100001}"
rubbing_variant sliding "{$rub, \"friction_coefficient\": 0.1, \"tip_sliding\": \"backwards\"}"
rubbing_variant response "{\"gap\": {\"constant\": 0}, \"friction_coefficient\": 0.1, \"rotation_speed\": 100, \"revolutions\": 1, \"steps_per_revolution\": 100, \"response\": {\"node\": 99, \"direction\": 2}}"
rubbing_variant steps "{\"gap\": {\"constant\": 0}, \"friction_coefficient\": 0.1, \"rotation_speed\": 100, \"revolutions\": 100000, \"steps_per_revolution\": 100000, \"response\": {\"node\": 2, \"direction\": 2}}"
rubbing_variant unknown "{$rub, \"friction_coefficient\": 0.1, \"colour\": 1}"
rubbing_variant mass "{$rub, \"friction_coefficient\": 0.1}" ', "mass": "diagonal"'
rubbing_variant rotation-matrices "{$rub, \"friction_coefficient\": 0.1}" ', "rotation_effects": true'
rubbing_variant rotation-type "{$rub, \"friction_coefficient\": 0.1}" ', "rotation_effects": 1'
rubbing_variant no-campaign "{$rub, \"friction_coefficient\": 0.1}"
rubbing_variant campaign "{$rub, \"friction_coefficient\": 0.1, \"campaign\": {\"runs\": [{\"method\": \"macneal\", \"modes\": [1]}]}}"
rubbing_variant campaign-method "{$rub, \"friction_coefficient\": 0.1, \"campaign\": {\"runs\": [{\"method\": \"guyan\", \"modes\": [1]}]}}"
rubbing_variant campaign-cc "{$rub, \"friction_coefficient\": 0.1, \"campaign\": {\"runs\": [{\"method\": \"cc\", \"modes\": [1]}]}}"
rubbing_variant campaign-cc-twice "{$rub, \"friction_coefficient\": 0.1, \"campaign\": {\"runs\": [{\"method\": \"cc\", \"modes\": [1], \"fixed_interface_modes\": 0}, {\"method\": \"cc\", \"modes\": [1, 2], \"fixed_interface_modes\": 1}]}}"
rubbing_variant campaign-cb-fixed "{$rub, \"friction_coefficient\": 0.1, \"campaign\": {\"runs\": [{\"method\": \"cb\", \"modes\": [1], \"fixed_interface_modes\": 2}]}}"
# rubbing.liner: bad values refused naming the key and the range.
lin='"thickness": 1, "young_modulus": 1000, "hardening_modulus": 0'
rubbing_variant liner-yield "{$rub, \"friction_coefficient\": 0.1, \"liner\": {$lin, \"yield_stress\": -1, \"cells_around\": 10}}"
rubbing_variant liner-cells "{$rub, \"friction_coefficient\": 0.1, \"liner\": {$lin, \"yield_stress\": 1, \"cells_around\": 0}}"
rubbing_variant liner-z "{$rub, \"friction_coefficient\": 0.1, \"liner\": {$lin, \"yield_stress\": 1, \"cells_around\": 10, \"z_min\": 0}}"
rubbing_variant liner-patch "{$rub, \"friction_coefficient\": 0.1, \"liner\": {$lin, \"yield_stress\": 1, \"cells_around\": 10, \"tip_patch\": {\"circumferential\": 5.0, \"axial\": 0}}}"
expect 2 "key 'rubbing': missing (a contact run of a component needs" -- "$rsi" simulate "$work/ccx-good.json" --out "$work/out"
# A contact node ccx expanded (a beam, shell or plane node: a row per
# expanded node and direction) and a response node ccx created (above the
# deck's largest id): neither is one point with one dof per direction
# (the contact took the last row of each direction, silently).
ccx_variant expanded '1.1\n1.2\n1.3\n2.1\n2.2\n2.3\n2.1\n2.2\n2.3\n' "${good_sti}7 7 1.0\n8 8 1.0\n9 9 1.0\n" "${good_mas}7 7 1.0\n8 8 1.0\n9 9 1.0\n"
ccx_variant created "${good_dof}3.1\n" "${good_sti}7 7 1.0\n" "${good_mas}7 7 1.0\n"
printf '{"component": {"name": "tiny", "source": {"calculix_deck": "ccx/deck.inp", "calculix_matrices": "ccx/expanded"}, "boundary": {"node_set": "TIP"}, "units": "N, mm, t, s"}, "rubbing": {%s, "friction_coefficient": 0.1}}\n' "$rub" >"$work/rubbing-expanded.json"
printf '{"component": {"name": "tiny", "source": {"calculix_deck": "ccx/deck.inp", "calculix_matrices": "ccx/created"}, "boundary": {"node_set": "TIP"}, "units": "N, mm, t, s"}, "rubbing": {%s, "friction_coefficient": 0.1}}\n' "${rub/\"node\": 2/\"node\": 3}" >"$work/rubbing-created.json"
expect 2 "key 'component.boundary': node 2 has 2 rows of ux: ccx expanded it" -- "$rsi" simulate "$work/rubbing-expanded.json" --out "$work/out"
expect 2 "key 'rubbing.response': node 3 is a node ccx created (no position in the deck)" -- "$rsi" simulate "$work/rubbing-created.json" --out "$work/out"
expect 2 "key 'rubbing.friction_coefficient': must be in [0, 2], got 3" -- "$rsi" simulate "$work/rubbing-mu.json" --out "$work/out"
expect 2 "key 'rubbing.gap': must be {\"oval\": {\"g_m\": .., \"width\": ..}} or {\"constant\": g0}" -- "$rsi" simulate "$work/rubbing-gap.json" --out "$work/out"
expect 2 "key 'rubbing.gap.oval.width': must be in (0, 1), got 1.5" -- "$rsi" simulate "$work/rubbing-width.json" --out "$work/out"
expect 2 "key 'rubbing.rotation_speed': must be nonzero, in [-100000, 100000] rad/s (its sign is the rotation direction about rotation_axis: > 0 counter-clockwise), got 0" -- "$rsi" simulate "$work/rubbing-omega.json" --out "$work/out"
expect 2 "key 'rubbing.rotation_speed': must be in [-100000, 100000] rad/s, got -100001" -- "$rsi" simulate "$work/rubbing-omega-range.json" --out "$work/out"
expect 2 "key 'rubbing.tip_sliding': must be \"with_rotation\" or \"against_rotation\", got \"backwards\"" -- "$rsi" simulate "$work/rubbing-sliding.json" --out "$work/out"
expect 2 "key 'rubbing.response': node 99 direction 2 is not a dof of the model" -- "$rsi" simulate "$work/rubbing-response.json" --out "$work/out"
expect 2 "key 'rubbing.revolutions': revolutions x steps_per_revolution must be at most 2147483647" -- "$rsi" simulate "$work/rubbing-steps.json" --out "$work/out"
expect 2 "key 'rubbing.colour': unknown key" -- "$rsi" simulate "$work/rubbing-unknown.json" --out "$work/out"
expect 2 "key 'rubbing.liner.yield_stress': must be in (0, inf) (stress), got -1" -- "$rsi" simulate "$work/rubbing-liner-yield.json" --out "$work/out"
expect 2 "key 'rubbing.liner.cells_around': must be an integer in [1, 10000000], got 0" -- "$rsi" simulate "$work/rubbing-liner-cells.json" --out "$work/out"
expect 2 "key 'rubbing.liner.z_max': must be given with z_min" -- "$rsi" simulate "$work/rubbing-liner-z.json" --out "$work/out"
expect 2 "key 'rubbing.liner.tip_patch.axial': must be in (0, inf) (length), got 0" -- "$rsi" simulate "$work/rubbing-liner-patch.json" --out "$work/out"
expect 2 "key 'component.mass': must be \"consistent\" or \"lumped\" (HRZ), got \"diagonal\"" -- "$rsi" simulate "$work/rubbing-mass.json" --out "$work/out"
expect 2 "key 'component.rotation_effects': needs ccx to run the deck under the centrifugal load, and source.calculix_matrices names matrices already written" -- "$rsi" simulate "$work/rubbing-rotation-matrices.json" --out "$work/out"
expect 2 "key 'component.rotation_effects': must be true or false, got 1" -- "$rsi" simulate "$work/rubbing-rotation-type.json" --out "$work/out"
expect 2 "--speed: rotation effects are for a component case (a CalculiX deck or the gmsh blade); $src/data/cases/batailly2007.json is the paper's 2D case" -- "$rsi" modes "$src/data/cases/batailly2007.json" --speed 100 --out "$work/out"
expect 2 "--speeds: a Campbell diagram needs at least two speeds, got '100'" -- "$rsi" modes "$work/rubbing-mass.json" --speeds 100 --out "$work/out"
expect 2 "--speeds: the speeds must ascend, got '200,100'" -- "$rsi" modes "$work/rubbing-mass.json" --speeds 200,100 --out "$work/out"
expect 2 "key 'rubbing.campaign': missing, nothing to run" -- "$rsi" campaign "$work/rubbing-no-campaign.json" --out "$work/out"
expect 2 "--jobs: a component case's campaign runs one run at a time" -- "$rsi" campaign "$work/rubbing-campaign.json" --jobs 2 --out "$work/out"
expect 2 "--target-e2: only for the paper's case" -- "$rsi" campaign "$work/rubbing-campaign.json" --target-e2 0.1 --out "$work/out"
expect 2 "key 'rubbing.campaign.runs[0].method': must be \"cb\", \"ccm\", \"macneal\" or \"cc\", got \"guyan\"" -- "$rsi" campaign "$work/rubbing-campaign-method.json" --out "$work/out"
expect 2 "--full-field: only for the paper's case" -- "$rsi" simulate "$work/rubbing-no-campaign.json" --full-field --out "$work/out"
expect 2 "key 'rubbing.campaign.runs[0].fixed_interface_modes': missing (required)" -- "$rsi" campaign "$work/rubbing-campaign-cc.json" --out "$work/out"
expect 2 "key 'rubbing.campaign.runs[0].fixed_interface_modes': only for \"method\": \"cc\"" -- "$rsi" campaign "$work/rubbing-campaign-cb-fixed.json" --out "$work/out"
expect 2 "--boundary-modes: characteristic constraint modes: 1 to 3 boundary modes (the boundary dofs), got 0" -- "$rsi" simulate "$work/rubbing-no-campaign.json" --method cc --modes 1 --out "$work/out"
expect 2 "key 'rubbing.campaign.runs[1].modes': n_c = 1 is in an earlier cc entry already" -- "$rsi" campaign "$work/rubbing-campaign-cc-twice.json" --out "$work/out"
expect 2 "--boundary-modes: only for --method cc (characteristic constraint modes)" -- "$rsi" simulate "$work/rubbing-no-campaign.json" --method cb --modes 1 --boundary-modes 2 --out "$work/out"
# rsi sweep's cc runs: the case's sweep.runs entries as rubbing.campaign.runs', or --method cc.
sweep_variant() { # NAME SWEEP_JSON
  printf '{"component": {"name": "tiny", "source": {"calculix_deck": "ccx/deck.inp", "calculix_matrices": "ccx/good"}, "boundary": {"node_set": "TIP"}, "units": "N, mm, t, s"}, "rubbing": {%s, "friction_coefficient": 0.1}, "sweep": %s}\n' \
    "$rub" "$2" >"$work/sweep-$1.json"
}
sweep_variant cc '{"speeds": [100], "runs": [{"method": "cc", "modes": [1]}]}'
sweep_variant cc-twice '{"speeds": [100], "runs": [{"method": "cc", "modes": [1], "fixed_interface_modes": 0}, {"method": "cc", "modes": [2, 1], "fixed_interface_modes": 1}]}'
sweep_variant cb-fixed '{"speeds": [100], "runs": [{"method": "cb", "modes": [1], "fixed_interface_modes": 2}]}'
expect 2 "key 'sweep.runs[0].fixed_interface_modes': missing (required)" -- "$rsi" sweep "$work/sweep-cc.json" --no-report --out "$work/out"
expect 2 "key 'sweep.runs[1].modes': n_c = 1 is listed already" -- "$rsi" sweep "$work/sweep-cc-twice.json" --no-report --out "$work/out"
expect 2 "key 'sweep.runs[0].fixed_interface_modes': only for \"method\": \"cc\"" -- "$rsi" sweep "$work/sweep-cb-fixed.json" --no-report --out "$work/out"
expect 2 "--boundary-modes: --method cc needs its characteristic constraint modes n_c (>= 1" -- "$rsi" sweep "$work/rubbing-no-campaign.json" --speeds 100 --method cc --modes 1 --no-report --out "$work/out"
expect 2 "--boundary-modes: only with --method cc" -- "$rsi" sweep "$work/rubbing-no-campaign.json" --speeds 100 --method cb --modes 1 --boundary-modes 2 --no-report --out "$work/out"
# A mode count the reduction refuses, named by the entry's key (not simulate's options).
sweep_variant cc-many '{"speeds": [100], "runs": [{"method": "full"}, {"method": "cc", "modes": [9], "fixed_interface_modes": 0}]}'
sweep_variant cc-eta '{"speeds": [100], "runs": [{"method": "cc", "modes": [1], "fixed_interface_modes": 9}]}'
expect 2 "sweep-cc-many.json: key 'sweep.runs[1].modes': characteristic constraint modes: 1 to 3" -- "$rsi" sweep "$work/sweep-cc-many.json" --no-report --out "$work/out"
expect 2 "sweep-cc-eta.json: key 'sweep.runs[0].fixed_interface_modes': Craig-Bampton takes 0 to" -- "$rsi" sweep "$work/sweep-cc-eta.json" --no-report --out "$work/out"
expect 2 "--method: cc with component.rotation_effects: not built in a speed subspace" -- "$rsi" sweep "$src/data/cases/blade3d-rubbing-rotating.json" --speeds 1000 --method cc --modes 2 --boundary-modes 3 --no-report --out "$work/out"
/usr/bin/python3 -c 'import json, sys; c = json.load(open(sys.argv[1])); c["sweep"] = {"speeds": [1000], "runs": [{"method": "cc", "modes": [3], "fixed_interface_modes": 2}]}; json.dump(c, open(sys.argv[2], "w"))' \
  "$src/data/cases/blade3d-rubbing-rotating.json" "$work/sweep-cc-rotating.json"
expect 2 "key 'sweep.runs': cc with component.rotation_effects: not built in a speed subspace" -- "$rsi" sweep "$work/sweep-cc-rotating.json" --no-report --out "$work/out"
expect 2 "--method: must be full, cb, ccm or guyan for the paper's case (macneal, cc: component cases), got 'cc'" -- "$rsi" sweep "$src/data/cases/batailly2007.json" --method cc --modes 2 --boundary-modes 3 --no-report --out "$work/out"
# A component campaign whose only run is refused (cb-9 of 3 interior dofs): exit 3 (a run
# failed), and the report still written, naming the run (it left no history to draw).
rubbing_variant campaign-refused "{$rub, \"friction_coefficient\": 0.1, \"campaign\": {\"runs\": [{\"method\": \"cb\", \"modes\": [9]}]}}"
"$rsi" campaign "$work/rubbing-campaign-refused.json" --out "$work/refused" >"$work/stdout" 2>"$work/stderr"
got=$?
if [ "$got" -eq 3 ] && grep -qF "Refused before a step (no history; rsi's message says why): cb-9." "$work/refused/report.md" &&
  grep -qF "cb-9 failed: key 'rubbing.campaign.runs[0].modes': Craig-Bampton takes 0 to 3" "$work/stdout" "$work/stderr"; then
  passes=$((passes + 1))
  echo "ok   exit 3 | rsi campaign rubbing-campaign-refused.json | the report lists cb-9 as refused"
else
  failures=$((failures + 1))
  echo "FAIL exit $got | rsi campaign rubbing-campaign-refused.json | $(tail -n 3 "$work/stderr" | tr '\n' ' ')"
fi

# Matrix Market folders in rsi export's layout (the good one written by rsi export).
"$rsi" export "$work/ccx-good.json" --out "$work/mm" >/dev/null
mm_variant() { # NAME FILE CONTENT: a copy of the good folder with FILE replaced
  cp -r "$work/mm/tiny" "$work/mm/$1"
  printf "$3" >"$work/mm/$1/$2"
  printf '{"component": {"name": "tiny", "source": {"matrix_market": "mm/%s"}, "units": "N, mm, t, s"}}\n' "$1" >"$work/mm-$1.json"
}
mm_variant truncated K.mtx '%%%%MatrixMarket matrix coordinate real symmetric\n6 6 7\n1 1 4\n4 1 -1\n'
mm_variant banner K.mtx '%%%%MatrixMarket matrix array real general\n6 6 7\n'
mm_variant size-line M.mtx '%%%%MatrixMarket matrix coordinate real symmetric\n6 5 6\n'
mm_variant upper M.mtx '%%%%MatrixMarket matrix coordinate real symmetric\n6 6 2\n1 1 1\n1 2 0.5\n'
mm_variant inf M.mtx '%%%%MatrixMarket matrix coordinate real symmetric\n6 6 1\n1 1 -inf\n'
mm_variant rows K.mtx '%%%%MatrixMarket matrix coordinate real symmetric\n5 5 1\n1 1 4\n'
mm_variant asymmetric K.mtx '%%%%MatrixMarket matrix coordinate real general\n6 6 3\n1 1 4\n4 1 -1\n1 4 -1.001\n'
mm_variant dofs dofs.csv 'index,node,kind,boundary\n0,1,ux,0\n2,1,uy,0\n'
mm_variant no-diagonal M.mtx '%%%%MatrixMarket matrix coordinate real symmetric\n6 6 5\n1 1 1\n2 2 1\n3 3 1\n4 4 1\n6 6 1\n'
mm_variant nodes nodes.csv 'node,x,y,z\n1,0,0,0\n'
for cmd in modes export reduce; do
  extra=()
  [ "$cmd" = reduce ] && extra=(--method cb)
  expect 2 "mm/truncated/K.mtx: the size line announces 7 entries, the file holds 2 (truncated?)" -- "$rsi" "$cmd" "$work/mm-truncated.json" "${extra[@]}" --out "$work/out"
  expect 2 "mm/banner/K.mtx:1: expected the banner" -- "$rsi" "$cmd" "$work/mm-banner.json" "${extra[@]}" --out "$work/out"
  expect 2 "mm/size-line/M.mtx:2: size line must be 'n n entries'" -- "$rsi" "$cmd" "$work/mm-size-line.json" "${extra[@]}" --out "$work/out"
  expect 2 "mm/upper/M.mtx:4: a symmetric Matrix Market file stores the lower triangle" -- "$rsi" "$cmd" "$work/mm-upper.json" "${extra[@]}" --out "$work/out"
  expect 2 "mm/inf/M.mtx:3: value is not finite" -- "$rsi" "$cmd" "$work/mm-inf.json" "${extra[@]}" --out "$work/out"
  expect 2 "mm/rows/K.mtx: 5 rows, but dofs.csv lists 6 dofs" -- "$rsi" "$cmd" "$work/mm-rows.json" "${extra[@]}" --out "$work/out"
  expect 2 "mm/asymmetric/K.mtx:5: not symmetric" -- "$rsi" "$cmd" "$work/mm-asymmetric.json" "${extra[@]}" --out "$work/out"
  expect 2 "mm/dofs/dofs.csv:3: index must be 1 (rows in order), got 2" -- "$rsi" "$cmd" "$work/mm-dofs.json" "${extra[@]}" --out "$work/out"
  expect 2 "mm/no-diagonal/M.mtx: no diagonal entry (5, 5): the mass diagonal must be positive" -- "$rsi" "$cmd" "$work/mm-no-diagonal.json" "${extra[@]}" --out "$work/out"
  expect 2 "mm/nodes/dofs.csv: node 2 has dofs but no line in nodes.csv" -- "$rsi" "$cmd" "$work/mm-nodes.json" "${extra[@]}" --out "$work/out"
done

# Hardening, third round (classes 1, 2, 5): declared sizes checked before
# anything is sized by them; a general file holding one triangle; keys read
# and refused with exit 2 naming them, where they ended as exit 1 with
# internal names or ran with no effect.
# A size line of 2e9 rows: was minutes and 23 GB before the mismatch (the
# timeout stands for "at once": the check precedes any allocation).
mm_variant huge-rows K.mtx '%%%%MatrixMarket matrix coordinate real symmetric\n2000000000 2000000000 1\n1 1 4\n'
mm_variant huge-count M.mtx '%%%%MatrixMarket matrix coordinate real symmetric\n6 6 5000000000000\n1 1 1\n'
# general: the lower triangle only (mirrored and used as symmetric before);
# both triangles, equal, pass.
mm_variant general-lower K.mtx '%%%%MatrixMarket matrix coordinate real general\n6 6 7\n1 1 4\n4 1 -1\n2 2 4\n3 3 4\n4 4 2\n5 5 2\n6 6 2\n'
mm_variant general-both K.mtx '%%%%MatrixMarket matrix coordinate real general\n6 6 8\n1 1 4\n4 1 -1\n1 4 -1\n2 2 4\n3 3 4\n4 4 2\n5 5 2\n6 6 2\n'
# K vanishing against M: a Young's modulus of 1e-300 (was exit 1,
# "TridiagEigen: eigen decomposition failed").
mm_variant vanishing K.mtx '%%%%MatrixMarket matrix coordinate real symmetric\n6 6 7\n1 1 4e-300\n4 1 -1e-300\n2 2 4e-300\n3 3 4e-300\n4 4 2e-300\n5 5 2e-300\n6 6 2e-300\n'
for cmd in modes export; do
  extra=()
  [ "$cmd" = modes ] && extra=(--count 3) # of the 6 dofs
  expect 2 "mm/huge-rows/K.mtx: 2000000000 rows, but dofs.csv lists 6 dofs" -- timeout 20 "$rsi" "$cmd" "$work/mm-huge-rows.json" "${extra[@]}" --out "$work/out"
  expect 2 "mm/huge-count/M.mtx:2: the size line announces 5000000000000 entries, more than the 21 a symmetric (lower triangle) 6 x 6 matrix holds" -- timeout 20 "$rsi" "$cmd" "$work/mm-huge-count.json" "${extra[@]}" --out "$work/out"
  expect 2 "mm/general-lower/K.mtx:4: not symmetric: (4, 1) = -1 but (1, 4) is not given (0); a general file stores both triangles" -- "$rsi" "$cmd" "$work/mm-general-lower.json" "${extra[@]}" --out "$work/out"
  expect 2 "key 'component.source.matrix_market': the stiffness vanishes against the mass: K_ii / M_ii, the scale of omega^2, is at most 4e-300" -- "$rsi" "$cmd" "$work/mm-vanishing.json" "${extra[@]}" --out "$work/out"
done
expect 0 "wrote" -- "$rsi" export "$work/mm-general-both.json" --out "$work/out-general"
if [ -e "$work/out-general/tiny/K.mtx" ] && cmp -s "$work/out-general/tiny/K.mtx" "$work/mm/tiny/K.mtx"; then
  passes=$((passes + 1))
  echo "ok   a general K.mtx holding both triangles reads as the symmetric one (re-exported byte for byte)"
else
  failures=$((failures + 1))
  echo "FAIL a general K.mtx holding both triangles: not re-exported as the symmetric one"
fi
# A component name starting with '.': was exit 1 "StagedOutput::publish: ...
# is in no entry of the command's output set".
printf '{"component": {"name": ".hidden", "source": {"matrix_market": "mm/tiny"}, "units": "N"}}\n' >"$work/name-dot.json"
printf '{"component": {"name": ".rsi-stage-1", "source": {"matrix_market": "mm/tiny"}, "units": "N"}}\n' >"$work/name-stage.json"
for name in dot stage; do
  expect 2 "key 'component.name': must be a plain folder name (no '/' or '\\', not starting with '.')" -- "$rsi" export "$work/name-$name.json" --out "$work/out"
done
# rubbing.contact_nodes repeated, unknown, clamped, off the boundary: were
# exit 1 naming RigidSurfaceContact / rigid_surface_nodes (or, off the
# boundary, a full run that the reduced ones refuse).
rubbing_variant contact-twice "{$rub, \"friction_coefficient\": 0.1, \"contact_nodes\": [2, 2]}"
rubbing_variant contact-unknown "{$rub, \"friction_coefficient\": 0.1, \"contact_nodes\": [2, 99]}"
for method in full cb; do
  extra=()
  [ "$method" = cb ] && extra=(--modes 1)
  expect 2 "key 'rubbing.contact_nodes': contact node 2 is listed twice" -- "$rsi" simulate "$work/rubbing-contact-twice.json" --method "$method" "${extra[@]}" --out "$work/out"
  expect 2 "key 'rubbing.contact_nodes': contact node 99 is not a node of tiny" -- "$rsi" simulate "$work/rubbing-contact-unknown.json" --method "$method" "${extra[@]}" --out "$work/out"
done
# A run's steps counted in 64 bits before it starts. At 1e-4 rad/s the
# tiny model (stability limit 0.952 s) takes k = 7334 steps a sample of
# T/N = 628.3 s; 58,562.5 revolutions of 10 samples make 585,625 x 7334 =
# 4,294,973,750 steps, which a 32-bit count wrapped to 6,454: both runs
# stopped there and reported "completed" with exit 0 (0.88 of one sample).
rubbing_variant wrap "{\"gap\": {\"oval\": {\"g_m\": 0.1, \"width\": 0.15}}, \"friction_coefficient\": 0.1, \"rotation_speed\": 0.0001, \"revolutions\": 58562.5, \"steps_per_revolution\": 10, \"response\": {\"node\": 2, \"direction\": 2}}"
expect 2 "keys 'rubbing.revolutions' and 'rubbing.steps_per_revolution': 585625 samples x 7334 steps a sample (the full run steps at" -- "$rsi" simulate "$work/rubbing-wrap.json" --method full --out "$work/out"
expect 2 "keys 'rubbing.revolutions' and 'rubbing.steps_per_revolution': 585625 samples x 7334 steps a sample (the cb run steps at" -- "$rsi" simulate "$work/rubbing-wrap.json" --method cb --modes 1 --out "$work/out"
expect 2 "= 4294973750 steps, more than the 2147483647 a run can count" -- "$rsi" simulate "$work/rubbing-wrap.json" --method cb --modes 1 --out "$work/out"
# The gmsh blade's element_size in its range but far past what the run can
# hold: refused before gmsh from the estimated mesh (was minutes of gmsh
# and millions of dofs before ccx ran out of memory; the timeout stands for
# "before gmsh", and no gmsh runs here: the cache is the test's own).
/usr/bin/python3 "$src/verification/cli/case_variant.py" "$src/data/cases/blade3d.json" "$work/blade-fine.json" \
  component.source.gmsh_blade.element_size=0.4
expect 2 "key 'component.source.gmsh_blade.element_size': 0.4 mm gives about 19155396 dofs (estimated before gmsh from the volume" -- timeout 20 "$rsi" modes "$work/blade-fine.json" --ccx-cache "$work/blade-cache" --out "$work/out"
if [ -e "$work/blade-cache" ]; then
  failures=$((failures + 1))
  echo "FAIL element_size 0.4: the ccx cache was written ($(ls "$work/blade-cache" | head -3 | tr '\n' ' '))"
else
  passes=$((passes + 1))
  echo "ok   element_size 0.4: refused before gmsh (no cache entry)"
fi
# A history of 2.1e9 samples of one contact node would be 504 GB:
rubbing_variant history-size "{\"gap\": {\"constant\": 0}, \"friction_coefficient\": 0.1, \"rotation_speed\": 100, \"revolutions\": 21, \"steps_per_revolution\": 100000000, \"response\": {\"node\": 2, \"direction\": 2}}"
expect 2 "key 'rubbing.output_every': 2100000000 samples (rubbing.revolutions x rubbing.steps_per_revolution) written every 1 would make history.csv about 504 GB (limit 100 GB)" -- timeout 20 "$rsi" simulate "$work/rubbing-history-size.json" --out "$work/out"

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
