#!/usr/bin/env bash
# SPEC §9, one pipeline: a command takes every kind of case and never asks
# which kind it holds; cli/support/case_kinds.hpp reads the kind once and
# hands the command's overload its case. Fails if a file of cli/commands/
# reads the kind itself (is_component_case, parse_case, parse_component_case,
# a ProblemKind, or an optional component case tested for presence).
# Usage: commands_without_kind_branches.sh SOURCE_DIR
set -u
src=$1
if [ ! -d "$src/cli/commands" ]; then
  echo "FAIL $src/cli/commands is missing (the layout moved: update this test)"
  echo "0 passed, 1 failed"
  exit 1
fi
if hits=$(grep -rnE 'is_component_case|parse_case\(|parse_component_case|ProblemKind::|component_case\.has_value\(\)' \
  "$src/cli/commands"); then
  echo "FAIL a command reads the kind of its case:"
  echo "$hits"
  echo "0 passed, 1 failed"
  exit 1
fi
echo "ok   no file of cli/commands/ reads the kind of its case (case_kinds.hpp does)"
echo "1 passed, 0 failed"
