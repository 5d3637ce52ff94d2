#!/bin/bash
# The speed-up of `landslide sweep` on two MPI ranks: 8 members of the
# 1661-point paper slope over the friction angle of its trigger (14 to 28
# degrees), --threads 1, run in one process, under `mpirun -np 2`, and, for
# what the machine gives a second process at all, as two plain processes of
# 4 members each side by side; in turns (one, mpirun, two plain, one, ...)
# so that all see the same load. Prints the wall time of each and the
# speed-ups. A bench: it prints figures and never fails on timing
# (bench/README.md, "sweep_speedup.sh").
#   bench/sweep_speedup.sh [BUILD_DIR] [ROUNDS]
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "${1:-$repo/build}" && pwd)
rounds=${2:-2}
landslide=$build/app/landslide
mpirun=$(command -v mpirun || true)
[ -x "$landslide" ] || { echo "error: $landslide: not built (cmake --build $build)" >&2; exit 2; }
[ -n "$mpirun" ] || { echo "error: no mpirun (install openmpi-bin)" >&2; exit 2; }
work=$(mktemp -d /tmp/sweep-speedup.XXXXXX)
trap 'rm -rf "$work"' EXIT
cp "$repo/scenarios/paper-slope-phi20-n1661.json" "$work/base.json"
# The sweep (all 8 members) and its halves (a: the first 4, b: the last 4).
for name_values in "sweep:14, 16, 18, 20, 22, 24, 26, 28" "a:14, 16, 18, 20" "b:22, 24, 26, 28"; do
  cat > "$work/${name_values%%:*}.json" <<JSON
{"base": "base.json", "axes": [{"path": "stages.1.set.friction_angle", "values": [${name_values#*:}]}]}
JSON
done
cd "$work"
echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min)"
"$landslide" sweep sweep.json --out check --threads 1 --check | grep -v ': ok'

# Runs COMMAND... with its output in LOG; prints its wall seconds.
timed() {
  local log=$1 start end
  shift
  start=$(date +%s.%N)
  if ! "$@" > "$log" 2>&1; then
    echo "error: $* failed:" >&2
    cat "$log" >&2
    exit 1
  fi
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}

# Both halves side by side, as two processes without MPI, into DIR-a, DIR-b.
two_plain() {
  "$landslide" sweep a.json --out "$1-a" --threads 1 > "$1-a.log" 2>&1 &
  local a=$! b_status=0
  "$landslide" sweep b.json --out "$1-b" --threads 1 > "$1-b.log" 2>&1 || b_status=$?
  wait "$a" && return "$b_status"
}

printf '%-6s %14s %12s %15s %15s %15s\n' round "1 process [s]" "2 ranks [s]" "2 plain [s]" \
  "speed-up ranks" "speed-up plain"
for r in $(seq 1 "$rounds"); do
  one=$(timed "one-$r.log" "$landslide" sweep sweep.json --out "one-$r" --threads 1)
  two=$(timed "two-$r.log" "$mpirun" --oversubscribe --allow-run-as-root -np 2 \
    "$landslide" sweep sweep.json --out "two-$r" --threads 1)
  plain=$(timed "plain-$r.log" two_plain "plain-$r")
  printf '%-6s %14.2f %12.2f %15.2f %15.2f %15.2f\n' "$r" "$one" "$two" "$plain" \
    "$(echo "$one / $two" | bc -l)" "$(echo "$one / $plain" | bc -l)"
  cmp -s "one-$r/sweep.csv" "two-$r/sweep.csv" || echo "note: round $r: sweep.csv differs"
done
echo "load after: $(cut -d' ' -f1-3 /proc/loadavg)"
