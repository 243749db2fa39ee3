#!/usr/bin/env bash
# Installs the Debian packages morphogen needs to build and test. Idempotent:
# installs only what is missing; runs apt-get as root or through sudo.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libeigen3-dev libcgal-dev libboost-dev libgmp-dev libmpfr-dev
  nlohmann-json3-dev libvalijson-dev libspdlog-dev libfmt-dev libcli11-dev
  libtinygltf-dev libstb-dev catch2
  libjs-three chromium python3   # report: three.js copied into each report; its browser tests
  libopenmpi-dev openmpi-bin
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

sudo=()
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo=(sudo)
fi
echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${sudo[@]}" apt-get update -qq
"${sudo[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
