#!/usr/bin/env bash
# Speed of another revision against this build, in one run: builds REV's rpt in a temporary git
# worktree, then alternates `rpt bench` of both for ROUNDS rounds, pinned to one core, and prints
# per scene and step the medians, the speed-up, the per-round speed-ups of the frame median and
# both MPJPEs (scripts/bench_simd_before_after.py). On a shared, drifting machine only such
# same-run comparisons mean anything. BUILD_DIR (default build) must hold this revision's rpt.
# Usage: bash scripts/bench_against.sh REV [ROUNDS] [BUILD_DIR] [-- --scene NAME ...]
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -lt 1 ]; then
  echo "usage: bash scripts/bench_against.sh REV [ROUNDS] [BUILD_DIR] [-- --scene NAME ...]" >&2
  exit 2
fi
REV="$1"
shift
ROUNDS=5
BUILD=build
[ $# -gt 0 ] && [ "$1" != "--" ] && { ROUNDS="$1"; shift; }
[ $# -gt 0 ] && [ "$1" != "--" ] && { BUILD="$1"; shift; }
[ $# -gt 0 ] && [ "$1" = "--" ] && shift
if ! [[ "$ROUNDS" =~ ^[1-9][0-9]*$ ]]; then
  echo "bench_against: ROUNDS must be a positive integer, got '$ROUNDS'" >&2
  exit 2
fi
if ! COMMIT=$(git rev-parse --verify --quiet "$REV^{commit}"); then
  echo "bench_against: $REV is not a revision of this repository" >&2
  exit 2
fi
if [ ! -x "$BUILD/rpt" ]; then
  echo "bench_against: $BUILD/rpt not found: build this revision first (cmake --build $BUILD --target rpt)" >&2
  exit 2
fi
WORK=$(mktemp -d "${TMPDIR:-/tmp}/rpt-bench-against.XXXXXX")
cleanup() { git worktree remove --force "$WORK/src" > /dev/null 2>&1 || true; rm -rf "$WORK"; }
trap cleanup EXIT
git worktree add --detach --quiet "$WORK/src" "$COMMIT"
echo "building $REV ($(git rev-parse --short=12 "$COMMIT")) in $WORK ..." >&2
# The build uses ccache when installed (CMakeLists.txt); paths below $WORK count as relative, so a
# later run of this script finds the objects of an earlier one.
export CCACHE_BASEDIR="$WORK"
if ! { cmake -S "$WORK/src" -B "$WORK/build" -DCMAKE_BUILD_TYPE=Release -DRPT_BUILD_TESTS=OFF \
         && cmake --build "$WORK/build" --target rpt -j"$(nproc)"; } > "$WORK/build.log" 2>&1; then
  tail -20 "$WORK/build.log" >&2
  echo "bench_against: $REV does not build here (log above)" >&2
  exit 1
fi
PIN=""
command -v taskset > /dev/null && PIN="taskset -c $(( $(nproc) - 1 ))"
python3 scripts/bench_simd_before_after.py "$BUILD/rpt" --rounds "$ROUNDS" --pin "$PIN" \
  --before-rpt "$WORK/build/rpt" --before-name "$REV" "$@"
