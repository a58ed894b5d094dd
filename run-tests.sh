#!/usr/bin/env bash
# Builds rsi (Release, warnings are errors) and runs the test suite with
# ctest: every test but those labelled long; with --all, those too (the
# long suite: the external Rotor 37 model, the 3D bladed disk's rows and
# reduced runs, the studies' sizes; verification/CMakeLists.txt lists
# them). Installs missing Debian packages first.
set -euo pipefail
cd "$(dirname "$0")"
labels=(-LE long)
case "${1-}" in
  "") ;;
  --all) labels=() ;;
  *)
    echo "usage: ./run-tests.sh [--all]   (--all: the long tests too)" >&2
    exit 2
    ;;
esac
source .ci/deps.sh
rsi_install_dependencies
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DRSI_WERROR=ON
cmake --build build -j"$(nproc)"
ctest --test-dir build --output-on-failure -j"$(nproc)" "${labels[@]}"
