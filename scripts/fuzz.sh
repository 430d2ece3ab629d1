#!/usr/bin/env bash
# Fuzzes every input format with libFuzzer (clang, ASan + UBSan), one format after the other.
#   bash scripts/fuzz.sh [SECONDS_PER_FORMAT [FORMAT...]]     (default 60 s, every format)
# Builds the fuzzers of the "asan" preset (CMakePresets.json) into build-asan/, writes the seed corpora the project generates
# (rpt_fuzz_seeds) to build-asan/corpus/<format>/seeds, keeps what each run finds in
# build-asan/corpus/<format>/found (reused by the next run), crash inputs in
# build-asan/artifacts/<format>/, one log per format in build-asan/logs/, and prints one line per
# format: runs, seconds, coverage, result. Exits 1 when any format crashed, leaked, hit a
# sanitizer report, a timeout (10 s per input) or the memory limit (2 GB).
# Environment: RPT_FUZZ_JOBS (build jobs, default nproc), RPT_FUZZ_NICE (default 19).
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_FORMAT="${1:-60}"
shift || true
BUILD_DIR=build-asan
NICE="nice -n ${RPT_FUZZ_NICE:-19}"

cmake --preset asan >/dev/null
mapfile -t ALL < <(sed -n '/^set(RPT_FUZZ_TARGETS/,/)/p' fuzz/CMakeLists.txt | tr ' ()' '\n\n\n' | grep -v -e '^$' -e '^set$' -e '^RPT_FUZZ_TARGETS$')
FORMATS=("$@")
if [ ${#FORMATS[@]} -eq 0 ]; then FORMATS=("${ALL[@]}"); fi
TARGETS=(rpt_fuzz_seeds)
for f in "${FORMATS[@]}"; do TARGETS+=("rpt_fuzz_$f"); done
$NICE cmake --build "$BUILD_DIR" -j"${RPT_FUZZ_JOBS:-$(nproc)}" --target "${TARGETS[@]}" >/dev/null

rm -rf "$BUILD_DIR/corpus/"*/seeds
"$BUILD_DIR/fuzz/rpt_fuzz_seeds" "$BUILD_DIR/corpus-seeds"
mkdir -p "$BUILD_DIR/logs"
failed=0
printf '%-22s %10s %8s %8s  %s\n' format runs seconds cov result
for f in "${FORMATS[@]}"; do
  corpus="$BUILD_DIR/corpus/$f"
  mkdir -p "$corpus/found" "$corpus/seeds" "$BUILD_DIR/artifacts/$f"
  cp "$BUILD_DIR/corpus-seeds/$f/"* "$corpus/seeds/"
  log="$BUILD_DIR/logs/$f.log"
  start=$(date +%s)
  status=0
  ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1" UBSAN_OPTIONS="print_stacktrace=1" \
    $NICE "$BUILD_DIR/fuzz/rpt_fuzz_$f" -max_total_time="$SECONDS_PER_FORMAT" -timeout=10 -rss_limit_mb=2048 \
    -malloc_limit_mb=2048 -max_len=65536 -print_final_stats=1 -artifact_prefix="$BUILD_DIR/artifacts/$f/" \
    "$corpus/found" "$corpus/seeds" >"$log" 2>&1 || status=$?
  seconds=$(( $(date +%s) - start ))
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  result=ok
  if [ "$status" != 0 ]; then
    result="FAILED (exit $status): $(grep -m1 -E 'ERROR|SUMMARY|deadly|timeout|out-of-memory' "$log" || true) -- see $log"
    failed=1
  fi
  printf '%-22s %10s %8s %8s  %s\n' "$f" "${runs:-?}" "$seconds" "${cov:-?}" "$result"
done
exit $failed
