#!/usr/bin/env bash
# Fuzzes every input format with libFuzzer (clang, ASan + UBSan, coverage-guided).
#   bash scripts/fuzz.sh [SECONDS_PER_FORMAT [FORMAT...]]     (default 60 s, every format)
# Builds the fuzzer of the "asan" preset (CMakePresets.json): one executable, rpt_fuzz, whose
# format is chosen by RPT_FUZZ_TARGET. Writes the seed corpora the project generates
# (rpt_fuzz_seeds) to <build>/corpus/<format>/seeds, keeps what each run finds in
# <build>/corpus/<format>/found (reused by the next run), crash inputs in <build>/artifacts/<format>/,
# one log per format in <build>/logs/, and prints one line per format: inputs run, seconds of wall
# clock and of CPU, coverage, result. Exits 1 when any format crashed, leaked, hit a sanitizer
# report, a timeout (10 s per input) or the memory limit (2 GB). Bugs inside libraries we use are
# suppressed only as listed, with their upstream reports, in fuzz/lsan_suppressions.txt.
# Environment: RPT_FUZZ_BUILD_DIR (default build-asan), RPT_FUZZ_JOBS (build jobs, default nproc),
# RPT_FUZZ_NICE (default 19), RPT_FUZZ_PARALLEL (formats fuzzed at once, one core each; default 1).
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_FORMAT="${1:-60}"
shift || true
BUILD_DIR="${RPT_FUZZ_BUILD_DIR:-build-asan}"
NICE="nice -n ${RPT_FUZZ_NICE:-19}"

# Configured once with the "asan" preset; a build folder configured otherwise (scripts/ci_sanitizers.sh
# builds at -O0) keeps its settings.
if [ ! -f "$BUILD_DIR/CMakeCache.txt" ]; then cmake --preset asan -B "$BUILD_DIR" >/dev/null; fi
mapfile -t ALL < <(sed -n '/^set(RPT_FUZZ_TARGETS/,/)/p' fuzz/CMakeLists.txt | tr ' ()' '\n\n\n' | grep -v -e '^$' -e '^set$' -e '^RPT_FUZZ_TARGETS$')
FORMATS=("$@")
if [ ${#FORMATS[@]} -eq 0 ]; then FORMATS=("${ALL[@]}"); fi
$NICE cmake --build "$BUILD_DIR" -j"${RPT_FUZZ_JOBS:-$(nproc)}" --target rpt_fuzz rpt_fuzz_seeds >/dev/null

rm -rf "$BUILD_DIR/corpus-seeds" "$BUILD_DIR/corpus/"*/seeds
"$BUILD_DIR/fuzz/rpt_fuzz_seeds" "$BUILD_DIR/corpus-seeds"
mkdir -p "$BUILD_DIR/logs"
printf '%-22s %10s %8s %8s %8s  %s\n' format runs seconds cpu_s cov result
# Fuzzes one format; prints its line and leaves its exit status in <build>/logs/<format>.status.
fuzz_one() {
  local f="$1" corpus="$BUILD_DIR/corpus/$1" log="$BUILD_DIR/logs/$1.log" start status=0 seconds cpu runs cov result
  mkdir -p "$corpus/found" "$corpus/seeds" "$BUILD_DIR/artifacts/$f"
  cp "$BUILD_DIR/corpus-seeds/$f/"* "$corpus/seeds/"
  start=$(date +%s)
  RPT_FUZZ_TARGET="$f" ASAN_OPTIONS="detect_leaks=1:allocator_may_return_null=1" UBSAN_OPTIONS="print_stacktrace=1" \
    LSAN_OPTIONS="suppressions=$PWD/fuzz/lsan_suppressions.txt:print_suppressions=0" \
    $NICE /usr/bin/time -f "%U %S" -o "$log.cpu" "$BUILD_DIR/fuzz/rpt_fuzz" -max_total_time="$SECONDS_PER_FORMAT" \
    -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$BUILD_DIR/artifacts/$f/" "$corpus/found" "$corpus/seeds" >"$log" 2>&1 || status=$?
  seconds=$(( $(date +%s) - start ))
  cpu=$(awk 'NF == 2 { printf "%d", $1 + $2 }' "$log.cpu" 2>/dev/null || true)
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  result=ok
  if [ "$status" != 0 ]; then
    result="FAILED (exit $status): $(grep -m1 -E 'ERROR|SUMMARY|deadly|timeout|out-of-memory' "$log" || true) -- see $log"
  fi
  echo "$status" >"$BUILD_DIR/logs/$f.status"
  printf '%-22s %10s %8s %8s %8s  %s\n' "$f" "${runs:-?}" "$seconds" "${cpu:-?}" "${cov:-?}" "$result"
}
PARALLEL="${RPT_FUZZ_PARALLEL:-1}"
rm -f "$BUILD_DIR/logs/"*.status
for f in "${FORMATS[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$PARALLEL" ]; do wait -n || true; done
  fuzz_one "$f" &
done
wait
failed=0
for f in "${FORMATS[@]}"; do
  if [ "$(cat "$BUILD_DIR/logs/$f.status" 2>/dev/null || echo missing)" != 0 ]; then failed=1; fi
done
exit $failed
