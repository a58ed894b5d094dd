#!/usr/bin/env bash
# SPEC §1: reduced/ never uses the reference solver's time integrator or
# contact code. Fails if any file of reduced/ includes their headers.
# Usage: reduced_independence.sh SOURCE_DIR
set -u
forbidden='#include "(central_difference|mass_factor|tip_casing_contact|contact_law|reference_run|frictional_contact_law|tip_ring_frictional_contact|rigid_surface_contact|structure_contact|full_order_run|component_reference_run|rubbing_monitor)\.hpp"'
if hits=$(grep -rnE "$forbidden" "$1/reduced"); then
  echo "reduced/ includes reference integrator or contact code:"
  echo "$hits"
  echo "0 passed, 1 failed"
  exit 1
fi
echo "ok   reduced/ includes none of the reference integrator (central_difference, mass_factor, full_order_run and its adapters), its contact laws (contact_law, frictional_contact_law, tip_casing_contact, tip_ring_frictional_contact, rigid_surface_contact, structure_contact) or rubbing_monitor"
echo "1 passed, 0 failed"
