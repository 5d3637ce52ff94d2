#!/usr/bin/env bash
# Fresh Debian 12 machine: install what is missing, build Release, run every test.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
ctest --test-dir build --output-on-failure --parallel "$(nproc)" --timeout 900
