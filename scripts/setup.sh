#!/usr/bin/env bash
# Shared set-up of run.sh and test.sh: install what is missing (Debian 12),
# then configure and build Release into build/.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config git libeigen3-dev nlohmann-json3-dev
          libcli11-dev libpng-dev zlib1g-dev libosmesa6-dev libfreetype-dev fonts-dejavu-core ffmpeg
          libgtest-dev googletest libopenmpi-dev openmpi-bin)
# The compiler: CXX (and CC) where set, else the one scripts/pick_compiler.sh
# picks for this processor (clang where it has no AVX-512; why is there).
if [ -n "${CXX:-}" ]; then
  read -r cc cxx why <<< "${CC:-cc} $CXX (CXX is set)"
else
  read -r cc cxx why <<< "$(scripts/pick_compiler.sh)"
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
