#!/usr/bin/env bash
# Regenerates every table in results/ (see docs/results.md). Needs a build (./build/rpt);
# the real-data tables (results/real) need ../shared/data and are skipped without it.
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
# The simulated detector's profiles (docs/detector_model.md) on one scene.
sweep synthetic-detectors --dataset synthetic --param cameras=5 --param people=4 --param frames=200 \
      --grid param.noise=perfect,clean,realistic,hard
# The pair score's two knobs around their defaults (docs/algorithm.md, step 8).
SCORE_GRID=(--grid score.scale_factor=4,5,6 --grid filter.min_match_score=0.6,0.7,0.8)
sweep scoring-synthetic --dataset synthetic --param cameras=5 --param people=4 --param frames=200 "${SCORE_GRID[@]}"

# results/real: every real case we can run, with the paper's row beside ours.
real() {  # name, then rpt eval arguments
  local name="$1"; shift
  local dir="$OUT/real/$name"
  mkdir -p "$dir"
  "$RPT" eval --quiet --threads 1 --out "$dir" "$@" > /dev/null
  rm -f "$dir/predictions.json"  # large; rerun the command to get it
  echo "wrote $dir"
}
ours() { sed -n 3p "$OUT/real/$1/summary.md" | sed "s#^| [^|]*|#| $2 |#"; }
# The paper's row for an rpt dataset name, from results/paper.json (the one copy of those numbers).
paper() {
  python3 -c 'import json, sys
d = json.load(open("results/paper.json"))
r = d["datasets"][sys.argv[1]]
# The paper FPS is of its whole system (2D network on a GPU included): marked, not comparable.
cell = lambda c: str(r[c]) + (" (whole system)" if c == "fps" else "")
print("| " + r["label"] + " | " + " | ".join(cell(c) for c in d["columns"]) + " | |")' "$1"
}

# A joint-definition adapter (docs/joint_adapter.md) fitted on one part of a dataset and evaluated
# on another, beside the same held-out part without it. The adapter file (its split, offsets and
# fitting frame ids) is kept as results/real/adapters/<name>.json; summary.json states the split too.
adapted() {  # name, fit selection (--param), held-out selection (--param), then the shared rpt arguments
  local name="$1" fit="$2" held_out="$3"; shift 3
  mkdir -p "$OUT/real/adapters"
  "$RPT" fit-adapter --threads 1 --param "$fit" "$@" --out "$OUT/real/adapters/$name.json" > /dev/null
  real "$name-without" --param "$held_out" "$@"
  real "$name" --param "$held_out" "$@" --adapter "$OUT/real/adapters/$name.json"
}

adapter_results() {
  adapted shelf4da-adapter-fit0-149    frames=0-149   frames=150-300 --dataset shelf-4da --root "$SHARED/shelf/4d_association"
  adapted shelf4da-adapter-fit150-300  frames=150-300 frames=0-149   --dataset shelf-4da --root "$SHARED/shelf/4d_association"
  adapted mvor-adapter-fit-days12      days=1,2       days=3,4       --dataset mvor --root "$SHARED/mvor"
  adapted mvor-adapter-fit-days34      days=3,4       days=1,2       --dataset mvor --root "$SHARED/mvor"
}

