#!/usr/bin/env bash
# The examples against the installed package, as a program outside the repository uses it:
# installs BUILD (already built) to a temporary prefix, builds examples/ there with
# find_package(impact 0.2 COMPONENTS scene) and runs them, then compiles two by hand with
# pkg-config's flags (impact, impact-scene).
#   bash examples/check_installed.sh BUILD
set -euo pipefail
build=${1:?usage: check_installed.sh BUILD}
examples=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cmake --install "$build" --prefix "$tmp/prefix" > "$tmp/install.log"
cmake -S "$examples" -B "$tmp/b" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$tmp/prefix" > "$tmp/configure.log" 2>&1 ||
  { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/b" -j "${JOBS:-2}" > "$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; exit 1; }
for example in bouncing_ball ensemble_sweep scene_run; do
  echo "== $example (find_package(impact 0.2), impact::impact)"
  "$tmp/b/$example"
done
echo "== run_scene_file drop.toml (find_package(impact 0.2 COMPONENTS scene), impact::scene)"
"$tmp/b/run_scene_file" "$examples/drop.toml"
echo "== sweep_scene_file drop.toml (impact::sweep(), impact::scene)"
"$tmp/b/sweep_scene_file" "$examples/drop.toml"

echo "== bouncing_ball (pkg-config --cflags --libs impact)"
pc=$(find "$tmp/prefix" -name impact.pc)
export PKG_CONFIG_PATH="$(dirname "$pc")${PKG_CONFIG_PATH:+:$PKG_CONFIG_PATH}"
read -r -a flags <<<"$(pkg-config --cflags --libs impact)"
"${CXX:-c++}" -std=c++20 -O2 "$examples/bouncing_ball.cpp" "${flags[@]}" -o "$tmp/bouncing_ball_pc"
"$tmp/bouncing_ball_pc"
echo "== run_scene_file drop.toml (pkg-config --cflags --libs impact-scene)"
read -r -a flags <<<"$(pkg-config --cflags --libs impact-scene)"
"${CXX:-c++}" -std=c++20 -O2 "$examples/run_scene_file.cpp" "${flags[@]}" -o "$tmp/run_scene_file_pc"
"$tmp/run_scene_file_pc" "$examples/drop.toml"
echo "examples: built against the package installed from $build (CMake and pkg-config) and ran"
