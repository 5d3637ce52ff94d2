#!/usr/bin/env bash
# The compiler scripts/setup.sh builds with, from the processor's flags.
#   scripts/pick_compiler.sh [CPUINFO]   (default /proc/cpuinfo)
# Prints one line: the C compiler, the C++ compiler, then why.
#
# The step computes eight points at once in 64-byte vectors (Lane8,
# sim/physics/lanes.hpp). With AVX-512 both compilers keep one in a register.
# Without it, g++ 12 keeps a Lane8 in memory and takes its shuffles and
# selects apart lane by lane, where clang 14 splits it into two 32-byte
# halves. Built for AVX2 (-march=x86-64-v3) on the project's machine, the
# 66,787-point slope took 530 to 590 ns a point-step on one thread with g++
# and 90 to 124 with clang, the same bits (issue 17, twenty-eighth pass,
# bench/README.md). With AVX-512 the two were within the machine's drift of
# each other, and g++ stays: its code is the one the passes measured.
set -euo pipefail
cpuinfo=${1:-/proc/cpuinfo}
if [ ! -r "$cpuinfo" ]; then
  echo "gcc g++ ($cpuinfo unreadable: the Debian default)"
elif grep -qw avx512f "$cpuinfo"; then
  echo "gcc g++ (this processor has AVX-512)"
else
  echo "clang clang++ (no AVX-512 on this processor: g++ keeps the step's 8-lane vectors in memory)"
fi
