#!/usr/bin/env bash
# The component-case schema walked key by key (issue "Hardening, third
# round"): every key data/README.md lists for a component case, changed,
# must change the output of the commands it feeds or their message; a key
# whose change changes nothing is read and ignored (component_case_walk.py
# says how). A two-brick CalculiX deck (24 dofs) for most keys, the gmsh
# blade's coarse default for its own, a 3-sector coarse bladed disk for its
# own; the ccx cache is the suite's.
# About 40 s in Release. Skipped (exit 77) without gmsh or ccx.
# Usage: component_case_walk.sh RSI SOURCE_DIR CCX_CACHE
set -u
rsi=$1
src=$2
cache=$3
. "$(dirname "$0")/skip_without_gmsh_ccx.sh"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
/usr/bin/python3 "$src/verification/cli/component_case_walk.py" "$rsi" "$src" "$work" "$cache"