# The adapter table of results/real/README.md (after adapter_results).
adapter_table() {
  local head='| run | PCP (%) | PCK@100 (%) | PCK@500 (%) | MPJPE (mm) | Recall@100 (%) | Recall@500 (%) | Invalid (%) | F1 (%) | FPS (1/s) | Frames (count) |'
  echo "## Joint-definition adapter, held-out frames"
  echo
  echo "\`rpt fit-adapter\` on one part, \`rpt eval --adapter\` on the other (2-fold; docs/joint_adapter.md). Each"
  echo "pair of rows is the same held-out frames without and with the adapter; the adapter files, with"
  echo "their split, offsets and fitting frames, are in adapters/. FPS does not include the adapter."
  echo
  echo "$head"
  echo '|---|---|---|---|---|---|---|---|---|---|---|'
  ours shelf4da-adapter-fit0-149-without "Shelf-4DA frames 150-300, no adapter"
  ours shelf4da-adapter-fit0-149 "Shelf-4DA frames 150-300, adapter fitted on frames 0-149"
  ours shelf4da-adapter-fit150-300-without "Shelf-4DA frames 0-149, no adapter"
  ours shelf4da-adapter-fit150-300 "Shelf-4DA frames 0-149, adapter fitted on frames 150-300"
  ours mvor-adapter-fit-days12-without "MVOR days 3-4, no adapter"
  ours mvor-adapter-fit-days12 "MVOR days 3-4, adapter fitted on days 1-2"
  ours mvor-adapter-fit-days34-without "MVOR days 1-2, no adapter"
  ours mvor-adapter-fit-days34 "MVOR days 1-2, adapter fitted on days 3-4"
}

# Where the GT persons of the two real-detection runs are lost (their losses.csv side by side).
loss_table() {
  echo "## Where the ground-truth persons are lost"
  echo
  echo "\`rpt eval --loss-table\` (docs/diagnostics.md, section 4): each GT person in the category of the first"
  echo "step that loses it, with the default options; folders mvor-openpose-losses and shelf4da-openpose-losses."
  echo
  python3 - "$OUT/real/mvor-openpose-losses/losses.csv" "$OUT/real/shelf4da-openpose-losses/losses.csv" <<'PY'
import csv, sys
tables = [{(r["category"], r["detail"]): r for r in csv.DictReader(open(path))} for path in sys.argv[1:]]
print("| category | detail | MVOR, shipped OpenPose | Shelf, 4D-Association OpenPose |")
print("|---|---|---|---|")
for key, row in tables[0].items():
    cells = []
    for table in tables:
        r = table.get(key)
        cells.append(f"{r['persons']} ({r['percent_of_gt']} %)" if r else "")
    label = f"**{key[0]}**" if not key[1] else ""
    print(f"| {label or ''} | {key[1]} | " + " | ".join(cells) + " |")
PY
}

# How many of the wrong PCP parts the detections could have given (the loss-table runs' summary.json).
parts_table() {
  echo "## PCP parts within reach of the detections"
  echo
  echo "\`rpt eval --loss-table\` (docs/diagnostics.md, section 4): the parts PCP evaluates, those wrong in the"
  echo "output, and those no pair of two views of the person's own detections triangulates within PCP's"
  echo "test (beyond the best pair: a property of the detections and labels); folders mvor-openpose-losses"
  echo "and shelf4da-openpose-losses, \`loss_table.parts\` in summary.json."
  echo
  python3 - "$OUT/real/mvor-openpose-losses/summary.json" "$OUT/real/shelf4da-openpose-losses/summary.json" <<'PY'
import json, sys
tables = [json.load(open(path))["loss_table"] for path in sys.argv[1:]]
def table(first, rows):
    print(f"| {first} | MVOR, shipped OpenPose | Shelf, 4D-Association OpenPose |")
    print("|---|---|---|")
    for label, cell in rows:
        print(f"| {label} | " + " | ".join(cell(t) for t in tables) + " |")
table("parts", [
    ("evaluated", lambda t: str(t["parts"]["evaluated"])),
    ("wrong in the output", lambda t: f"{t['parts']['wrong']} (PCP {t['parts']['pcp']:.2f} %)"),
    ("beyond the best pair (PCP with only those wrong)",
     lambda t: f"{t['parts']['beyond_best_pair']} ({t['parts']['pcp_best_pair']:.2f} %)"),
    ("wrong and beyond the best pair", lambda t: str(t["parts"]["wrong_beyond_best_pair"]))])
print()
print("Mean joint error (mm) over the joints of matched persons that 2 or more of their views detected,")
print("`loss_table.joint_references`: the output, a confidence-weighted fit of all those views (told the")
print("association), and the best pair per joint (chosen with the GT: optimistic for one pair).")
print()
table("joints", [("compared", lambda t: str(t["joint_references"]["joints"]))] +
      [(label, lambda t, key=key: f"{t['joint_references'][key]:.1f}")
       for key, label in [("output_mm", "output"), ("all_views_mm", "all views fitted"),
                          ("best_pair_mm", "best pair per joint")]])
PY
}

