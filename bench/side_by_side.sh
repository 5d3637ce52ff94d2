#!/bin/bash
# Two builds of bench/throughput's size sweep in turns (before, after,
# before, after, ...), so that both see the same drift of this machine's
# speed, which moves single runs by up to 40 % from minute to minute. Prints,
# per row of the sweep and per thread count, the median of each binary's
# rounds with its range, and after / before of the medians. A bench: it
# prints figures and never fails on timing (bench/README.md).
#   bench/side_by_side.sh BEFORE AFTER [ROUNDS] [SIZE-SWEEP OPTIONS...]
# BEFORE and AFTER are throughput binaries; the options go to --sizes, e.g.
#   bench/side_by_side.sh old/build/bench/throughput build/bench/throughput 5 20 --up-to 2000000
# BEFORE_OPTIONS and AFTER_OPTIONS, if set, go to one binary only (a binary
# before the team rule knows no --exact-threads):
#   AFTER_OPTIONS=--exact-threads bench/side_by_side.sh OLD NEW 5 20
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 BEFORE AFTER [ROUNDS] [SIZE-SWEEP OPTIONS...]" >&2; exit 2; }
before=$1 after=$2
rounds=${3:-3}
shift $(($# < 3 ? $# : 3))
for b in "$before" "$after"; do
  [ -x "$b" ] || { echo "error: $b: not an executable" >&2; exit 2; }
done
rows=$(mktemp /tmp/side-by-side.XXXXXX)
trap 'rm -f "$rows"' EXIT
echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg); $rounds rounds of --sizes $*" \
  "(before: ${BEFORE_OPTIONS:-no more options}; after: ${AFTER_OPTIONS:-no more options})"
for ((r = 1; r <= rounds; ++r)); do
  for which in before after; do
    bin=$before options=${BEFORE_OPTIONS:-}
    [ "$which" = after ] && bin=$after options=${AFTER_OPTIONS:-}
    # A row of the sweep: refine, points, steps, 1-thread and 2-thread Mpt/s, ...
    # shellcheck disable=SC2086 # options are words
    "$bin" --sizes "$@" $options | awk -v w="$which" '$1 ~ /^[0-9]+$/ && NF >= 6 {print w, $2, $4, $5}' >> "$rows"
  done
  echo "round $r of $rounds done ($(date -u +%H:%M:%S) UTC)"
done
awk '
function median(list,   n, a, i, j, t) {
  n = split(list, a, " ")
  for (i = 2; i <= n; ++i) for (j = i; j > 1 && a[j - 1] > a[j]; --j) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
  return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
}
function range(list,   n, a, i, lo, hi) {
  n = split(list, a, " "); lo = a[1]; hi = a[1]
  for (i = 2; i <= n; ++i) { if (a[i] < lo) lo = a[i]; if (a[i] > hi) hi = a[i] }
  return sprintf("%.1f-%.1f", lo, hi)
}
{ key = $2; if (!(key in seen)) { seen[key] = 1; order[++count] = key }
  one[$1, key] = one[$1, key] " " $3; two[$1, key] = two[$1, key] " " $4 }
END {
  printf "%10s  %-22s %-22s %6s  %-22s %-22s %6s\n", "points", "1 thread before", "1 thread after",
         "ratio", "2 threads before", "2 threads after", "ratio"
  for (i = 1; i <= count; ++i) {
    k = order[i]
    b1 = median(one["before", k]); a1 = median(one["after", k])
    b2 = median(two["before", k]); a2 = median(two["after", k])
    printf "%10s  %5.1f (%-14s) %5.1f (%-14s) %6.2f  %5.1f (%-14s) %5.1f (%-14s) %6.2f\n", k,
           b1, range(one["before", k]), a1, range(one["after", k]), a1 / b1,
           b2, range(two["before", k]), a2, range(two["after", k]), a2 / b2
  }
  print "M point-steps/s: median of the rounds (range); ratio: after / before of the medians"
}' "$rows"
