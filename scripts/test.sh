#!/usr/bin/env bash
# Installs what is missing, builds tether with its tests and runs the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTETHER_BUILD_TESTS=ON
cmake --build build --parallel
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
# Then the fast tests again under AddressSanitizer + UBSan (docs/robustness.md).
bash scripts/test-sanitizers.sh
