#!/usr/bin/env bash
# Plane-strain Hertz benchmark, CalculiX vs tether: generates the decks
# (tools/make_hertz_deck.py), runs both codes one after the other under
# /usr/bin/time -v, compares the contact pressure with the exact solution
# (tools/hertz_summary.py), prints the table and writes bench/hertz/results.md.
# Not part of CTest/CI (nothing registers it); run it by hand.
#
# Usage: bench/hertz/run.sh [CASE ...]         (default: $SIZES)
#   CASE = SIZE[/CPE4|/CPE8][/rigid], SIZE = 2k, 25k, 230k, 1M (target dofs)
# Environment:
#   SIZES="2k 25k 230k 1M"   cases when none are given
#   CODES=ccx,tether         which codes to run
#   TETHER_MEMORY=           e.g. 480: also run tether with --memory 480 (row "tether-budget":
#                            MUMPS factors out of core when they would not fit in 480 MB)
#   CCX_MAX=230k             largest size run in ccx (230k: ~260 s and 3.9 GB of memory;
#                            1M needs several times that: raise it only on a free machine)
#   WORK=/tmp/hertz_bench    decks and run directories (kept for inspection)
#   RESULTS=bench/hertz/results.md
#   TETHER=build/bin/tether  (built as scripts/demo.sh does, Release with CMake + Ninja, when
#                            missing; BUILD=0 turns that off)
#   TIMEOUT=3600 THREADS=1 INCREMENTS=10
#   WAIT_LOAD=               e.g. 1.5: before each run wait (up to WAIT_MAX=900 s) until the
#                            1-minute load average is below it (the machine is shared)
# A failed run (tether without contact, a timeout, ...) is a table row
# "CODE: failed (message)", not an error of the script.
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
python=/usr/bin/python3          # the one with numpy and matplotlib (Debian packages)
[[ -x $python ]] || python=python3

tether=${TETHER:-$root/build/bin/tether}
if [[ ! -x $tether && ${BUILD:-1} == 1 && -z ${TETHER:-} ]]; then
  echo "run.sh: $tether not found; building it (Release, as scripts/demo.sh does)" >&2
  { cmake -S "$root" -B "$root/build" -G Ninja -DCMAKE_BUILD_TYPE=Release &&
    cmake --build "$root/build" --parallel --target tether_cli; } >&2 ||
    echo "run.sh: build failed; the tether rows will say so" >&2
fi

cases=("$@")
if [[ ${#cases[@]} -eq 0 ]]; then
  read -r -a cases <<< "${SIZES:-2k 25k 230k 1M}"
fi

args=(--codes "${CODES:-ccx,tether}" --ccx-max "${CCX_MAX:-230k}" --workdir "${WORK:-/tmp/hertz_bench}"
      --results "${RESULTS:-$here/results.md}" --json "${WORK:-/tmp/hertz_bench}/results.json"
      --tether "$tether" --timeout "${TIMEOUT:-3600}" --threads "${THREADS:-1}"
      --increments "${INCREMENTS:-10}")
if [[ -n ${TETHER_MEMORY:-} ]]; then
  args+=(--tether-memory "$TETHER_MEMORY")
fi
if [[ -n ${WAIT_LOAD:-} ]]; then
  args+=(--wait-load "$WAIT_LOAD" --wait-max "${WAIT_MAX:-900}")
fi
exec "$python" "$root/tools/hertz_bench.py" "${args[@]}" "${cases[@]}"