# What MVOR's unmatched predictions show in its 2D labels (its loss-table run's summary.json).
unmatched_labels_table() {
  echo "## What the unmatched predictions show (MVOR's 2D labels)"
  echo
  echo "\`rpt eval --loss-table\` (docs/diagnostics.md, section 4): MVOR labels people in 2D and gives only"
  echo "some a 3D pose; each unmatched prediction by the labels its detections (or, when not merged from"
  echo "pairs, its projections) overlap; folder mvor-openpose-losses, \`loss_table.unmatched_with_2d_labels\`"
  echo "in summary.json."
  echo
  python3 - "$OUT/real/mvor-openpose-losses/summary.json" <<'PY'
import json, sys
u = json.load(open(sys.argv[1]))["loss_table"]["unmatched_with_2d_labels"]
rows = [("labelled_3d", "labelled_3d: a detection of a 3D-labelled person (misplaced, mixed, or a ghost using it)"),
        ("labelled_2d_only", "labelled_2d_only: each detection overlaps a person labelled in 2D only"),
        ("partly_2d_only", "partly_2d_only: some do, the others overlap nobody labelled"),
        ("unlabelled", "unlabelled: no detection overlaps a labelled person")]
print("| the unmatched prediction shows | MVOR, shipped OpenPose |")
print("|---|---|")
for key, label in rows:
    print(f"| {label} | {u[key]} |")
print(f"| **all unmatched** (of them judged by their projection) | {u['predictions']} ({u['by_projection']}) |")
PY
}

invalid_causes_table() {
  echo "## Why predictions are Invalid"
  echo
  echo "\`rpt eval\` (docs/diagnostics.md, section 5): every counted prediction that is not a match, by its"
  echo "nearest GT person and the 500 mm gate; folders mvor-openpose and shelf4da-openpose, \`invalid_causes\` in summary.json."
  echo
  python3 - "$OUT/real/mvor-openpose/summary.json" "$OUT/real/shelf4da-openpose/summary.json" <<'PY'
import json, sys
runs = [json.load(open(path)) for path in sys.argv[1:]]
rows = [("duplicate", "duplicate: nearest GT person within 500 mm, matched to another prediction"),
        ("near_matched_gt", "near_matched_gt: nearest GT person 500 to 1000 mm away, matched to another prediction"),
        ("near_missed_gt", "near_missed_gt: nearest GT person 500 to 1000 mm away, matched to none"),
        ("far_from_gt", "far_from_gt: every GT person 1000 mm or farther away"),
        ("no_gt", "no_gt: no GT person to compare with (a frame without GT)")]
print("| cause | MVOR, shipped OpenPose | Shelf, 4D-Association OpenPose |")
print("|---|---|---|")
for key, label in rows:
    print(f"| {label} | " + " | ".join(str(run["invalid_causes"][key]) for run in runs) + " |")
print("| **all unmatched** (Invalid: their share of the predictions) | " +
      " | ".join(f"{sum(run['invalid_causes'].values())} ({run['invalid']:.1f} % of {run['predictions']})" for run in runs) + " |")
PY
}

