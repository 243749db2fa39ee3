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
  nodejs       # the Khronos glTF validator (tools/gltf) and playwright-core (tools/browser)
  libcpp-httplib-dev   # morphogen breed's local HTTP server
  blender python3-numpy   # the species pack's import check (headless; Blender's glTF importer needs numpy)
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
# Debian's nodejs comes without npm; other builds of nodejs bundle it.
command -v npm >/dev/null || missing+=(npm)
install_node_tool() {
  # tools/NAME/package-lock.json pins it; npm ci only when it is not there yet.
  local name=$1 module=$2 tools
  tools="$(cd "$(dirname "$0")/.." && pwd)/tools/$name"
  if [ -d "$tools/node_modules/$module" ]; then
    echo "setup: $module present"
  else
    echo "setup: installing $module in tools/$name"
    (cd "$tools" && npm ci --no-audit --no-fund --loglevel=error)
  fi
}
install_node_tools() {
  install_node_tool gltf gltf-validator        # the Khronos glTF validator
  install_node_tool browser playwright-core    # drives Debian's Chromium in browser tests
}

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all packages present"
  install_node_tools
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
install_node_tools
