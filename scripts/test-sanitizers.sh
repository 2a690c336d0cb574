#!/usr/bin/env bash
# Builds tether with AddressSanitizer + UndefinedBehaviorSanitizer (CMake preset
# `asan`, directory build-asan) and runs the fast tests under them: every test
# but the package/install tests and the example smoke tests (CMakePresets.json,
# docs/robustness.md). Any sanitizer report aborts the test that triggered it.
set -euo pipefail
cd "$(dirname "$0")/.."
# The same options as the presets, also for gtest_discover_tests while building.
export ASAN_OPTIONS="halt_on_error=1:abort_on_error=0:detect_leaks=1:detect_stack_use_after_return=0:strict_string_checks=1:check_initialization_order=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan-suppressions.txt:print_suppressions=0"
export OMP_NUM_THREADS=2
start=$(date +%s)
cmake --preset asan
cmake --build --preset asan --parallel "$(nproc)"
built=$(date +%s)
status=0
ctest --preset asan --parallel "$(nproc)" || status=$?
end=$(date +%s)
echo "sanitizer build: $((built - start)) s, tests: $((end - built)) s"
exit "$status"
