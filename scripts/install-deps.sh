#!/usr/bin/env bash
# Installs the Debian packages tether needs to build, test and compare with CalculiX
# (and to build and test the Python package: pybind11, pytest, NumPy, meshio).
# Safe to run again: packages already present are skipped by apt-get.
#
#   bash scripts/install-deps.sh         what scripts/test.sh and scripts/demo.sh need
#   bash scripts/install-deps.sh fuzz    the same plus Clang and its libFuzzer/sanitizer
#                                        runtimes for scripts/fuzz.sh (about 350 MB more,
#                                        so not installed for everyone)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libsuitesparse-dev libmumps-seq-dev liblapack-dev libopenblas0-pthread libginac-dev
  libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  gmsh calculix-ccx
  python3 python3-numpy python3-matplotlib python3-meshio python3-vtk9
  python3-dev pybind11-dev python3-pybind11 python3-pytest
)
for group in "$@"; do
  case "$group" in
    fuzz) packages+=(clang-14 libclang-rt-14-dev llvm-14) ;;  # llvm-14: llvm-symbolizer for the reports
    *) echo "install-deps: unknown group '$group' (known: fuzz)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
