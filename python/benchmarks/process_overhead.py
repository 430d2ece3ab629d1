"""What calling the triangulator from Python costs (docs/python.md, "Speed"): on the shelf-like scene
(5 cameras, 4 people, 17 joints, the clean detector profile: `rpt bench --scene shelf-like`),
  1. process_sequence: wall time per frame of the whole call against the C++ time per frame inside it
     (the triangulator's own steady-clock time, FrameStats::total_us), with and without its checks;
  2. process: wall time of one call (numpy views in, arrays out) against the C++ time inside it; the
     difference is the per-call overhead of the binding (conversion, checks, GIL, result arrays).
Not a test: timings depend on the machine. Pin it for stable numbers: taskset -c 1 python3 process_overhead.py
[--cli build/rpt] (with --cli, `rpt bench --scene shelf-like` is run too, for the CLI's own median)."""
import argparse
import json
import subprocess
import time

import numpy as np
import rpt

parser = argparse.ArgumentParser()
parser.add_argument("--repeat", type=int, default=5)
parser.add_argument("--cli", help="the rpt executable, to print `rpt bench --scene shelf-like`'s median too")
args = parser.parse_args()

scene = rpt.synthetic.scene(cameras=5, people=4, frames=300, noise="clean", seed=1)
views = [(frame.views, frame.timestamp) for frame in scene]  # numpy arrays made once, outside the timing
triangulator = rpt.Triangulator.for_sequence(scene)
triangulator.process_sequence(scene)  # warm-up: buffers grown

ratios, sequence_wall, sequence_cpp = [], [], []
for _ in range(args.repeat):
    triangulator.reset()
    predictions = triangulator.process_sequence(scene)
    wall_us = predictions.wall_seconds * 1e6 / len(predictions)
    cpp_us = float(np.mean(predictions.frame_time_us))
    sequence_wall.append(wall_us)
    sequence_cpp.append(cpp_us)
    ratios.append(wall_us / cpp_us)
print(f"process_sequence: {np.median(sequence_wall):.1f} us/frame wall, {np.median(sequence_cpp):.1f} us/frame in the "
      f"triangulator (means over {len(scene)} frames, median of {args.repeat} runs): "
      f"+{(np.median(ratios) - 1) * 100:.1f} %; median frame {np.median(predictions.frame_time_us):.1f} us")

unchecked_wall, unchecked_cpp = [], []
for _ in range(args.repeat):
    triangulator.reset()
    unchecked = triangulator.process_sequence(scene, checks=False)
    unchecked_wall.append(unchecked.wall_seconds * 1e6 / len(unchecked))
    unchecked_cpp.append(float(np.mean(unchecked.frame_time_us)))
print(f"process_sequence(checks=False): {np.median(unchecked_wall):.1f} us/frame wall, "
      f"{np.median(unchecked_cpp):.1f} us/frame in the triangulator "
      f"(+{(np.median(unchecked_wall) / np.median(unchecked_cpp) - 1) * 100:.1f} %)")

call_us, inside_us = [], []
for _ in range(args.repeat):
    triangulator.reset()
    for frame_views, timestamp in views:
        start = time.perf_counter()
        triangulator.process(frame_views, timestamp)
        call_us.append((time.perf_counter() - start) * 1e6)
        inside_us.append(triangulator.stats["total_us"])
overhead = np.array(call_us) - np.array(inside_us)
print(f"process: {np.median(call_us):.1f} us per call, {np.median(inside_us):.1f} us in the triangulator: "
      f"overhead {np.median(overhead):.1f} us per call (median; 90th percentile {np.percentile(overhead, 90):.1f} us)")

empty = [np.zeros((0, 17, 3))] * 5
triangulator.reset()
empty_us = []
for _ in range(2000):
    start = time.perf_counter()
    triangulator.process(empty)
    empty_us.append((time.perf_counter() - start) * 1e6)
print(f"process on a frame without detections: {np.median(empty_us):.1f} us per call "
      f"({triangulator.stats['total_us']:.1f} us in the triangulator)")

if args.cli:
    bench = json.loads(subprocess.run([args.cli, "bench", "--scene", "shelf-like", "--no-baseline", "--json"],
                                      capture_output=True, text=True, check=True).stdout)
    scene_result = bench["scenes"][0]
    print(f"rpt bench --scene shelf-like (C++ alone): median {scene_result['frame_time_us_median']:.1f} us/frame, "
          f"mean {scene_result['frame_time_us_mean']:.1f} us/frame")
