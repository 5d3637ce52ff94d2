#!/usr/bin/env bash
# Rewrites tests/regression/expected/ from the current code and prints every
# summary number that changed (old -> new) for the commit message.
# Only for an intended physics or painter change: see README.md, "Regression
# tests". Usage: scripts/update-regression.sh [BUILD_DIR]   (default: build)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
if [ ! -f "$build/build.ninja" ]; then
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi
cmake --build "$build" --target regression_tests
# Bit-identical for any thread count; one thread leaves the other cores alone.
OMP_NUM_THREADS=1 LANDSLIDE_UPDATE_REGRESSION=1 \
  "$build/tests/regression/regression_tests" --gtest_filter='PaperSlope/*' --gtest_brief=1 |
  grep -v '^\[' || true
echo
git status --short -- tests/regression/expected 2>/dev/null || true
echo "Look at the changed images (git difftool, or open them) before committing, and put the"
echo "changed numbers above into the commit message with the reason for the change."
