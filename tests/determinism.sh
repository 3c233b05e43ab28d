#!/usr/bin/env bash
# Compares the output of two builds of `impact` byte for byte (`make determinism` builds an -O0
# one and compares it with $(BUILD), which is -O3; a restructuring compares a build of the commit
# before it with one after): every shipped scene with a [method] table (experiments/*/*.toml), run
# with every method, as it is and moved close to the floor so that the contact branches run
# thousands of times, writing the channels u, v, N and E, its events (--events) and its errors
# against the reference (--against exact; the summary lines compared with their wall times cut),
# and one sweep per scene and method (two steps, the default quantities). Prints one line per
# method and exits 1 on any difference. Usage: tests/determinism.sh BUILD_A BUILD_B
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
# Runs `impact ARGS` with both builds (the events of a run to a file of each) and counts the
# outcome: same bytes (rows, events, summary lines without their wall times), different, or refused
# by both.
compare() {
  local code_a=0 code_b=0 events=()
  [ "$1" = run ] && events=(--events "$out/a.ev")
  "$a" "$@" "${events[@]}" >"$out/a.csv" 2>"$out/a.err" || code_a=$?
  [ "$1" = run ] && events=(--events "$out/b.ev")
  "$b" "$@" "${events[@]}" >"$out/b.csv" 2>"$out/b.err" || code_b=$?
  sed -i 's/[0-9.]* s wall//g' "$out/a.err" "$out/b.err"
  if [ "$code_a" -ne "$code_b" ]; then
    echo "DIFFERENT EXIT CODES ($code_a, $code_b): impact $*" >&2
    differ=$((differ + 1))
  elif [ "$code_a" -ne 0 ]; then
    refused=$((refused + 1))  # e.g. penalty with floor.cor: refused by both
  elif cmp -s "$out/a.csv" "$out/b.csv" && cmp -s "$out/a.err" "$out/b.err" &&
       { [ "$1" != run ] || cmp -s "$out/a.ev" "$out/b.ev"; }; then
    same=$((same + 1))
  else
    echo "DIFFERENT OUTPUT: impact $*" >&2
    cmp "$out/a.csv" "$out/b.csv" | head -n 1 >&2 || true
    diff "$out/a.err" "$out/b.err" | head -n 4 >&2 || true
    differ=$((differ + 1))
  fi
}

failed=0
for method in direct fb_newton moreau_jean penalty exact event_driven; do
  same=0 differ=0 refused=0
  for scene in experiments/*/*.toml; do
    grep -q '^\[method\]' "$scene" || continue
    for variant in "${variants[@]}"; do
      # shellcheck disable=SC2086  # the variant is a list of options
      set -- run "$scene" --set "method.name=$method" --set 'output.channels=["u","v","N","E"]' \
        --against exact $variant
      compare "$@"
    done
    # One sweep per scene: its points go through summarize() or the ensemble, not run_scene().
    h=$(sed -n 's/^h *= *\([0-9.e+-]*\).*/\1/p' "$scene" | head -n 1)
    compare sweep "$scene" --set "method.name=$method" --vary "time.h=$h,$(awk "BEGIN{print $h/2}")"
  done
  printf '%-12s %3d runs byte-identical, %d different, %d refused by both\n' \
    "$method" "$same" "$differ" "$refused"
  [ "$differ" -eq 0 ] || failed=1
done
exit "$failed"
