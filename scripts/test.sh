#!/usr/bin/env bash
# Builds everything (library, CLI, tests, benchmarks) and runs every test, then the regression gates.
# Real-data tests read ../shared/data when it exists and are skipped otherwise.
# Prints the time of each step (CI watches its budget with them).
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR="${BUILD_DIR:-build}"
. scripts/step_time.sh
t=$(date +%s)
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release -DRPT_BUILD_TESTS=ON -DRPT_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)"
step build "$t"
t=$(date +%s)
ctest --test-dir "$BUILD_DIR" --output-on-failure -j"$(nproc)"
step tests "$t"
t=$(date +%s)
# Accuracy and speed regression gates (synthetic suites; real fixtures when ../shared/data exists).
"$BUILD_DIR/rpt" check --thresholds results/thresholds.json
step "regression gates" "$t"
