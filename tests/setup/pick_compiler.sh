#!/usr/bin/env bash
# scripts/pick_compiler.sh on three made-up processors: the build's compiler
# follows the AVX-512 flag (avx512f), and a cpuinfo it cannot read leaves
# Debian's default.   tests/setup/pick_compiler.sh SOURCE_DIR
set -euo pipefail
pick=$1/scripts/pick_compiler.sh
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
flags="fpu sse sse2 avx avx2 fma bmi2"
printf 'processor\t: 0\nflags\t\t: %s avx512f avx512dq\n' "$flags" > "$dir/avx512"
printf 'processor\t: 0\nflags\t\t: %s avx512_vnni\n' "$flags" > "$dir/avx2"  # a look-alike flag only
printf 'processor\t: 0\nFeatures\t: fp asimd sve\n' > "$dir/arm"
failed=0
expect() {
  local file=$1 want=$2 got
  got=$("$pick" "$file" | cut -d' ' -f1-2)
  if [ "$got" != "$want" ]; then
    echo "FAIL: $file: picked '$got', expected '$want'"
    failed=1
  else
    echo "ok: $(basename "$file"): $("$pick" "$file")"
  fi
}
expect "$dir/avx512" "gcc g++"
expect "$dir/avx2" "clang clang++"
expect "$dir/arm" "clang clang++"
expect "$dir/none" "gcc g++"
exit $failed
