#!/usr/bin/env bash
# Installs what is missing, builds tether with its tests and runs the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTETHER_BUILD_TESTS=ON
cmake --build build --parallel
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
# The fast tests under AddressSanitizer + UBSan (docs/robustness.md) need a
# second full build, about 10-14 minutes on 2 cores: opt in with
# TETHER_SANITIZERS=1 until that build is trimmed enough for CI's time budget.
if [ "${TETHER_SANITIZERS:-0}" = 1 ]; then
  bash scripts/test-sanitizers.sh
fi
