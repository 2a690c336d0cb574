#!/usr/bin/env bash
# Fuzzes the deck reader and model builder (fuzz/deck_fuzzer.cpp: what
# `tether check` does) with libFuzzer under AddressSanitizer + UBSan.
#
#   bash scripts/fuzz.sh [runs] [seconds]
#
# runs     executions to do (default 1000000; 0 = no limit)
# seconds  wall-time limit (default 0 = none); whichever limit comes first stops it
#
# Installs Clang and compiler-rt if missing (scripts/install-deps.sh fuzz),
# configures and builds the fuzzer in its own directory (TETHER_FUZZ_BUILD_DIR,
# default build-fuzz), seeds it with every .inp deck under examples/ and tests/
# and the few decks of fuzz/seeds/ for keywords those do not use (copied at run
# time into <build>/fuzz-seeds), gives it the dictionary fuzz/deck.dict,
# and prints the figures: executions, exec/s, coverage, findings.
# New interesting inputs accumulate in <build>/fuzz-corpus across runs; a crash,
# hang (> 10 s), leak or allocation over 2 GB stops the run and is saved in
# <build>/fuzz-artifacts/ (reproduce: <build>/bin/deck_fuzzer <file>).
# Not part of scripts/test.sh (CI). Exit status: 0 no finding, 1 a finding,
# other: the fuzzer could not be built or run.
set -euo pipefail
cd "$(dirname "$0")/.."
runs=${1:-1000000}
seconds=${2:-0}
dir=${TETHER_FUZZ_BUILD_DIR:-build-fuzz}
libfuzzer_runs=$runs
if [ "$runs" = 0 ]; then libfuzzer_runs=-1; fi  # libFuzzer: -runs=-1 is unlimited, 0 runs only the corpus

bash scripts/install-deps.sh fuzz

# -O1 with line tables, assertions on (no NDEBUG); libtether static so that
# the coverage counters of the library are in the fuzzer itself.
cmake -S . -B "$dir" -G Ninja \
  -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" \
  -DTETHER_FUZZ=ON -DTETHER_BUILD_TESTS=OFF -DTETHER_BUILD_BENCH=OFF -DBUILD_SHARED_LIBS=OFF >/dev/null
cmake --build "$dir" --target deck_fuzzer --parallel "$(nproc)"

seeds="$dir/fuzz-seeds"
corpus="$dir/fuzz-corpus"
artifacts="$dir/fuzz-artifacts"
rm -rf "$seeds"
mkdir -p "$seeds" "$corpus" "$artifacts"
n_seeds=0
while IFS= read -r -d '' deck; do
  cp "$deck" "$seeds/$(echo "${deck#./}" | tr '/' '_')"
  n_seeds=$((n_seeds + 1))
done < <(find examples tests fuzz/seeds -name '*.inp' -type f -print0)

export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:strict_string_checks=1:check_initialization_order=1:detect_stack_use_after_return=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan-suppressions.txt:print_suppressions=0"
export ASAN_SYMBOLIZER_PATH=/usr/lib/llvm-14/bin/llvm-symbolizer  # file:line in the reports
export OMP_NUM_THREADS=1

log="$dir/fuzz.log"
before=$(find "$artifacts" -type f | wc -l)
echo "fuzz: $n_seeds seed decks, runs=$runs, seconds=$seconds, log $log"
start=$(date +%s)
status=0
"$dir/bin/deck_fuzzer" -runs="$libfuzzer_runs" -max_total_time="$seconds" -max_len=65536 -timeout=10 \
  -rss_limit_mb=2048 -dict=fuzz/deck.dict -print_final_stats=1 -artifact_prefix="$artifacts/" \
  "$corpus" "$seeds" >"$log" 2>&1 || status=$?
end=$(date +%s)

stat() { sed -n "s/^stat::$1: *//p" "$log" | tail -1; }
# libFuzzer's last status line: cov = coverage points (edges) reached, ft = features
# (edges with hit-count buckets, comparisons), corp = inputs kept in memory / their size.
coverage=$(grep -oE 'cov: [0-9]+ ft: [0-9]+ corp: [0-9]+/[0-9]+[A-Za-z]+' "$log" | tail -1 || true)
findings=$(($(find "$artifacts" -type f | wc -l) - before))
echo "fuzz: executions   $(stat number_of_executed_units)"
echo "fuzz: wall time    $((end - start)) s"
echo "fuzz: exec/s       $(stat average_exec_per_sec)"
echo "fuzz: coverage     ${coverage:-?}   ($(find "$corpus" -type f | wc -l) files in $corpus)"
echo "fuzz: peak RSS     $(stat peak_rss_mb) MB"
echo "fuzz: findings     $findings (in $artifacts/)"
if [ "$status" -ne 0 ]; then
  grep -E '^(==[0-9]+==ERROR|SUMMARY|deck_fuzzer:|.*runtime error:|ALARM|.*out-of-memory)' "$log" | head -20 || true
  find "$artifacts" -type f -newer "$log" -o -type f -newermt "@$start" 2>/dev/null | sort -u | sed 's/^/fuzz: saved /'
  echo "fuzz: the fuzzer stopped with status $status (see $log)"
  exit 1
fi
