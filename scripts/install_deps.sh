#!/usr/bin/env bash
# Installs the build and test dependencies from Debian 12 packages (run as root, or with sudo).
set -euo pipefail
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  build-essential cmake pkg-config ccache \
  libeigen3-dev libopencv-dev nlohmann-json3-dev libcli11-dev libhdf5-dev zlib1g-dev \
  libgtest-dev libgmock-dev libbenchmark-dev \
  clang libclang-rt-14-dev >/dev/null
echo "dependencies installed"
