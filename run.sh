#!/usr/bin/env bash
# Fresh Debian 12 machine: install what is missing, build Release, run the
# default scenario (the paper's slope with 1661 points) and say where its
# frames and videos are. Usage: ./run.sh [SCENARIO.json] [OUT_DIR]
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
scenario=${1:-scenarios/paper-slope-phi20-n1661.json}
out=${2:-out/$(basename "$scenario" .json)}
# --overwrite: run.sh always writes into the same folder, replacing its last run.
build/app/landslide run "$scenario" --out "$out" --overwrite
echo "outputs in $out:"
echo "  summary: $out/summary.json"
[ -f "$out/series.csv" ] && echo "  time series: $out/series.csv, $out/series.png"
shopt -s nullglob
for dir in "$out"/frames/*/; do
  field=$(basename "$dir")
  frames=("$dir"[0-9][0-9][0-9][0-9][0-9][0-9].png)
  echo "  $field: ${#frames[@]} frames in ${dir%/}/"
  for video in "$out/$field.mp4" "$out/$field.gif"; do
    [ -f "$video" ] && echo "    $video"
  done
done
[ -d "$out/vtk" ] && echo "  VTK states: $out/vtk/points.pvd"
exit 0
