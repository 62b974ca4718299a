#!/usr/bin/env bash
# Installs the Debian 12 packages Klueng needs to build, test and run,
# skipping those already present. Run as root (or with sudo).
set -euo pipefail

packages=(
  build-essential cmake ccache pkg-config clang libclang-rt-14-dev
  qt6-base-dev qt6-base-dev-tools qt6-tools-dev qt6-tools-dev-tools qt6-l10n-tools
  qt6-svg-dev libgl-dev
  libeigen3-dev libfmt-dev libpng-dev nlohmann-json3-dev libdxflib-dev
  libgtest-dev libgmock-dev googletest libbenchmark-dev
  fonts-thai-tlwg xvfb xauth x11-apps poppler-utils
  desktop-file-utils shared-mime-info dpkg-dev file
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
