#!/usr/bin/env bash
# Shared set-up of run.sh and test.sh: install what is missing (Debian 12),
# then configure and build Release into build/.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config git libeigen3-dev nlohmann-json3-dev
          libcli11-dev libpng-dev zlib1g-dev libosmesa6-dev libfreetype-dev fonts-dejavu-core ffmpeg
          libgtest-dev googletest libopenmpi-dev openmpi-bin)
# The compiler: clang, unless CXX (and CC) name another. The step computes
# eight points at once in 64-byte vectors (Lane8, sim/physics/lanes.hpp).
# Without AVX-512, g++ 12 keeps such a vector in memory and takes its shuffles
# and selects apart lane by lane, where clang 14 splits it into two AVX
# registers: built for AVX2, the 66,787-point slope's step took 496 to 505 ns
# a point-step with g++ and 90 to 106 with clang. With AVX-512 clang was
# ahead too: the gallery's paper figures in 132 to 136 s against 140 to 145, the
# granular column 1.05 to 1.11 times g++'s point-steps a second on one thread.
# Both give the same bits (issue 17, twenty-eighth pass, bench/README.md).
if [ -n "${CXX:-}" ]; then
  cc=${CC:-cc} cxx=$CXX why="(CXX is set)"
else
  cc=clang cxx=clang++ why="(the default: a faster step than g++, the same bits; scripts/setup.sh)"
fi
# llvm: llvm-ar for clang's link-time optimisation; libomp-dev: clang's OpenMP.
if [ "$cxx" = clang++ ]; then packages+=(clang llvm libomp-dev); fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}"
  sudo_cmd=()
  [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}"
fi

echo "compiler: $cxx $why"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx" >/dev/null
cmake --build build --parallel "$(nproc)"
