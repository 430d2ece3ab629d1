#!/usr/bin/env bash
# Installs the Debian 12 packages rpt needs (run as root, or with sudo).
#   bash scripts/install_deps.sh            what building and running `rpt` needs
#   bash scripts/install_deps.sh --python   that, plus what the Python module needs (docs/python.md)
#   bash scripts/install_deps.sh --tests    all of it, plus what the tests, benchmarks and fuzzers need
set -euo pipefail
python=0
tests=0
case "${1:-}" in
  "") ;;
  --python) python=1 ;;
  --tests) python=1; tests=1 ;;
  *) echo "usage: bash scripts/install_deps.sh [--python | --tests]" >&2; exit 2 ;;
esac
SUDO=""
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
# The build (Ninja: README command 1 builds with it, 14 % faster than Makefiles on 2 cores,
# CONTRIBUTING.md); the OpenCV modules rpt uses, one package each (cmake/RptFindOpenCV.cmake: Debian's
# libopencv-dev would add about 120 packages rpt does not use); Highway (libhwy-dev) for the SIMD
# kernels chosen at run time (core/pipeline/simd_kernels.h); RE2 (libre2-dev) for --map-pattern,
# matched in linear time whatever the pattern; and three.js and Chart.js, which rpt
# report inlines into report.html at run time (engine/report/report_html.h).
$SUDO apt-get install -y -qq --no-install-recommends \
  build-essential cmake ninja-build pkg-config ccache \
  libeigen3-dev nlohmann-json3-dev libcli11-dev libhdf5-dev zlib1g-dev libtomlplusplus-dev libhwy-dev libre2-dev \
  libopencv-core-dev libopencv-imgproc-dev libopencv-imgcodecs-dev libopencv-videoio-dev \
  libjs-three libjs-chart.js >/dev/null
if [ "$python" = 1 ]; then
  # The Python module rpt (python/, docs/python.md).
  $SUDO apt-get install -y -qq --no-install-recommends python3-dev python3-numpy pybind11-dev >/dev/null
fi
if [ "$tests" = 1 ]; then
  # GoogleTest, Google Benchmark, OpenCV's calib3d (tests/core compares our projection with it),
  # clang with libFuzzer (fuzz/), Chromium for the report's
  # browser test (tests/report/; skipped without it), pytest for the Python module's tests,
  # matplotlib for its example and mypy for its type stubs' checks (tests/python/), the locale sources of Debian's locales (a test
  # compiles de_DE.UTF-8 into a scratch folder: a decimal comma must not change the module's
  # numbers; skipped without them), and Slurm with munge for the one-node cluster of
  # scripts/ci_slurm.sh (`rpt sweep --slurm`; the packages' services are not started: the script
  # starts its own daemons).
  $SUDO apt-get install -y -qq --no-install-recommends \
    libgtest-dev libgmock-dev libbenchmark-dev libopencv-calib3d-dev clang libclang-rt-14-dev chromium \
    python3-pytest python3-matplotlib python3-mypy locales slurm-wlm munge >/dev/null
fi
echo "dependencies installed"
