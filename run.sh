#!/usr/bin/env bash
# Fresh Debian 12 machine: install what is missing, build Release, run the
# default scenario. Usage: ./run.sh [SCENARIO.json] [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
scenario=${1:-scenarios/elastic-column.json}
out=${2:-out/$(basename "$scenario" .json)}
build/app/landslide run "$scenario" --out "$out"
echo "outputs in $out"
