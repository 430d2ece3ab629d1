#!/usr/bin/env bash
# Installs the Debian 12 packages rpt needs (run as root, or with sudo).
#   bash scripts/install_deps.sh           what building and running `rpt` needs
#   bash scripts/install_deps.sh --tests   that, plus what the tests, benchmarks and fuzzers need
set -euo pipefail
tests=0
case "${1:-}" in
  "") ;;
  --tests) tests=1 ;;
  *) echo "usage: bash scripts/install_deps.sh [--tests]" >&2; exit 2 ;;
esac
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# The build (with the Python module rpt: python3-dev, python3-numpy, pybind11-dev; docs/python.md;
# Highway, libhwy-dev, for the SIMD kernels chosen at run time: core/pipeline/simd_kernels.h),
# and three.js and Chart.js, which rpt report inlines into report.html at run time
# (engine/report/report_html.h).
$SUDO apt-get install -y -qq --no-install-recommends \
  build-essential cmake pkg-config ccache \
  libeigen3-dev libopencv-dev nlohmann-json3-dev libcli11-dev libhdf5-dev zlib1g-dev libtomlplusplus-dev libhwy-dev \
  python3-dev python3-numpy pybind11-dev \
  libjs-three libjs-chart.js >/dev/null
if [ "$tests" = 1 ]; then
  # GoogleTest, Google Benchmark, clang with libFuzzer (fuzz/), Chromium for the report's
  # browser test (tests/report/; skipped without it), pytest for the Python module's tests and
  # matplotlib for its example (tests/python/), and Slurm with munge for the one-node cluster of
  # scripts/ci_slurm.sh (`rpt sweep --slurm`; the packages' services are not started: the script
  # starts its own daemons).
  $SUDO apt-get install -y -qq --no-install-recommends \
    libgtest-dev libgmock-dev libbenchmark-dev clang libclang-rt-14-dev chromium \
    python3-pytest python3-matplotlib slurm-wlm munge >/dev/null
fi
echo "dependencies installed"
