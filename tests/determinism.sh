#!/usr/bin/env bash
# Compares the output of two builds of `impact` byte for byte (`make determinism` builds an -O0
# one and compares it with $(BUILD), which is -O3): every shipped scene with a [method] table
# (experiments/*/*.toml), run with every method, as it is and moved close to the floor so that the
# contact branches run thousands of times. Prints one line per method and exits 1 on any
# difference. Usage: tests/determinism.sh BUILD_A BUILD_B
set -euo pipefail
cd "$(dirname "$0")/.."
a=${1:?usage: tests/determinism.sh BUILD_A BUILD_B}/impact
b=${2:?usage: tests/determinism.sh BUILD_A BUILD_B}/impact
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

variants=(
  ""
  "--set initial.u0=0.05 --set time.T=2"
  "--set initial.u0=0.05 --set time.T=2 --set force.f=-9.80665 --set time.h=3e-4"
  "--set initial.u0=1e-3 --set initial.v0=0 --set time.T=1 --set force.f=-1 --set floor.phi=-0.5"
)
failed=0
for method in direct fb_newton moreau_jean penalty exact event_driven; do
  same=0 differ=0 refused=0
  for scene in experiments/*/*.toml; do
    grep -q '^\[method\]' "$scene" || continue
    for variant in "${variants[@]}"; do
      # shellcheck disable=SC2086  # the variant is a list of options
      set -- run "$scene" -q --set "method.name=$method" $variant
      code_a=0 code_b=0
      "$a" "$@" >"$out/a.csv" 2>"$out/a.err" || code_a=$?
      "$b" "$@" >"$out/b.csv" 2>"$out/b.err" || code_b=$?
      if [ "$code_a" -ne "$code_b" ]; then
        echo "DIFFERENT EXIT CODES ($code_a, $code_b): impact $*" >&2
        differ=$((differ + 1))
      elif [ "$code_a" -ne 0 ]; then
        refused=$((refused + 1))  # e.g. penalty with floor.cor: refused by both
      elif cmp -s "$out/a.csv" "$out/b.csv"; then
        same=$((same + 1))
      else
        echo "DIFFERENT OUTPUT: impact $*" >&2
        cmp "$out/a.csv" "$out/b.csv" | head -n 1 >&2 || true
        differ=$((differ + 1))
      fi
    done
  done
  printf '%-12s %3d runs byte-identical, %d different, %d refused by both\n' \
    "$method" "$same" "$differ" "$refused"
  [ "$differ" -eq 0 ] || failed=1
done
exit "$failed"
