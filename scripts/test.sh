#!/usr/bin/env bash
# Installs what is missing, builds tether with its tests and runs the whole suite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTETHER_BUILD_TESTS=ON
cmake --build build --parallel
ctest --test-dir build --output-on-failure --parallel "$(nproc)"
# Then a subset of the fast tests under AddressSanitizer + UBSan (deck reader,
# bad-deck corpus, constraints, assembly, contact; docs/robustness.md): a second,
# partial build at -O1. TETHER_SANITIZERS=0 skips it, TETHER_SANITIZERS=all runs
# every fast test under the sanitizers instead (a full second build).
case "${TETHER_SANITIZERS:-1}" in
  0) echo "test.sh: sanitizer stage skipped (TETHER_SANITIZERS=0)" ;;
  all) bash scripts/test-sanitizers.sh --all ;;
  *) bash scripts/test-sanitizers.sh ;;
esac
