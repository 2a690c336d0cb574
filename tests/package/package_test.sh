#!/usr/bin/env bash
# Installs tether from the build tree into a scratch prefix, builds a consumer
# project with find_package(tether) and runs it on the demo deck.
set -euo pipefail
source_dir=$1 build_dir=$2
work=$build_dir/tests/package/scratch
rm -rf "$work" && mkdir -p "$work"
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
cmake -S "$source_dir/tests/package/consumer" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/build" >/dev/null
out=$("$work/build/consumer" "$source_dir/examples/lame/lame.inp")
echo "$out"
grep -q "analysis complete" <<<"$out"

# The Python package, when the build made it: installed beside the library,
# imported from the prefix (its RPATH finds the installed libtether).
site=$(ls -d "$work"/prefix/lib/python3*/dist-packages 2>/dev/null | head -1 || true)
if [ -n "$site" ]; then
  cd "$work"
  PYTHONPATH="$site" /usr/bin/python3 -c "
import tether, sys
assert tether.__file__.startswith('$site'), tether.__file__
job = tether.Job(tether.read_deck(sys.argv[1]))
summary = job.run()
print('python:', summary.message, job.results[-1].U.shape)
assert summary.completed
" "$source_dir/examples/lame/lame.inp"
fi
