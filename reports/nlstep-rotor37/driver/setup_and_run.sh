#!/bin/bash
# Reproduces NLstep's Rotor 37 'PLAUSIBLE' run (EXAMPLES/03_bladeCasingRubbing)
# under GNU Octave, for rsi's comparison (reports/nlstep-rotor37/report.md).
# Written for the rsi project; it is not NLstep code, and no NLstep or NLvib
# file is stored in the rsi repository: the trees are extracted from git
# repositories you provide.
#
# Usage:
#   bash setup_and_run.sh NLSTEP_GIT NLVIB_GIT [WORK_DIR]
#     NLSTEP_GIT  git directory of github.com/maltekrack/NLstep
#                 (e.g. `git clone --bare`; needs commit bba497d, 2025-06-17)
#     NLVIB_GIT   git directory holding upstream NLvib commit c7e9006
#                 (Malte Krack, 2025-06-17), e.g. a clone of
#                 github.com/julianjurai/NLvib-py, whose history holds the
#                 upstream commits; CMS_ROM.m and FEmodel.m, which NLstep
#                 needs, were added upstream in June 2025)
#     WORK_DIR    where the trees, the ccx run and out/ go (default ./nlstep-run)
#   Environment (optional):
#     R37_DECK_DIR   folder with blade.inp and blade.msh
#                    (default: ../../../../shared/external/rotor37 from this
#                    script, i.e. rsi's ../shared/external/rotor37)
#     STEPS_PER_REV  time steps a revolution (default: the example's 1000)
#     REVOLUTIONS    revolutions (default: the example's 50)
#     MU             friction coefficient (default: the example's 0.15)
#                    (each given value is written into the example's copy,
#                    lines 191, 190 and 103 of bladeCasingRubbing.m)
#     DRIVER=response  run run_rotor37_response.m (response and total normal
#                    force only, one integration: WORK_DIR/out/response_short.csv)
#                    instead of run_rotor37_plausible.m (the full export;
#                    it needs at least 5 revolutions)
#     CHECK_ROM=1    also run check_rom_vs_fe.m (ROM against the FE model)
# Tools: GNU Octave (7.3.0 used), CalculiX ccx (2.20 used), git, sed.
set -euo pipefail
if [ $# -lt 2 ]; then sed -n '2,35p' "$0"; exit 2; fi
NLSTEP_GIT=$1
NLVIB_GIT=$2
ROOT=$(mkdir -p "${3:-./nlstep-run}" && cd "${3:-./nlstep-run}" && pwd)
NLSTEP_REV=bba497dadf90a93d1677a811efcad47f28b40b82
NLVIB_REV=c7e90068784cf498a45542521a9a1489fd659420
DRV=$(cd "$(dirname "$0")" && pwd)
DECK=${R37_DECK_DIR:-$DRV/../../../../shared/external/rotor37}
DECK=$(cd "$DECK" && pwd)
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 CCX_NPROC_STIFFNESS=1 CCX_NPROC_EQUATION_SOLVER=1

# Extract a tree blob by blob (`git archive` aborts on blobs a partial mirror
# lacks, e.g. NLstep's EXAMPLES/04 .sti/.mas, which are not needed here).
extract() { # gitdir rev dest [pathprefix]
  local G=$1 REV=$2 DEST=$3 PFX=${4:-}
  git --git-dir="$G" ls-tree -r "$REV" $PFX | while read -r mode type sha path; do
    mkdir -p "$DEST/$(dirname "$path")"
    git --git-dir="$G" cat-file blob "$sha" > "$DEST/$path" 2>/dev/null \
      || { echo "skip (blob missing): $path"; rm -f "$DEST/$path"; }
  done
}
rm -rf "$ROOT/NLstep"
extract "$NLSTEP_GIT" "$NLSTEP_REV" "$ROOT/NLstep"
extract "$NLVIB_GIT" "$NLVIB_REV" "$ROOT/NLstep/SRC/NLvib" SRC

# The one code change, in NLvib's CMS_ROM.m, MCN branch: Octave's eigs returns
# the eigenvalues in descending order; the original line sorts the mode shapes
# but not om (the CB branch of the same file already does [om,ind] = sort(om)).
CMS="$ROOT/NLstep/SRC/NLvib/SRC/MechanicalSystems/CMS_ROM.m"
[ "$(grep -c '\[~,ind\] = sort(om);' "$CMS")" = 1 ] || { echo "CMS_ROM.m: expected one '[~,ind] = sort(om);'"; exit 1; }
sed -i 's/\[~,ind\] = sort(om);/[om,ind] = sort(om);/' "$CMS"
grep -n 'sort(om)' "$CMS"

EX="$ROOT/NLstep/EXAMPLES/03_bladeCasingRubbing"
setline() { # pattern replacement: edit one line of the example's copy
  [ "$(grep -c "$1" "$EX/bladeCasingRubbing.m")" = 1 ] || { echo "bladeCasingRubbing.m: expected one line '$1'"; exit 1; }
  sed -i "s/$1/$2/" "$EX/bladeCasingRubbing.m"
  grep -n "^${2%% *}" "$EX/bladeCasingRubbing.m"
}
[ -z "${STEPS_PER_REV:-}" ] || setline '^numberOfTimeStepsPerRevolution = 1e3;' "numberOfTimeStepsPerRevolution = $STEPS_PER_REV;"
[ -z "${REVOLUTIONS:-}" ] || setline '^numberOfRevolutions = 50;' "numberOfRevolutions = $REVOLUTIONS;"
[ -z "${MU:-}" ] || setline '^mu = 0.15; ' "mu = $MU; "

# CalculiX matrices: run ccx on a copy of the deck (never inside the deck folder)
FE="$ROOT/ccx"; mkdir -p "$FE"
cp "$DECK/blade.inp" "$DECK/blade.msh" "$FE/"
chmod u+w "$FE"/blade.*
(cd "$FE" && ccx -i blade > ccx.log 2>&1)
cmp "$FE/blade.dof" "$EX/FEmodel/blade.dof"       # must equal NLstep's shipped DOF map
ln -sf "$FE/blade.sti" "$EX/FEmodel/blade.sti"
ln -sf "$FE/blade.mas" "$EX/FEmodel/blade.mas"

# Run (the Octave driver sources NLstep's own example script)
mkdir -p "$ROOT/out"
if [ "${DRIVER:-full}" = response ]; then
  octave-cli -q --eval "NLSTEP_ROOT='$ROOT/NLstep'; OUT_FILE='$ROOT/out/response_short.csv'; run('$DRV/run_rotor37_response.m')" \
    2>&1 | tee "$ROOT/out/octave_log.txt"
else
  octave-cli -q --eval "NLSTEP_ROOT='$ROOT/NLstep'; OUT_DIR='$ROOT/out'; run('$DRV/run_rotor37_plausible.m')" \
    2>&1 | tee "$ROOT/out/octave_log.txt"
fi
if [ "${CHECK_ROM:-0}" = 1 ]; then
  octave-cli -q --eval "NLSTEP_ROOT='$ROOT/NLstep'; run('$DRV/check_rom_vs_fe.m')" \
    2>&1 | tee "$ROOT/out/check_rom_vs_fe.log"
fi
