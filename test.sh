#!/usr/bin/env bash
# Fresh Debian 12 machine: install what is missing, build Release, run every test.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
# ctest runs one test per core; one OpenMP thread each keeps the cores from
# being oversubscribed (tests that need two threads ask for them).
OMP_NUM_THREADS=1 ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 900
