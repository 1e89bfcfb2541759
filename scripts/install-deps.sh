#!/usr/bin/env bash
# Installs, from Debian 12 packages, everything the project builds and runs
# with. Only packages that are missing are installed; `apt-get update` runs
# first whenever something is missing (package lists may be stale or empty).
set -euo pipefail

packages=(
  # build
  build-essential cmake pkg-config
  # libraries
  libopenimageio-dev openimageio-tools libglm-dev nlohmann-json3-dev libcli11-dev
  libtinygltf-dev libembree-dev libgtest-dev libgmock-dev libbenchmark-dev
  # external renderers and what Blender's glTF add-on needs
  povray blender python3-numpy
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "install-deps: installing ${missing[*]}"
$SUDO apt-get update
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
