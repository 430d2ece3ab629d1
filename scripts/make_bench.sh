#!/usr/bin/env bash
# Regenerates results/bench.md: rpt bench on the standard scenes, the real Shelf frames of the
# 4D-Association bundle (from $RPT_SHARED_DATA, default ../shared/data) and the scaling series, with
# the machine, compiler flags and commit. Usage: bash scripts/make_bench.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD="${1:-build}"
RPT="$BUILD/rpt"
# Pinned to one core where possible: on a shared 2-core machine migrations add 10-30 % noise.
PIN=""
command -v taskset > /dev/null && PIN="taskset -c $(( $(nproc) - 1 ))"
cmake --build "$BUILD" --target rpt > /dev/null  # refresh the embedded git revision
FLAGS=$(grep -E '^CMAKE_CXX_FLAGS_RELEASE:' "$BUILD/CMakeCache.txt" | cut -d= -f2-)
NATIVE=$(grep -E '^RPT_MARCH_NATIVE:' "$BUILD/CMakeCache.txt" | cut -d= -f2-)
# The real data (never copied into the project), as the tests find it.
SHARED_DATA="${RPT_SHARED_DATA:-../shared/data}"
{
  echo "# Benchmarks"
  echo
  echo "Regenerate with \`bash scripts/make_bench.sh\` (after building). Single thread, 2D to 3D including"
  echo "undistortion; medians over 5 passes after a warm-up pass; generated scenes with the \`clean\`"
  echo "simulated detector profile, the workload of every earlier run (bench/bench_scenes.cc; \`rpt bench --detector\` changes it). The baseline is a straightforward implementation of"
  echo "the same algorithm run in the same process (bench/baseline_triangulator.cc: SVD on every pair and"
  echo "joint, no pre-filter, fresh allocations per frame) on each scene's first 30 frames; the speed-up divides"
  echo "its median by rpt's median on those same frames (\`rpt on them\`)."
  echo
  echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ //'), $(nproc) cores${PIN:+; timed runs pinned to one core ($PIN)}"
  echo "- compiler: $(c++ --version | head -1); flags: \`${FLAGS}\`, -march=native: ${NATIVE}"
  echo "- commit: $(git rev-parse --short=12 HEAD)$(git diff --quiet HEAD -- core cli bench datasets metrics || echo ' (with uncommitted changes)')"
  echo
  echo "## Standard scenes"
  echo
  echo '```'
  $PIN "$RPT" bench --repeat 5 2>/dev/null
  echo '```'
  echo
  echo "## Real frames"
  echo
  echo "The 301 frames of Shelf (5 cameras) bundled by 4D-Association with their real OpenPose output, read by"
  echo "the shelf-4da reader in every pass as \`rpt eval\` reads them: \`paf_grouping (reader)\` is the reader's grouping of the"
  echo "raw OpenPose candidates into persons (part-affinity fields), done before the pipeline and not in its"
  echo "total; \`frame + grouping\` is the frame with it, the time the target is about. The baseline runs on the first 30 frames"
  echo "(\`baseline frames\`), as in every column; \`rpt on them\` and the speed-up are rpt's on those frames."
  echo
  echo '```'
  if [ -d "$SHARED_DATA/shelf/4d_association" ]; then
    $PIN "$RPT" bench --dataset shelf-4da --root "$SHARED_DATA/shelf/4d_association" --repeat 5 2>/dev/null
  else
    echo "(not measured: no 4D-Association Shelf bundle at $SHARED_DATA/shelf/4d_association; RPT_SHARED_DATA names the folder)"
  fi
  echo '```'
  echo
  echo "## Loading detections"
  echo
  echo '```'
  $PIN "$RPT" bench --io --io-frames 10000
  echo '```'
  echo
  echo "## Live input (\`rpt triangulate --follow\`)"
  echo
  echo "Lines fed one at a time through a pipe by a second thread, each after the output line of the one"
  echo "before; not pinned (the feeding thread and the live run are two threads). Target: --follow adds"
  echo "at most 100 us per frame over the triangulation time on shelf-like."
  echo
  echo '```'
  "$RPT" bench --follow --repeat 5 2>/dev/null
  echo '```'
  echo
  echo "## SIMD kernels against the scalar steps (same run)"
  echo
  echo "The scalar steps stay selectable (\`RPT_SIMD=off\`) for this comparison; both give the same results."
  echo "Kernels run in undistort (pinhole cameras, as here), prefilter, triangulate_core, score, triangulate_full, merge and refine; the other"
  echo "steps' ratios show what the machine's drift between the two processes alone does."
  echo
  echo '```'
  python3 scripts/bench_simd_before_after.py "$RPT" --pin "$PIN"  # 5 rounds of --repeat 10
  echo '```'
  echo
  # The newest commit that changed the pipeline (core/), and the one that changed it before (or
  # BENCH_AGAINST).
  PIPELINE=$(git log -1 --format=%h HEAD -- core)
  BASE=${BENCH_AGAINST:-$(git log -1 --format=%h "$PIPELINE^" -- core 2> /dev/null || true)}
  echo "## Against the previous pipeline commit (same run)"
  echo
  if [ -n "${BENCH_AGAINST:-}" ]; then
    echo "Against $BASE (\`BENCH_AGAINST\`), built and run alternately with this"
  else
    echo "The pipeline (core/) last changed in $PIPELINE; before that in $BASE, built and run alternately with this"
  fi
  echo "build (\`bash scripts/bench_against.sh $BASE 5 $BUILD\`; \`BENCH_AGAINST=REV\` picks another revision)."
  echo
  echo '```'
  if [ -n "$BASE" ]; then
    bash scripts/bench_against.sh "$BASE" 5 "$BUILD" 2>/dev/null || echo "($BASE could not be built or run here)"
  else
    echo "(no earlier pipeline commit)"
  fi
  echo '```'
  echo
  echo "## Scaling (cameras with 4 people; people with 5 cameras)"
  echo
  echo '```'
  $PIN "$RPT" bench --scaling --repeat 3 --baseline-frames 5 2>/dev/null
  echo '```'
} > results/bench.md
echo "wrote results/bench.md"
python3 scripts/readme_speed_table.py  # README's speed table from it (checked by ctest)
