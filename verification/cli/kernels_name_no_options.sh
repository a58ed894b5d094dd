#!/usr/bin/env bash
# Errors in two kinds: a kernel (reference/, reduced/) says what failed, in
# its own terms, and which of its inputs failed (FailureAdvice); the CLI
# words which option or case key that input came from
# (cli/support/failure_advice.cpp), or passes the names in with the input
# (ComponentLoadOptions::source_name, ccx_cache_name; the modes and step
# keys of a reduced run). Fails if a string literal in reference/ or
# reduced/ names a command line option (--name), anywhere, or one of the case
# keys the messages used to name (time.step, component.mass, rubbing.*,
# casing_modes, operating_point.*), outside the files allowed below.
# Comments are not checked.
# Usage: kernels_name_no_options.sh SOURCE_DIR
set -u
src=$1
# The case loaders name their own keys: that is their job.
loaders="reference/model/case_file.cpp reference/model/component_case.cpp reference/model/rubbing_points.cpp"
# Left, with the reason: the step rule's check states the output interval
# as the case's keys mid-sentence ("must divide the output interval
# time.step * output_every = ..."); its callers would have to pass that name.
left="reference/solver/run_step.cpp"
for d in reference reduced; do
  if [ ! -d "$src/$d" ]; then
    echo "FAIL $src/$d is missing (the layout moved: update this test)"
    echo "0 passed, 1 failed"
    exit 1
  fi
done
option='"[^"]*--[a-z]'
key='"[^"]*(time\.step|component\.mass|rubbing\.|casing_modes|operating_point)'
failed=0
checked=0
# FILE:LINE:CODE hits of PATTERN, the code's // comment cut off first.
hits() {
  (cd "$src" && grep -rnE --include='*.cpp' --include='*.hpp' "$1" reference reduced) |
    while IFS= read -r hit; do
      code=${hit#*:*:}
      code=$(printf '%s' "$code" | sed -E 's@(^|[[:space:]])//.*$@@')
      printf '%s' "$code" | grep -qE "$1" && printf '%s\n' "$hit"
    done
}
options=$(hits "$option")
checked=$((checked + 1))
if [ -n "$options" ]; then
  echo "FAIL a kernel names a command line option:"
  echo "$options"
  failed=$((failed + 1))
else
  echo "ok   no string in reference/ or reduced/ names a command line option"
fi
keys=""
while IFS= read -r hit; do
  [ -z "$hit" ] && continue
  file=${hit%%:*}
  case " $loaders $left " in
  *" $file "*) continue ;;
  esac
  keys+="$hit"$'\n'
done <<<"$(hits "$key")"
checked=$((checked + 1))
if [ -n "$keys" ]; then
  echo "FAIL a kernel names a case key (outside the loaders $loaders and $left):"
  printf '%s' "$keys"
  failed=$((failed + 1))
else
  echo "ok   no string in reference/ or reduced/ names a case key outside the loaders and $left"
fi
echo "$((checked - failed)) passed, $failed failed"
[ "$failed" -eq 0 ]
