#!/usr/bin/env bash
# Installs vemcast's build and test dependencies from Debian 12's packages, only when missing.
# Run as root (the README's two commands call it). Safe to run again: installs nothing twice.
set -euo pipefail
packages=(
  build-essential cmake ninja-build pkg-config ccache
  libglm-dev libnanoflann-dev libopenexr-dev libimath-dev libopencv-dev libcli11-dev
  nlohmann-json3-dev libtbb-dev
  libspdlog-dev libliquid-dev libtomlplusplus-dev
  libprotobuf-dev protobuf-compiler libboost-dev libzstd-dev libisal-dev libssl-dev
  libsystemd-dev
  libmosquitto-dev mosquitto      # MQTT: vemd publishes through a broker; tests start their own on loopback
  libaravis-dev libusb-1.0-0-dev aravis-tools libcamera-dev v4l-utils iproute2 util-linux openssl
  libembree-dev libglfw3-dev libepoxy-dev libegl-dev libegl1-mesa-dev libgl1-mesa-dri libegl-mesa0
  libtinyobjloader-dev libtinygltf-dev xvfb xauth librsvg2-bin
  libgtest-dev libgmock-dev libbenchmark-dev
  dpkg-dev file                  # cpack -G DEB: dpkg-shlibdeps finds the Depends
  clang-14 libclang-rt-14-dev
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "deps.sh: installing ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -q
  apt-get install -y -q --no-install-recommends "${missing[@]}"
fi
