#!/usr/bin/env bash
# Installs the build and test dependencies from Debian 12 packages (run as root, or with sudo).
set -euo pipefail
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends \
  build-essential cmake pkg-config ccache \
  libeigen3-dev libopencv-dev nlohmann-json3-dev libcli11-dev libhdf5-dev zlib1g-dev libtomlplusplus-dev \
  libgtest-dev libgmock-dev libbenchmark-dev \
  clang libclang-rt-14-dev >/dev/null
# rpt report: three.js and Chart.js, inlined into report.html at run time (engine/outputs/step_tables.html.h), and
# Chromium for the report's browser test (tests/report/; skipped without it).
$SUDO apt-get install -y -qq --no-install-recommends libjs-three libjs-chart.js chromium >/dev/null
echo "dependencies installed"
