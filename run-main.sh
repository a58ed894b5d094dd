#!/usr/bin/env bash
# The main job: builds rsi and runs the paper's case (data/cases/batailly2007.json)
# as `rsi campaign`: the full reference run and every reduced run of the case's
# campaign list (Guyan, Craig-Bampton, Craig-Chang-Martinez), their error norms
# and speedups (convergence.csv), and the method-comparison report with the
# analogues of paper Figs. 3 and 10-14 (report.md and its figures).
set -euo pipefail
cd "$(dirname "$0")"
source .ci/deps.sh
rsi_install_dependencies
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRSI_WERROR=ON >/dev/null
cmake --build build -j"$(nproc)"
out=out/main
./build/cli/rsi campaign data/cases/batailly2007.json --target-e2 0.05 --out "$out"
echo
echo "main job done: the reference run, the campaign of reduced runs and the report."
echo "report: $out/report.md (figures beside it); runs: $out/runs/; table: $out/convergence.csv"
