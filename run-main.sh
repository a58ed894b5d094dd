#!/usr/bin/env bash
# The main job: builds rsi and runs the paper's case (data/cases/batailly2007.json).
# Today that is the modal analysis of both parts, the matrix export, the
# frequency / nodal-diameter figure (paper Fig. 3) and the full reference
# contact run with its figures (paper Figs. 9-11), and the campaign of
# reduced runs (Guyan, Craig-Bampton, Craig-Chang-Martinez) with its
# method-comparison report (paper Figs. 10-14 analogues).
set -euo pipefail
cd "$(dirname "$0")"
source .ci/deps.sh
rsi_install_dependencies
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRSI_WERROR=ON >/dev/null
cmake --build build -j"$(nproc)"
case_file=data/cases/batailly2007.json
out=out/main
./build/cli/rsi modes "$case_file" --part bladed-disk --count 682 --out "$out/modes-bladed-disk"
./build/cli/rsi modes "$case_file" --part casing --count 40 --out "$out/modes-casing"
./build/cli/rsi export "$case_file" --out "$out/export"
/usr/bin/python3 reports/plot_fig3.py "$out/modes-bladed-disk/modes.csv" "$out/fig3_nodal_diameters.png"
./build/cli/rsi simulate "$case_file" --method full --out "$out/reference"
/usr/bin/python3 reports/plot_reference_run.py "$out/reference" "$out"
./build/cli/rsi campaign "$case_file" --target-e2 0.05 --out "$out/campaign"
/usr/bin/python3 reports/make_campaign_report.py "$out/campaign"
echo
echo "main job done: modal analysis, the full reference run, the campaign of reduced runs and its report."
echo "report: $out/campaign/report.md; reference run: $out/reference/; figures: $out/*.png"
