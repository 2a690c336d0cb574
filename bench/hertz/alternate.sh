#!/usr/bin/env bash
# Two tether builds on one Hertz deck, runs alternating (A, B, A, B, ...) so
# that both see the same load of a shared machine; prints each run's CPU
# time (user + system, /usr/bin/time -v), maximum RSS [MiB = kB / 1024],
# wall time, 1-minute load and Newton iterations, then the median and range
# of the CPU time and RSS of each build. One thread (OMP_NUM_THREADS=1). Not
# part of CTest/CI; run it by hand. The figures of docs/performance.md
# ("OpenBLAS kernels and the same output request ...", "The forward sweep
# skipped ...") were measured this way.
#
# Usage: bench/hertz/alternate.sh DECK A_TETHER B_TETHER [REPEATS]   (REPEATS default 3)
#   DECK: e.g. from /usr/bin/python3 tools/make_hertz_deck.py h230k.inp --dofs 230k --element CPE4 --increments 10
#         (add --no-field-output for the deck measured against ccx: no .vtu, as ccx writes no field results)
#   A_TETHER, B_TETHER: the two programs (e.g. a build of the commit before and build/bin/tether)
# Environment: WORK=/tmp/hertz_alternate (run directories; the .vtu files are deleted after each run);
#   DECK_B=OTHER.inp gives B its own deck (e.g. the mortar copy of DECK, one build for both)
set -euo pipefail

if [[ $# -lt 3 ]]; then
  sed -n '2,15p' "$0" >&2
  exit 2
fi
decks=("$(realpath "$1")" "$(realpath "${DECK_B:-$1}")")
programs=("$(realpath "$2")" "$(realpath "$3")")
repeats=${4:-3}
work=${WORK:-/tmp/hertz_alternate}
for p in "${programs[@]}"; do [[ -x $p ]] || { echo "alternate.sh: $p is not executable" >&2; exit 2; }; done
[[ -f ${decks[0]} && -f ${decks[1]} ]] || { echo "alternate.sh: no deck ${decks[*]}" >&2; exit 2; }
mkdir -p "$work"

declare -a cpu_a cpu_b rss_a rss_b
for ((r = 1; r <= repeats; ++r)); do
  for k in 0 1; do
    label=$([[ $k == 0 ]] && echo A || echo B)
    dir=$work/$label.$r
    rm -rf "$dir" && mkdir -p "$dir" && cp "${decks[$k]}" "$dir/hertz.inp"
    load=$(cut -d' ' -f1 /proc/loadavg)
    (cd "$dir" && OMP_NUM_THREADS=1 /usr/bin/time -v "${programs[$k]}" run hertz.inp -o . -q 2> time.txt > /dev/null) ||
      { echo "alternate.sh: run $label.$r failed, see $dir/time.txt" >&2; exit 1; }
    user=$(awk -F': ' '/User time/ {print $2}' "$dir/time.txt")
    sys=$(awk -F': ' '/System time/ {print $2}' "$dir/time.txt")
    kb=$(awk -F': ' '/Maximum resident/ {print $2}' "$dir/time.txt")
    wall=$(awk -F': ' '/Elapsed/ {print $2}' "$dir/time.txt")
    cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN {printf "%.2f", u + s}')
    rss=$(awk -v k="$kb" 'BEGIN {printf "%.1f", k / 1024}')
    its=$(grep -c 'iteration  *[1-9]' "$dir/hertz.msg" || true)
    echo "$label run $r: CPU $cpu s (user $user, sys $sys), RSS $rss MiB, wall $wall, load $load, $its iterations"
    if [[ $k == 0 ]]; then cpu_a+=("$cpu") rss_a+=("$rss"); else cpu_b+=("$cpu") rss_b+=("$rss"); fi
    rm -f "$dir"/*.vtu
  done
done

# Median and range of a list of numbers.
summary() { printf '%s\n' "$@" | sort -g | awk '{v[NR] = $1} END {m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "%.2f (%.2f-%.2f)", m, v[1], v[NR]}'; }
echo "A ${programs[0]}: CPU $(summary "${cpu_a[@]}") s, RSS $(summary "${rss_a[@]}") MiB"
echo "B ${programs[1]}: CPU $(summary "${cpu_b[@]}") s, RSS $(summary "${rss_b[@]}") MiB"
