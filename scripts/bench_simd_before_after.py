#!/usr/bin/env python3
"""Per-step times of the SIMD kernels against the scalar steps they replaced, in one run.

Runs `rpt bench --json` on the standard scenes alternately with RPT_SIMD=off (the steps' scalar
code, kept selectable for this comparison) and with the default kernels, ROUNDS times each, and
prints per scene and step the median over the rounds of each setting's per-step median and the
speed-up. Results are bit-identical between the two settings (tests/pipeline/simd_kernels_test.cc).

Usage: python3 scripts/bench_simd_before_after.py RPT [--rounds N] [--repeat N] [--pin CMD]
(scripts/make_bench.sh writes its output into results/bench.md).
"""
import argparse
import json
import os
import shlex
import statistics
import subprocess
import sys


def bench(rpt, pin, repeat, simd_off):
    env = dict(os.environ)
    env.pop("RPT_SIMD", None)
    if simd_off:
        env["RPT_SIMD"] = "off"
    command = shlex.split(pin) + [rpt, "bench", "--no-baseline", "--repeat", str(repeat), "--json"]
    done = subprocess.run(command, env=env, capture_output=True, text=True)
    if done.returncode != 0:
        sys.exit(f"bench_simd_before_after: {' '.join(command)} exited with {done.returncode}: {done.stderr.strip()}")
    return json.loads(done.stdout)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("rpt")
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--repeat", type=int, default=10)
    parser.add_argument("--pin", default="", help="command prefix, e.g. 'taskset -c 1'")
    args = parser.parse_args()
    runs = {False: [], True: []}
    for _ in range(args.rounds):
        for off in (True, False):
            runs[off].append(bench(args.rpt, args.pin, args.repeat, off))
    simd_path = runs[False][0]["simd"]
    scenes = [s["name"] for s in runs[False][0]["scenes"]]
    steps = list(runs[False][0]["scenes"][0]["step_time_us_median"].keys())

    def median(off, scene_index, key, step=None):
        values = []
        for run in runs[off]:
            scene = run["scenes"][scene_index]
            values.append(scene[key][step] if step else scene[key])
        return statistics.median(values)

    print(f"scalar steps (RPT_SIMD=off) against the {simd_path} kernels; medians of {args.rounds} alternating "
          f"rounds of `rpt bench --repeat {args.repeat}`, us per frame")
    print()
    header = f"{'step (us)':<18}" + "".join(f"{name:>30}" for name in scenes)
    print(header)
    print(f"{'':<18}" + "".join(f"{'scalar -> SIMD (speed-up)':>30}" for _ in scenes))
    rows = [(step, "step_time_us_median", step) for step in steps] + [("total (median)", "frame_time_us_median", None)]
    for label, key, step in rows:
        cells = []
        for i in range(len(scenes)):
            before, after = median(True, i, key, step), median(False, i, key, step)
            cell = f"{before:.2f} -> {after:.2f} ({before / after:.2f}x)" if after >= 0.05 else "-"  # a step that did not run
            cells.append(f"{cell:>30}")
        print(f"{label:<18}" + "".join(cells))
    return 0


if __name__ == "__main__":
    sys.exit(main())
