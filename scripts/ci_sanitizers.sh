#!/usr/bin/env bash
# CI's second stage (after scripts/test.sh): the input-facing tests built with AddressSanitizer +
# UndefinedBehaviorSanitizer (CMake preset "asan", clang, build-asan/), then a short bounded fuzz
# run of every input format (scripts/fuzz.sh, same build). Prints the time of each step.
#   bash scripts/ci_sanitizers.sh [FUZZ_SECONDS_PER_FORMAT]     (default 3)
# Only the fuzz targets' test executable (rpt_fuzz_tests: every format's seeds, cut and flipped,
# plus the regressions) is built and run sanitized: it is what reads untrusted bytes, and building
# more sanitized would not fit CI's time (docs/robustness.md has the numbers). RPT_ASAN_TESTS
# overrides the list, e.g. RPT_ASAN_TESTS="rpt_datasets_tests rpt_fuzz_tests".
set -euo pipefail
cd "$(dirname "$0")/.."
FUZZ_SECONDS="${1:-3}"
read -r -a TESTS <<<"${RPT_ASAN_TESTS:-rpt_fuzz_tests}"
step() { echo "== $1: $(( $(date +%s) - $2 )) s"; }

t=$(date +%s)
cmake --preset asan >/dev/null
cmake --build build-asan -j"$(nproc)" --target "${TESTS[@]}" >/dev/null
step "sanitized build of ${TESTS[*]}" "$t"
t=$(date +%s)
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
for test in "${TESTS[@]}"; do
  exe=$(find build-asan -name "$test" -type f -perm -u+x | head -1)
  "$exe" --gtest_brief=1
done
step "sanitized tests" "$t"
t=$(date +%s)
bash scripts/fuzz.sh "$FUZZ_SECONDS"
step "fuzz build and run ($FUZZ_SECONDS s per format)" "$t"
