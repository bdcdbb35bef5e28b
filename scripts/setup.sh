#!/usr/bin/env bash
# Installs the Debian 12 packages turf needs. The one place that lists them
# (docker/ uses this script too). Idempotent: installs only what is missing.
# clang + libclang-rt are for the libFuzzer targets (tests/fuzz.cmake).
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build ccache pkg-config
  libfastrtps-dev libfastcdr-dev fastddsgen default-jre-headless fastdds-tools
  libmujoco-dev libqhull-dev libtinyxml2-dev  # tinyxml2: composing robot MJCF files (core/legged)
  libeigen3-dev libfmt-dev libspdlog-dev libyaml-cpp-dev libcli11-dev
  libprotobuf-dev protobuf-compiler
  libgtest-dev gdb  # gdb: a test still running at its deadline prints its threads' stacks (tests/support/watchdog.cpp)
  iproute2 nftables  # multi-host tests: network namespaces, veth, multicast blocked (tests/multihost)
  clang libclang-rt-14-dev clang-format  # clang-format: scripts/check-format.sh (CI)
  libboost-dev nlohmann-json3-dev chromium chromium-driver  # turf-viewer (Boost.Beast, JSON) and its browser test
  openssl  # turf security init: the CA, certificates and signed permissions of DDS Security
  libzstd-dev liblz4-dev  # MCAP recordings (codecs/mcap): zstd- or lz4-compressed chunks
  python3-pybind11 pybind11-dev python3-numpy python3-pytest  # `import turf` (python/) and its tests
  cyclonedds-dev cyclonedds-tools  # a second DDS implementation: the Booster SDK topics across vendors (tests/booster)
  libegl-dev libegl-mesa0 libgl1-mesa-dri  # turf-render: offscreen OpenGL through EGL (Mesa llvmpipe without a GPU)
  libjpeg62-turbo-dev  # turf-render: JPEG camera images (codecs/image)
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