real_results() {
  sweep real/ablations-mvor --dataset mvor --root "$SHARED/mvor" --list results/ablations.json
  sweep real/ablations-shelf4da --dataset shelf-4da --root "$SHARED/shelf/4d_association" --list results/ablations.json
  sweep real/scoring-mvor --dataset mvor --root "$SHARED/mvor" "${SCORE_GRID[@]}"
  sweep real/scoring-shelf4da --dataset shelf-4da --root "$SHARED/shelf/4d_association" "${SCORE_GRID[@]}"
  real mvor-openpose         --dataset mvor --root "$SHARED/mvor"
  real mvor-openpose-paper   --dataset mvor --root "$SHARED/mvor" --param evaluated=paper
  real shelf4da-openpose     --dataset shelf-4da --root "$SHARED/shelf/4d_association"
  real shelf-simulated       --dataset shelf --root "$SHARED/shelf" --param frames=0-2 --simulate \
       --set metrics.legacy_pcp=shelf
  real campus-simulated      --dataset campus --root "$SHARED/campus" --param frames=0-2 --simulate \
       --set metrics.legacy_pcp=campus
  real panoptic-simulated    --dataset panoptic --root "$SHARED/panoptic" \
       --param sequences=160906_band1,160906_band2 --param every=1 --simulate
  # The same two real runs with the loss table (its recording counts in the frame time: FPS differs).
  real mvor-openpose-losses     --dataset mvor --root "$SHARED/mvor" --loss-table
  real shelf4da-openpose-losses --dataset shelf-4da --root "$SHARED/shelf/4d_association" --loss-table
  adapter_results
  local head='| run | PCP (%) | PCK@100 (%) | PCK@500 (%) | MPJPE (mm) | Recall@100 (%) | Recall@500 (%) | Invalid (%) | F1 (%) | FPS (1/s) | Frames (count) |'
  {
    echo "# Real cases: rpt beside the paper"
    echo
    echo "Generated by \`bash scripts/make_results.sh\` (section \`real_results\`); each folder holds the"
    echo "summary, per-joint errors, configuration and run information of one \`rpt eval\` command (its"
    echo "command line is in run.json). Paper rows: Bermuth et al., CVPR 2026, tables 'Transfer to ...'"
    echo "(their 2D network, their protocol). Their FPS is their whole system's on an Nvidia 3090, the 2D"
    echo "network and image demosaicing included; ours is the triangulation alone (10^6 / the median frame"
    echo "time, one thread of the machine in run.json): the two are not comparable, and results/bench.md"
    echo "compares the triangulation with other methods' on the same machine."
    echo "MVOR: by default rpt evaluates the 8 arm and torso joints MVOR labels in 3D (shoulders, elbows, wrists,"
    echo "hips); \`--param evaluated=paper\` adds MVOR's head as the nose, as the RPT authors' evaluation code does."
    echo "Shelf-4DA's FPS is the pipeline's: the reader's grouping of the raw OpenPose candidates into persons"
    echo "(row \`paf_grouping (reader)\` of its steps.csv) is not in it; \`frame + grouping\` there has both."
    echo
    echo "## Real 2D detections"
    echo
    echo "$head"
    echo '|---|---|---|---|---|---|---|---|---|---|---|'
    ours mvor-openpose "MVOR, shipped OpenPose, 8 arm/torso joints (rpt)"
    ours mvor-openpose-paper "MVOR, shipped OpenPose, + head as nose (rpt)"
    paper mvor
    ours shelf4da-openpose "Shelf, 4D-Association OpenPose and GT (rpt)"
    paper shelf-4da
    echo
    echo "## Real cameras and GT, simulated detector (realistic profile)"
    echo
    echo "$head"
    echo '|---|---|---|---|---|---|---|---|---|---|---|'
    ours shelf-simulated "Shelf fixture, 3 frames (rpt)"
    paper shelf
    ours campus-simulated "Campus fixture, 3 frames (rpt)"
    paper campus
    ours panoptic-simulated "Panoptic fixture, 40 frames (rpt)"
    paper panoptic
    echo
    adapter_table
    echo
    loss_table
    echo
    parts_table
    echo
    invalid_causes_table
    echo
    unmatched_labels_table
  } > "$OUT/real/README.md"
  echo "wrote $OUT/real/README.md"
}

if [ -d "$SHARED" ]; then
  real_results
else
  echo "skipping the real-fixture tables: $SHARED is absent"
fi
