#!/usr/bin/env python3
"""Per-step times of the SIMD kernels against the scalar steps they replaced, in one run.

Runs `rpt bench --json` on the standard scenes alternately with RPT_SIMD=off (the steps' scalar
code, kept selectable for this comparison) and with the default kernels, ROUNDS times each, and
prints per scene and step the median over the rounds of each setting's per-step median and the
speed-up. Results are bit-identical between the two settings (tests/pipeline/simd_kernels_test.cc).
`--before AVX2` compares the kernels on AVX2 (4 double lanes) with the default instead (on an
AVX-512 CPU: 8 lanes), which measures what twice the lanes buy. `--before-rpt OTHER` runs another
build's rpt (default kernels) as "before": another revision against this one
(scripts/bench_against.sh builds one and calls this).

Usage: python3 scripts/bench_simd_before_after.py RPT [--rounds N] [--repeat N] [--pin CMD]
       [--before PATH | --before-rpt OTHER_RPT --before-name NAME]
(scripts/make_bench.sh writes its output into results/bench.md).
"""
import argparse
import json
import os
import shlex
import statistics
import subprocess
import sys


def bench(rpt, pin, repeat, simd, scenes=()):
    """One `rpt bench --json` run with RPT_SIMD=simd (None: the default kernels)."""
    env = dict(os.environ)
    env.pop("RPT_SIMD", None)
    if simd is not None:
        env["RPT_SIMD"] = simd
    command = shlex.split(pin) + [rpt, "bench", "--no-baseline", "--repeat", str(repeat), "--json"]
    for scene in scenes:
        command += ["--scene", scene]
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
    parser.add_argument("--before", default="off",
                        help="RPT_SIMD of the 'before' runs: off (the scalar steps, default) or an instruction set")
    parser.add_argument("--before-rpt", default=None, help="another build's rpt for the 'before' runs (default kernels)")
    parser.add_argument("--before-name", default="before", help="with --before-rpt: its name in the table")
    parser.add_argument("--scene", action="append", default=[], help="only this scene (repeatable; default: the standard ones)")
    args = parser.parse_args()
    runs = {True: [], False: []}  # True: before
    for _ in range(args.rounds):
        for before in (True, False):
            if before and args.before_rpt:
                runs[True].append(bench(args.before_rpt, args.pin, args.repeat, None, args.scene))
            else:
                runs[before].append(bench(args.rpt, args.pin, args.repeat, args.before if before else None, args.scene))
    simd_path = runs[False][0]["simd"]
    scenes = [s["name"] for s in runs[False][0]["scenes"]]
    steps = list(runs[False][0]["scenes"][0]["step_time_us_median"].keys())

    def median(off, scene_index, key, step=None):
        values = []
        for run in runs[off]:
            scene = run["scenes"][scene_index]
            value = scene[key].get(step) if step else scene.get(key)
            if value is None:  # a step the other revision does not have
                return None
            values.append(value)
        return statistics.median(values)

    if args.before_rpt:
        before_name, after_name = args.before_name, "this build"
        revision = lambda run: run.get("run", {}).get("git_revision", "?")
        print(f"{args.before_name} ({revision(runs[True][0])}) against this build ({revision(runs[False][0])}), "
              f"both with their default kernels; medians of {args.rounds} alternating rounds of "
              f"`rpt bench --repeat {args.repeat}`, us per frame")
    else:
        before_name, after_name = ("scalar" if args.before == "off" else runs[True][0]["simd"]), simd_path
        print(f"{'scalar steps (RPT_SIMD=off)' if args.before == 'off' else f'the {before_name} kernels (RPT_SIMD={args.before})'} "
              f"against the {simd_path} kernels; medians of {args.rounds} alternating "
              f"rounds of `rpt bench --repeat {args.repeat}`, us per frame")
    print()
    column = f"{before_name} -> {after_name} (speed-up)"
    width = max(30, len(column) + 2)  # columns stay apart whatever the names
    header = f"{'step (us)':<18}" + "".join(f"{name:>{width}}" for name in scenes)
    print(header)
    print(f"{'':<18}" + "".join(f"{column:>{width}}" for _ in scenes))
    rows = [(step, "step_time_us_median", step) for step in steps] + [("total (median)", "frame_time_us_median", None)]
    for label, key, step in rows:
        cells = []
        for i in range(len(scenes)):
            before, after = median(True, i, key, step), median(False, i, key, step)
            # A step that did not run times ~0.03 us on both sides; one that got that cheap ran before.
            ran = before is not None and after is not None and max(before, after) >= 0.05
            cell = f"{before:.2f} -> {after:.2f} ({before / max(after, 0.01):.2f}x)" if ran else "-"
            cells.append(f"{cell:>{width}}")
        print(f"{label:<18}" + "".join(cells))
    # Per-round ratios of the frame medians (the host's drift hits both sides of a round alike).
    cells = []
    for i in range(len(scenes)):
        ratios = [b["scenes"][i]["frame_time_us_median"] / a["scenes"][i]["frame_time_us_median"]
                  for b, a in zip(runs[True], runs[False])]
        cells.append(f"{f'{statistics.median(ratios):.2f}x ({min(ratios):.2f}-{max(ratios):.2f})':>{width}}")
    print(f"{'speed-up per round':<18}" + "".join(cells))
    cells = []
    for i in range(len(scenes)):
        mpjpe = f"{runs[True][0]['scenes'][i]['mpjpe_mm']:.4f} -> {runs[False][0]['scenes'][i]['mpjpe_mm']:.4f}"
        cells.append(f"{mpjpe:>{width}}")
    print(f"{'MPJPE (mm)':<18}" + "".join(cells))
    return 0


if __name__ == "__main__":
    sys.exit(main())
