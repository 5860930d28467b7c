#!/usr/bin/env bash
# Installs the Debian 12 packages plyimpact needs to build and test, only if some are missing.
# Fast no-op when everything is present. Needs root (or sudo) when something must be installed.
set -euo pipefail

packages=(
  cmake ninja-build g++ pkg-config
  libgmsh-dev libeigen3-dev libvtk9-dev libyaml-cpp-dev libgtest-dev libbenchmark-dev
  gnuplot-nox   # PNG plots (plyimpact plot, dcb-reduce), headless: pngcairo terminal, no X11
  # tools/paraview_view.py renders with VTK's Python when ParaView is absent; Debian's VTK needs an
  # X server even off screen, so the test that renders it headlessly runs under xvfb-run (needs xauth).
  python3-vtk9 xvfb xauth
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi

echo "plyimpact: installing missing packages: ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then sudo_cmd=(sudo); else
    echo "plyimpact: need root to install ${missing[*]} (run as root or install sudo)" >&2; exit 1
  fi
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "plyimpact: packages installed"
