#!/usr/bin/env bash
# Linear bulk held (tether's default) against assembling and factorizing the
# bulk at every Newton iteration (`tether run --no-reuse`), on the plane-strain
# Hertz deck (node-to-surface, HARD, elastic, small strain), in a *STATIC step
# and in a *DYNAMIC step (HHT, fixed increment) of the same model.
# A benchmark, not a test: nothing registers it with CTest; run it by hand.
#
# Usage: bench/reuse/run.sh [SIZE ...]     SIZE = 2k, 25k, 230k, 1M (default: 25k)
# Environment:
#   TETHER=build/bin/tether  WORK=/tmp/tether_reuse_bench  THREADS=1  INCREMENTS=10
#   CASES="static dynamic"   MODES="held fresh"
# For each size, case and mode it prints one Markdown table row: CPU seconds
# (user + system) and peak resident memory from /usr/bin/time -v, Newton
# iterations (from the .sta), and tether's own timing line (assembly,
# factorizations, solves), and checks that held and fresh wrote the same .dat
# (byte for byte, or within 1e-10: see agree()).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
python=/usr/bin/python3
[[ -x $python ]] || python=python3
tether=${TETHER:-$root/build/bin/tether}
work=${WORK:-/tmp/tether_reuse_bench}
threads=${THREADS:-1}
sizes=("$@")
[[ ${#sizes[@]} -gt 0 ]] || sizes=(25k)
read -r -a cases <<< "${CASES:-static dynamic}"
read -r -a modes <<< "${MODES:-held fresh}"

# The dynamic variant: steel's density (tonne/mm^3), the pressure ramped over
# the step, HHT alpha = -0.05 at the static step's fixed increment.
dynamic_deck() {
  sed -e 's/^\*ELASTIC$/*DENSITY\n7.85e-9\n*ELASTIC/' \
      -e 's/^\*STEP, INC=100$/*STEP, INC=100, AMPLITUDE=RAMP/' \
      -e "s/^\*STATIC$/*DYNAMIC, ALPHA=-0.05, DIRECT/" "$1"
}

# Held and fresh .dat: identical, within 1e-10 (tools/compare_runs.py --tolerance's rule: the
# held bulk's residual comes from its tangent, summed in another order), or different.
agree() {
  if cmp -s "$1" "$2"; then echo "held and fresh .dat identical"; return; fi
  PYTHONPATH="$root/tools" "$python" -c 'import sys
from tethertools.compare_runs import text_within
why = text_within(open(sys.argv[1]).read(), open(sys.argv[2]).read(), 1e-10)
print("held and fresh .dat within 1e-10" if why is None else "**held and fresh .dat differ**: " + why)' "$1" "$2"
}

echo "| size | case | mode | CPU [s] | peak memory [MiB] | Newton iterations | tether's timing line |"
echo "| --- | --- | --- | ---: | ---: | ---: | --- |"
for size in "${sizes[@]}"; do
  mkdir -p "$work/$size"
  deck="$work/$size/hertz.inp"
  [[ -f $deck ]] || "$python" "$root/tools/make_hertz_deck.py" "$deck" --dofs "$size" --element CPE4 \
    --increments "${INCREMENTS:-10}" > /dev/null
  for case in "${cases[@]}"; do
    input="$work/$size/$case.inp"
    if [[ $case == dynamic ]]; then dynamic_deck "$deck" > "$input"; else cp "$deck" "$input"; fi
    for mode in "${modes[@]}"; do
      out="$work/$size/$case-$mode"
      rm -rf "$out" && mkdir -p "$out"
      flags=()
      [[ $mode == fresh ]] && flags=(--no-reuse)
      OMP_NUM_THREADS=$threads /usr/bin/time -v "$tether" run "$input" -o "$out" "${flags[@]}" \
        > "$out/stdout.txt" 2> "$out/time.txt" || true
      cpu=$(awk -F': ' '/User time/ {u=$2} /System time/ {s=$2} END {printf "%.1f", u + s}' "$out/time.txt")
      rss=$(awk -F': ' '/Maximum resident/ {printf "%.0f", $2 / 1024}' "$out/time.txt")
      its=$(awk '$1 ~ /^[0-9]+$/ && NF >= 9 {n += $4} END {print n + 0}' "$out/$case.sta" 2>/dev/null || echo -)
      timing=$(grep -m1 '^time ' "$out/stdout.txt" || tail -1 "$out/time.txt")
      echo "| $size | $case | $mode | $cpu | $rss | $its | $timing |"
    done
    if [[ -f $work/$size/$case-held/$case.dat && -f $work/$size/$case-fresh/$case.dat ]]; then
      echo "| $size | $case | | | | | $(agree "$work/$size/$case-held/$case.dat" "$work/$size/$case-fresh/$case.dat") |"
    fi
  done
done
