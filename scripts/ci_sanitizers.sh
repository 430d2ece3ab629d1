#!/usr/bin/env bash
# CI's second stage (after scripts/test.sh): the tests of what reads untrusted bytes, built with
# AddressSanitizer + UndefinedBehaviorSanitizer (CMake preset "asan": clang, -O1, asserts on,
# build-asan/), then a short bounded coverage-guided fuzz run of every input format
# (scripts/fuzz.sh, same build, one format per core). Prints the time of each step.
#   bash scripts/ci_sanitizers.sh [FUZZ_SECONDS_PER_FORMAT]     (default 3)
# RPT_ASAN_TESTS lists the sanitized test executables (default rpt_fuzz_tests: every format's
# seeds, cut and flipped at 24 places each, and the regression inputs of every bug the fuzzers
# found), e.g. RPT_ASAN_TESTS="rpt_fuzz_tests rpt_datasets_tests" for all reader tests.
set -euo pipefail
cd "$(dirname "$0")/.."
FUZZ_SECONDS="${1:-3}"
read -r -a TESTS <<<"${RPT_ASAN_TESTS:-rpt_fuzz_tests}"
step() { echo "== $1: $(( $(date +%s) - $2 )) s"; }

t=$(date +%s)
cmake --preset asan >/dev/null
cmake --build build-asan -j"$(nproc)" --target "${TESTS[@]}" rpt_fuzz rpt_fuzz_seeds >/dev/null
step "sanitized build of ${TESTS[*]} and the fuzzer" "$t"
t=$(date +%s)
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1" UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
export LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan_suppressions.txt:print_suppressions=0"
for test in "${TESTS[@]}"; do
  exe=$(find build-asan -name "$test" -type f -perm -u+x | head -1)
  "$exe" --gtest_brief=1
done
step "sanitized tests" "$t"
t=$(date +%s)
RPT_FUZZ_NICE=0 RPT_FUZZ_PARALLEL="$(nproc)" bash scripts/fuzz.sh "$FUZZ_SECONDS"
step "fuzz run ($FUZZ_SECONDS s per format)" "$t"
