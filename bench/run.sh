#!/usr/bin/env bash
# Runs tether_bench_assembly_solve for every size, each phase in its own
# process (so every peak-memory figure belongs to one size and one phase),
# and prints a Markdown table on stdout. Progress and the programs' readable
# reports go to stderr.
#
# Usage: bench/run.sh [BUILD_DIR]            (default: build-bench next to bench/)
# Environment:
#   SIZES="small medium large"   sizes to run (~20k, ~200k, ~1M dofs)
#   REPEAT=5                     repetitions of pattern build and assembly (best reported)
#   SOLVE_REPEAT=2               repetitions of each factorization + solve (best reported);
#                                the large size uses SOLVE_REPEAT_LARGE=1
#   ROUNDS=1                     whole runs per size and phase; the best of each figure is kept
#   THREADS=1,2                  thread counts for pattern build and assembly
#   WAIT_LOAD=1.0                before each process, wait (up to WAIT_MAX=900 s) until the
#                                1-minute load average is below this; empty: do not wait
# The end-to-end runs use OMP_NUM_THREADS as set (default: all cores).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../build-bench}
bin=$build/bin/tether_bench_assembly_solve
[[ -x $bin ]] || { echo "run.sh: $bin not found; build the target tether_bench_assembly_solve first" >&2; exit 1; }

