#!/usr/bin/env bash
# Regenerates every table in results/ (see docs/results.md). Needs a build (./build/rpt);
# the real-fixture tables need ../shared/data and are skipped without it.
# Usage: bash scripts/make_results.sh [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
RPT="${1:-build}/rpt"
cmake --build "${1:-build}" --target rpt > /dev/null  # refresh the embedded git revision
SHARED="../shared/data"
OUT=results
# Timing columns are single-threaded (--threads 1) so they are comparable across rows.

sweep() {  # name, then rpt sweep arguments
  local name="$1"; shift
  "$RPT" sweep --threads 1 --out "$OUT/$name" "$@" > /dev/null
  echo "wrote $OUT/$name/sweep.{md,csv,json}"
}

sweep synthetic-rigs     --dataset synthetic --param people=4 --param frames=200 --grid param.cameras=3,5,10,31
sweep synthetic-crowds   --dataset synthetic --param cameras=5 --param frames=200 --grid param.people=1,2,4,6,8,10
sweep synthetic-wholebody --dataset synthetic --param joints=wholebody --param people=2 --param frames=100 \
      --grid param.cameras=3,5,10
sweep ablations-synthetic --dataset synthetic --param cameras=6 --param people=5 --param frames=300 \
      --list results/ablations.json

fixture() {  # name, then rpt eval arguments
  local name="$1"; shift
  local tmp
  tmp=$(mktemp -d)
  "$RPT" eval --quiet --threads 1 --out "$tmp" "$@" > /dev/null
  mkdir -p "$OUT/fixtures/$name"
  cp "$tmp"/summary.md "$tmp"/summary.csv "$tmp"/summary.json "$tmp"/per_joint.csv "$tmp"/config.json "$tmp"/run.json \
     "$OUT/fixtures/$name/"
  rm -rf "$tmp"
  echo "wrote $OUT/fixtures/$name"
}

if [ -d "$SHARED" ]; then
  fixture shelf-simulated  --dataset shelf --root "$SHARED/shelf" --param frames=0-2 --simulate --set metrics.legacy_pcp=shelf
  fixture campus-simulated --dataset campus --root "$SHARED/campus" --param frames=0-2 --simulate --set metrics.legacy_pcp=campus
  fixture panoptic-simulated --dataset panoptic --root "$SHARED/panoptic" \
          --param sequences=160906_band1,160906_band2 --param every=1 --simulate
else
  echo "skipping the real-fixture tables: $SHARED is absent"
fi
