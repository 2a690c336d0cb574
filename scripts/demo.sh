#!/usr/bin/env bash
# Installs what is missing, builds tether (Release) and runs the demo deck:
# the Lame thick cylinder, compared with the exact solution.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
# Only the program (and libtether): the tests and benchmarks are on by default
# in the CMake project (TETHER_BUILD_TESTS, TETHER_BUILD_BENCH) and test.sh
# builds them in the same build/ directory; the demo does not need them.
cmake --build build --parallel --target tether_cli
./build/bin/tether run examples/lame/lame.inp -o out/lame
/usr/bin/python3 tools/lame_summary.py out/lame/lame.dat
/usr/bin/python3 tools/plot_lame.py out/lame/lame_1_1.vtu out/lame/lame.png
echo "plot: out/lame/lame.png   ParaView: paraview out/lame/lame.pvd"