sizes=${SIZES:-small medium large}
repeat=${REPEAT:-5}
solve_repeat=${SOLVE_REPEAT:-2}
solve_repeat_large=${SOLVE_REPEAT_LARGE:-1}
wait_load=${WAIT_LOAD-1.0}
wait_max=${WAIT_MAX:-900}
rounds=${ROUNDS:-1}
threads=${THREADS:-1,2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# merge FILE < new key=value lines: keeps the minimum of every figure
# (times and peaks alike; counts are equal between rounds).
merge() {
  local file=$1
  touch "$file"
  awk -F= 'NR == FNR { v[$1] = $2; order[++n] = $1; next }
           { k = $1; if (!(k in v)) { order[++n] = k; v[k] = $2 }
             else if ($2 ~ /^[-0-9.eE+]+$/ && $2 + 0 < v[k] + 0) v[k] = $2 }
           END { for (i = 1; i <= n; ++i) print order[i] "=" v[order[i]] }' \
      "$file" <(sed -n 's/^@//p') > "$file.tmp"
  mv "$file.tmp" "$file"
}

load1() { cut -d' ' -f1 /proc/loadavg; }
wait_quiet() {
  [[ -z $wait_load ]] && return
  local waited=0
  while awk -v l="$(load1)" -v m="$wait_load" 'BEGIN { exit !(l >= m) }' && ((waited < wait_max)); do
    sleep 10
    waited=$((waited + 10))
  done
}

merge_max() {  # file < one key=value line: keeps the maximum (load averages)
  local file=$1 line key value old
  touch "$file"
  IFS= read -r line
  key=${line#@}; key=${key%%=*}; value=${line#*=}
  old=$(sed -n "s/^$key=//p" "$file")
  if [[ -z $old ]]; then echo "$key=$value" >> "$file"
  elif awk -v a="$value" -v b="$old" 'BEGIN { exit !(a > b) }'; then sed -i "s/^$key=.*/$key=$value/" "$file"; fi
}

run_phase() {  # size tag args...
  local size=$1 tag=$2
  shift 2
  wait_quiet
  local load
  load=$(load1)
  echo "== $size $tag (load average: $(cut -d' ' -f1-3 /proc/loadavg))" >&2
  echo "@load_max=$load" | merge_max "$work/$size.kv"
  local rc=0
  "$bin" --size "$size" "$@" > "$work/out.txt" || rc=$?
  ((rc == 0)) || echo "run.sh: $size $tag exited with status $rc (figures so far are kept)" >&2
  sed "s/^@\([A-Za-z_0-9]*\)=/@${tag}_\1=/" "$work/out.txt" | merge "$work/$size.kv"
}

for size in $sizes; do
  for ((r = 0; r < rounds; ++r)); do
    sr=$solve_repeat
    [[ $size == large ]] && sr=$solve_repeat_large
    run_phase "$size" k --phase kernels --repeat "$repeat" --solve-repeat "$sr" --threads "$threads"
    run_phase "$size" a --phase analysis
    rm -rf "$work/out"
    run_phase "$size" f --phase analysis --write "$work/out"
    du -sk "$work/out" | awk '{ print "@f_files_mib=" $1 / 1024 }' | merge "$work/$size.kv"
  done
done

get() {  # size key -> value or "-"
  local v
  v=$(sed -n "s/^$2=//p" "$work/$1.kv" | head -n1)
  echo "${v:--}"
}
fmt_s() { [[ $1 == - ]] && echo - || printf '%.3f' "$1"; }
fmt_m() { [[ $1 == - ]] && echo - || printf '%.0f' "$1"; }
fmt_i() { [[ $1 == - ]] && echo - || printf "%'d" "$1"; }

row() {  # label formatter key
  local label=$1 f=$2 key=$3 line
  line="| $label |"
  for size in $sizes; do line+=" $($f "$(get "$size" "$key")") |"; done
  echo "$line"
}
sum_row() {  # label key1 key2 ...: sum of seconds
  local label=$1 line
  shift
  line="| $label |"
  for size in $sizes; do
    local total=0 v
    for k in "$@"; do
      v=$(get "$size" "$k")
      [[ $v == - ]] && { total=-; break; }
      total=$(awk -v a="$total" -v b="$v" 'BEGIN { print a + b }')
    done
    line+=" $(fmt_s "$total") |"
  done
  echo "$line"
}

header="| figure |"
rule="| --- |"
for size in $sizes; do
  header+=" $size |"
  rule+=" ---: |"
done
echo "$header"
echo "$rule"
row "mesh (elements per side)" echo k_mesh
row "dofs (all)" fmt_i k_dofs
row "equations (free dofs)" fmt_i k_equations
row "nnz(K), both triangles" fmt_i k_nnz_K
row "nnz(L), CHOLMOD" fmt_i k_order_default_nnz_L
row "CHOLMOD factorization GFlop" fmt_s k_order_default_gflop
row "CHOLMOD ordering chosen" echo k_order_default_method
row "nnz(L) with METIS ordering (not used)" fmt_i k_order_metis_nnz_L
row "GFlop with METIS ordering (not used)" fmt_s k_order_metis_gflop
row "METIS analysis [s] (not used)" fmt_s k_order_metis_analyze_s
IFS=, read -r -a tlist <<< "$threads"
for t in "${tlist[@]}"; do row "pattern build, $t thread(s) [s]" fmt_s "k_pattern_s_t$t"; done
for t in "${tlist[@]}"; do row "**assembly r + K, $t thread(s) [s]**" fmt_s "k_assembly_s_t$t"; done
for t in "${tlist[@]}"; do row "residual only, $t thread(s) [s]" fmt_s "k_residual_only_s_t$t"; done
for solver in cholmod umfpack; do
  name=${solver^^}
  row "$name analyze (ordering) [s]" fmt_s "k_${solver}_analyze_s"
  row "$name factorize [s]" fmt_s "k_${solver}_factorize_s"
  row "$name solve [s]" fmt_s "k_${solver}_solve_s"
  row "**$name analyze + factorize + solve [s]**" fmt_s "k_${solver}_total_s"
  row "$name analyze + factorize + solve, CPU time [s]" fmt_s "k_${solver}_total_cpu_s"
  row "$name error" echo "k_${solver}_error"
  row "$name re-factorize, same pattern [s]" fmt_s "k_${solver}_refactorize_s"
  row "$name relative residual" echo "k_${solver}_relative_residual"
done
row "end to end, read + StaticAnalysis, no files [s]" fmt_s a_e2e_total_s
row "end to end with result files [s]" fmt_s f_e2e_files_total_s
row "  of which writing files [s]" fmt_s f_e2e_files_write_s
row "  result files [MiB]" fmt_s f_files_mib
row "peak RSS: model (deck text + Model + elements) [MiB]" fmt_m k_model_peak_mib
row "peak RSS: during CHOLMOD phase [MiB]" fmt_m k_cholmod_peak_mib
row "peak RSS: during UMFPACK phase [MiB]" fmt_m k_umfpack_peak_mib
row "peak RSS: kernels process [MiB]" fmt_m k_process_peak_mib
row "**peak RSS: end-to-end process, no files [MiB]**" fmt_m a_process_peak_mib
row "peak RSS: end-to-end process with files [MiB]" fmt_m f_process_peak_mib
row "1-min load average at start (max of the 3 processes)" echo load_max
