"""Open a dataset, triangulate it, evaluate, plot (docs/python.md).
python3 triangulate_dataset.py [DATASET ROOT]   (default: a generated scene; real datasets with --simulate)"""
import sys

import matplotlib.pyplot as plt
import numpy as np
import rpt

name, root = sys.argv[1:3] if len(sys.argv) > 2 else ("synthetic", "")
dataset = rpt.datasets.open(name, root, simulate=name != "synthetic")
for sequence in dataset.load():
    predictions = rpt.Triangulator.for_sequence(sequence).process_sequence(sequence)
    summary = rpt.metrics.evaluate(sequence, predictions)
    print(f"{sequence.name}: PCP {summary['pcp']:.1f} %, MPJPE {summary['mpjpe_mm']:.1f} mm, "
          f"Recall@500 {summary['recall500']:.1f} %, {np.median(predictions.frame_time_us):.0f} us/frame")

    ax = plt.figure(figsize=(6, 6)).add_subplot(projection="3d")
    persons, track_ids = predictions[0]
    for joints, track_id in zip(persons, track_ids):
        seen = joints[:, 3] > 0
        ax.scatter(*joints[seen, :3].T, s=8, label=f"track {track_id}")
    for gt in sequence[0].gt:
        ax.scatter(*gt[gt[:, 3] > 0.1, :3].T, s=30, marker="x", color="gray")
    ax.scatter(*np.array([c.center for c in sequence.cameras]).T, marker="^", color="black", label="cameras")
    ax.set_title(f"{sequence.name}, frame {predictions.frame_ids[0]} (x: ground truth)")
    ax.legend()
    plt.savefig(f"{sequence.name.replace('/', '_')}.png", dpi=80)
