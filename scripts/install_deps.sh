#!/usr/bin/env bash
# Installs the Debian 12 packages the toolchain needs; does nothing when they are present.
set -euo pipefail
pkgs=(build-essential cmake ninja-build libdeal.ii-dev libgmsh-dev libhdf5-dev libeigen3-dev
      catch2 libcgal-dev python3-matplotlib python3-h5py python3-numpy)
missing=()
for p in "${pkgs[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#pkgs[@]} packages present"
  exit 0
fi
echo "install_deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO=sudo
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
