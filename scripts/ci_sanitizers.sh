#!/usr/bin/env bash
# CI's second stage (after scripts/test.sh): the tests of what reads untrusted bytes, built with
# AddressSanitizer + UndefinedBehaviorSanitizer (CMake preset "asan": clang, asserts on; here at
# -O0 with line tables only, which compiles a fifth faster than the preset's -O1 -g, in
# build-asan-ci/), then a short bounded coverage-guided fuzz run of every input format
# (scripts/fuzz.sh, same build, one format per core). Prints the time of each step.
#   bash scripts/ci_sanitizers.sh [FUZZ_SECONDS_PER_FORMAT]     (default 3)
#   bash scripts/ci_sanitizers.sh --build-only                  (the build step alone; .ci/run
#                                                                runs it beside scripts/test.sh)
# RPT_ASAN_TESTS lists the sanitized test executables (default rpt_fuzz_tests: every format's
# seeds, cut and flipped at 24 places each, and the regression inputs of every bug the fuzzers
# found), e.g. RPT_ASAN_TESTS="rpt_fuzz_tests rpt_datasets_tests" for all reader tests.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_ONLY=0
if [ "${1:-}" = "--build-only" ]; then BUILD_ONLY=1; shift; fi
FUZZ_SECONDS="${1:-3}"
read -r -a TESTS <<<"${RPT_ASAN_TESTS:-rpt_fuzz_tests}"
. scripts/step_time.sh

t=$(date +%s)
BUILD_DIR=build-asan-ci
cmake --preset asan -B "$BUILD_DIR" -DCMAKE_CXX_FLAGS_DEBUG="-O0 -g1" -DCMAKE_C_FLAGS_DEBUG="-O0 -g1" >/dev/null
cmake --build "$BUILD_DIR" -j"$(nproc)" --target "${TESTS[@]}" rpt_fuzz rpt_fuzz_seeds >/dev/null
step "sanitized build of ${TESTS[*]} and the fuzzer" "$t"
if [ "$BUILD_ONLY" = 1 ]; then exit 0; fi
t=$(date +%s)
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan_suppressions.txt:print_suppressions=0"
for test in "${TESTS[@]}"; do
  exe=$(find -H "$BUILD_DIR" -name "$test" -type f -perm -u+x | head -1)
  if [ -z "$exe" ]; then echo "ci_sanitizers.sh: no test executable $test in $BUILD_DIR" >&2; exit 1; fi
  "$exe" --gtest_brief=1
done
step "sanitized tests" "$t"
t=$(date +%s)
RPT_FUZZ_BUILD_DIR="$BUILD_DIR" RPT_FUZZ_NICE=0 RPT_FUZZ_PARALLEL="$(nproc)" bash scripts/fuzz.sh "$FUZZ_SECONDS"
step "fuzz run ($FUZZ_SECONDS s per format)" "$t"
