#!/bin/bash
# Instructions a point-step of the step's functions execute, counted by
# valgrind's callgrind on bench/phases, one thread. The count is the same
# from run to run of one binary, where this machine's timings of one binary
# move by a quarter from minute to minute: a change that cuts instructions
# from the slope's step (about 600 a point-step in 52 to 63 ns on one
# thread) shows here in one run, where a timing needs rounds in turns
# (bench/README.md, "instructions.sh"). A bench: it prints figures
# and fails only when it cannot count.
#
# bench/phases runs 30 untimed steps and a scene's set-up before its STEPS
# steps; two runs of STEPS = A and B steps are counted and their difference
# divided by (B - A) x points, so set-up and warm-up drop out.
#   bench/instructions.sh [BUILD_DIR] [PHASES_ARGS...]
#   default PHASES_ARGS: --scene paper-slope-phi20 (8,370 points, at rest);
#   --column alone: bench/phases' granular column (25,538 points, collapsing)
# valgrind (Debian: apt-get install valgrind) does not run AVX-512 code: on
# a processor with it, build with -DLANDSLIDE_NATIVE=OFF
# -DCMAKE_CXX_FLAGS=-march=x86-64-v3 first.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=$repo/build
if [ $# -gt 0 ] && [ -d "$1" ]; then build=$(cd "$1" && pwd); shift; fi
phases=$build/bench/phases
[ -x "$phases" ] || { echo "error: $phases: not built (cmake --build $build)" >&2; exit 2; }
command -v valgrind > /dev/null || { echo "error: no valgrind (apt-get install valgrind)" >&2; exit 2; }
args=("$@")
[ ${#args[@]} -gt 0 ] || args=(--scene paper-slope-phi20)
[ "${args[*]}" != "--column" ] || args=()  # bench/phases' own scene, the granular column
work=$(mktemp -d /tmp/instructions.XXXXXX)
trap 'rm -rf "$work"' EXIT
low=10 high=40
for steps in $low $high; do
  valgrind --tool=callgrind --callgrind-out-file="$work/$steps.out" \
    "$phases" 1 "$steps" "${args[@]}" --threads 1 > "$work/$steps.txt" 2> "$work/$steps.err" ||
    { cat "$work/$steps.err" >&2; echo "error: valgrind on $phases failed" >&2; exit 2; }
  callgrind_annotate --threshold=100 "$work/$steps.out" > "$work/$steps.ann"
done
points=$(awk '/^total/ {gsub(/[(]/, "", $4); print $4}' "$work/$high.txt")
echo "bench/phases 1 {$low,$high} ${args[*]} --threads 1: $points points, hash $(awk '/^hash/ {print $2}' "$work/$high.txt")"
python3 - "$work/$low.ann" "$work/$high.ann" "$points" "$((high - low))" <<'PY'
import re, sys
def self_counts(path):
    counts = {}
    for line in open(path):
        m = re.match(r'\s*([\d,]+) \([ \d.]+%\)\s+(?:[^:]*):(.*?)(?: \[[^\]]*\])?$', line)
        if m and 'PROGRAM TOTALS' not in line:
            counts[m.group(2)] = counts.get(m.group(2), 0) + int(m.group(1).replace(',', ''))
    return counts
low, high = self_counts(sys.argv[1]), self_counts(sys.argv[2])
point_steps = int(sys.argv[3]) * int(sys.argv[4])
rows = sorted(((high.get(f, 0) - low.get(f, 0)) / point_steps, f) for f in set(low) | set(high))
total = sum(r for r, _ in rows)
print(f"{total:8.1f}  instructions a point-step in all; by function (self), at least 0.5:")
for per_point, name in reversed(rows):
    if per_point >= 0.5:
        print(f"{per_point:8.1f}  {name[:110]}")
PY
