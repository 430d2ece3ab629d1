#!/usr/bin/env bash
# Builds everything (library, CLI, tests, benchmarks) and runs every test.
# Real-data tests read ../shared/data when it exists and are skipped otherwise.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${BUILD_DIR:-build}"
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DRPT_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"
ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$(nproc)"
# Accuracy and speed regression gates (synthetic suites; real fixtures when ../shared/data exists).
"$BUILD_DIR/rpt" check --thresholds results/thresholds.json
