#!/usr/bin/env bash
# Builds rsi (Release, warnings are errors) and runs every verification
# suite with ctest. Installs missing Debian packages first.
set -euo pipefail
cd "$(dirname "$0")"
source .ci/deps.sh
rsi_install_dependencies
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRSI_WERROR=ON
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)"
