#!/usr/bin/env bash
# Builds tether with AddressSanitizer + UndefinedBehaviorSanitizer (CMake preset
# `asan`, directory build-asan, -O1 -g1) and runs tests under them. Any
# sanitizer report aborts the test that triggered it (docs/robustness.md).
#
#   bash scripts/test-sanitizers.sh         the CI subset (what scripts/test.sh runs):
#                                           libtether, the tether program and the test
#                                           executables of the deck reader, the bad-deck
#                                           corpus, constraints, assembly and contact
#                                           (presets asan-ci); a few minutes on 2 cores
#   bash scripts/test-sanitizers.sh --all   every fast test: all but the package/install
#                                           tests and the example smoke tests (presets
#                                           asan); a full second build, 10-14 minutes
set -euo pipefail
cd "$(dirname "$0")/.."
case "${1:-}" in
  "") build_preset=asan-ci test_preset=asan-ci ;;
  --all) build_preset=asan test_preset=asan ;;
  *) echo "usage: $0 [--all]" >&2; exit 2 ;;
esac
# The same options as the presets, also for gtest_discover_tests while building.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=0:detect_leaks=1:detect_stack_use_after_return=0:strict_string_checks=1:check_initialization_order=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan-suppressions.txt:print_suppressions=0"
export OMP_NUM_THREADS=2
start=$(date +%s)
cmake --preset asan
cmake --build --preset "$build_preset" --parallel "$(nproc)"
built=$(date +%s)
status=0
ctest --preset "$test_preset" --parallel "$(nproc)" || status=$?
end=$(date +%s)
echo "sanitizer stage ($test_preset): build $((built - start)) s, tests $((end - built)) s"
exit "$status"
