#!/usr/bin/env bash
# SPEC §1: reduced/ never uses the reference solver's time integrator or
# contact code, and runs every reduced case through its one time loop.
# Fails if any file of reduced/ includes a header of reference/contact/ (read
# from the folder, so a new contact law is covered when it is added) or of
# the reference integrator, its drivers and their monitors (central_difference,
# mass_factor, reference_run, full_order_run,
# rubbing_monitor); or if an integrator is stepped anywhere in reduced/ but
# the loop reduced_drive.cpp (a second time loop).
# Usage: reduced_independence.sh SOURCE_DIR
set -u
src=$1
passed=0
failed=0
contact=$(cd "$src/reference/contact" && ls -- *.hpp | sed 's/\.hpp$//' | paste -sd'|')
if [ -z "$contact" ]; then
  echo "FAIL no headers found in $src/reference/contact (the layout moved: update this test)"
  echo "0 passed, 1 failed"
  exit 1
fi
integrator='central_difference|mass_factor|reference_run|full_order_run|rubbing_monitor'
forbidden="#include \"($contact|$integrator)\\.hpp\""
if hits=$(grep -rnE "$forbidden" "$src/reduced"); then
  echo "FAIL reduced/ includes reference integrator or contact code:"
  echo "$hits"
  failed=$((failed + 1))
else
  echo "ok   reduced/ includes none of reference/contact/ ($contact) nor $integrator"
  passed=$((passed + 1))
fi
if [ ! -f "$src/reduced/reduced_drive.cpp" ]; then
  echo "FAIL reduced/reduced_drive.cpp (the reduced time loop) is missing"
  failed=$((failed + 1))
elif loops=$(grep -rnE '(\.|->)step\(\)' "$src/reduced" --include='*.cpp' --include='*.hpp' |
  grep -v '^[^:]*/reduced_drive\.cpp:'); then
  echo "FAIL an integrator is stepped outside reduced/reduced_drive.cpp (a second time loop):"
  echo "$loops"
  failed=$((failed + 1))
else
  echo "ok   reduced/ steps its integrators only in reduced_drive.cpp (one time loop)"
  passed=$((passed + 1))
fi
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]
