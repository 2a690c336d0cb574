#!/usr/bin/env bash
# Installs tether from the build tree into a scratch prefix, builds
# examples/user_constraint with its own CMakeLists.txt against the installed
# package (as a user would), then loads the resulting plug-in from a plain-C
# driver compiled against the installed header and checks its outputs.
set -euo pipefail
source_dir=$1 build_dir=$2
work=$build_dir/tests/constraints/user_constraint_scratch
rm -rf "$work" && mkdir -p "$work"
# Everything `cmake --install` copies must exist, also when only the test
# executables were built.
cmake --build "$build_dir" --target tether tether_cli >/dev/null
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
header=$work/prefix/include/tether/constraints/user_constraint.h
test -f "$header" || { echo "not installed: $header" >&2; exit 1; }
cmake -S "$source_dir/examples/user_constraint" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/build" >/dev/null
library=$work/build/libequal_displacement.so
test -f "$library" || { echo "example did not produce $library" >&2; exit 1; }
# The header must be valid C (no C++ or Eigen in it).
cc -std=c99 -Wall -Wextra -Werror -pedantic -I"$work/prefix/include" \
  "$source_dir/tests/constraints/user_constraint_driver.c" -o "$work/driver" -ldl -lm
"$work/driver" "$library"
