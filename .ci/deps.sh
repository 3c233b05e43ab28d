#!/usr/bin/env bash
# Installs the Debian packages impact needs, skipping those already present.
# Used by `make deps` (and so by `make all` and `make test`); `make docs` adds doxygen through
# IMPACT_EXTRA_PACKAGES.
set -euo pipefail
packages=(cmake make g++ libeigen3-dev libgsl-dev gnuplot-nox catch2 libtomlplusplus-dev libcli11-dev
          libmuparser-dev pkg-config pybind11-dev python3-numpy python3-pytest python3-matplotlib)
[ -n "${IMPACT_EXTRA_PACKAGES:-}" ] && read -r -a extra <<<"$IMPACT_EXTRA_PACKAGES" && packages+=("${extra[@]}")

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

if ! command -v apt-get >/dev/null 2>&1; then
  cat >&2 <<MSG
impact: missing packages: ${missing[*]}
This is not a Debian-like system, so install by hand: CMake >= 3.18, a C++20 compiler (g++ >= 12),
Eigen 3, GSL, gnuplot, Catch2 v2, toml++ v3 (compiled library), CLI11 v2, muparser, pkg-config
(and for the Python module: pybind11, NumPy, pytest, matplotlib; for make docs: doxygen),
then rerun make.
MSG
  exit 1
fi
sudo=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 || { echo "impact: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
echo "impact: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
