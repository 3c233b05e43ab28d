#!/usr/bin/env bash
# Writes the fuzzer's seed corpus into DIR: every shipped scene (experiments/*/*.toml) as it is,
# and each again with --set overrides (after NUL bytes, the layout fuzz_scene.cpp reads) that move
# it close to the floor so that the first steps reach contact, and that switch it to every method
# and output channel. Usage: tests/fuzz/seeds.sh DIR
set -euo pipefail
cd "$(dirname "$0")/../.."
out=${1:?usage: tests/fuzz/seeds.sh DIR}
mkdir -p "$out"
methods=(direct fb_newton moreau_jean penalty exact)
variants=(
  ""
  "initial.u0=0.05"
  "initial.u0=0.05|floor.cor=0.5"
  "initial.u0=0.05|floor.phi=-1e-3|force.f=-9.80665"
  "initial.u0=0.05|time.h=1e-4|output.every=7"
  "initial.u0=0|initial.v0=0|force.f=-1"
  "initial.u0=0.05|output.channels=[\"u\", \"v\", \"N\", \"E\", \"iterations\"]"
)
n=0
for scene in experiments/*/*.toml; do
  for method in "${methods[@]}"; do
    for variant in "${variants[@]}"; do
      file="$out/$(basename "$(dirname "$scene")")_$(basename "$scene" .toml)_${method}_$n"
      cat "$scene" >"$file"
      printf '\0%s' "method.name=$method" >>"$file"
      if [ -n "$variant" ]; then
        IFS='|' read -r -a sets <<<"$variant"
        printf '\0%s' "${sets[@]}" >>"$file"
      fi
      n=$((n + 1))
    done
  done
done
echo "tests/fuzz/seeds.sh: $n seeds in $out"
