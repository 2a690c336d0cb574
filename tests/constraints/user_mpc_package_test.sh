#!/usr/bin/env bash
# Installs tether into a scratch prefix, builds examples/user_mpc with its own
# CMakeLists.txt against the installed package, and runs the example deck with
# the installed `tether` program: the rigid link's multiplier must be the exact
# -3.715326 (README of the example).
set -euo pipefail
source_dir=$1 build_dir=$2
work=$build_dir/tests/constraints/user_mpc_scratch
rm -rf "$work" && mkdir -p "$work/example"
cmake --build "$build_dir" --target tether tether_cli >/dev/null
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
test -f "$work/prefix/include/tether/constraints/user_mpc.h" || { echo "user_mpc.h not installed" >&2; exit 1; }
cp "$source_dir/examples/user_mpc/user_mpc.inp" "$work/example/"
cmake -S "$source_dir/examples/user_mpc" -B "$work/example/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/example/build" >/dev/null
"$work/prefix/bin/tether" run "$work/example/user_mpc.inp" -o "$work/out" -q
PYTHONPATH="$source_dir/tools" /usr/bin/python3 - "$work/out/user_mpc.dat" <<'PY'
import sys
import tethertools.dat
blocks = tethertools.dat.read(sys.argv[1])
link = tethertools.dat.last_block(blocks, "constraint multipliers", "LINK")["rows"][0][3]
print(f"user_mpc example: LINK multiplier {link:.6f} (exact -3.715326)")
sys.exit(0 if abs(link + 3.715326) < 2e-6 else 1)
PY
