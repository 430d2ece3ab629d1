#!/usr/bin/env python3
"""README's speed table from results/bench.md (its one source).

The README's "Speed" section names the machine and lists, per standard scene and for the real
Shelf frames, rpt's median frame time, its MPJPE, the naive baseline of the same run and the
speed-up; all of them come from the "Standard scenes" and "Real frames" blocks and the machine
line of results/bench.md; the real frames' grouping sentence from the latter block's rows
`paf_grouping (reader)` and `frame + grouping`; the time to load the HDF5 cache from its "Loading
detections" line. The paper column is the paper's and stays as the README has it.

Usage: python3 scripts/readme_speed_table.py [--check] [--root DIR]
  without --check: rewrites those cells and the machine sentence of README.md;
  --check: exit 1, naming each difference, when README.md does not say what results/bench.md says
  (run by ctest as ReadmeSpeedTable.MatchesResultsBench; scripts/make_bench.sh rewrites it).
"""
import argparse
import pathlib
import re
import sys

# README row label -> (the block of results/bench.md, the scene's column in `rpt bench`).
SCENES = {
    "shelf-like: 5 cameras, 4 people, 17 joints": ("Standard scenes", "shelf-like"),
    "whole body: 5 cameras, 2 people, 133 joints": ("Standard scenes", "whole-body"),
    "panoptic-like: 31 cameras, 8 people": ("Standard scenes", "panoptic-like"),
    "Shelf, real OpenPose (4D-Association bundle), 5 cameras": ("Real frames", "shelf-4da"),
}
MACHINE_SENTENCE = re.compile(
    r"(From `results/bench.md` \(regenerate: `bash scripts/make_bench.sh`\):\s+one\s+thread\s+of\s+)(an?\s+.+?)(\s+core)", re.S)


def fail(message):
    print(f"readme_speed_table: {message}", file=sys.stderr)
    sys.exit(2)


def read_block(path, text, title):
    """The rows (row name -> {scene: value}) of the `rpt bench` table under '## TITLE'."""
    section = re.search(r"^## " + re.escape(title) + r"[ \t]*\n(.*?)(?=^## |\Z)", text, re.S | re.M)
    block = section and re.search(r"^```\n(.*?)^```", section.group(1), re.S | re.M)
    if not block:
        fail(f"{path}: no code block under '## {title}'")
    rows, scenes = {}, None
    for line in block.group(1).splitlines():
        if line.startswith("step (us)"):
            scenes = line.split()[2:]
            continue
        if scenes is None or not line.strip():
            continue
        cells = line.split()
        values = cells[-len(scenes):]
        rows[" ".join(cells[:-len(scenes)])] = dict(zip(scenes, values))
    for needed in ("total (median)", "MPJPE (mm)", "baseline (us)", "speed-up"):
        if needed not in rows:
            fail(f"{path}: the block '{title}' has no '{needed}' row")
    return rows


def read_bench(path):
    """The rows of each block the README reads ({title: rows}) and the machine of results/bench.md."""
    text = path.read_text(encoding="utf-8")
    machine = re.search(r"^- machine: (.+?), \d+ cores", text, re.M)
    if not machine:
        fail(f"{path}: no '- machine: NAME, N cores' line")
    blocks = {title: read_block(path, text, title) for title in sorted({b for b, _ in SCENES.values()})}
    return blocks, machine.group(1)


def duration(us):
    """Microseconds as the README writes them: 62 us, 1.26 ms, 5.2 ms, 0.86 s."""
    if us < 1000:
        return f"{us:.0f} us"
    if us < 2000:
        return f"{us / 1000:.2f} ms"
    if us < 100000:
        return f"{us / 1000:.1f} ms"
    if us < 1000000:
        return f"{us / 1e6:.2f} s"
    return f"{us / 1e6:.1f} s"


def expected_cells(rows, scene):
    def value(row):
        cell = rows[row].get(scene)
        if cell is None:
            fail(f"results/bench.md: no '{scene}' column in row '{row}'")
        try:
            return float(cell.rstrip("x"))
        except ValueError:
            fail(f"results/bench.md: row '{row}', column '{scene}' is '{cell}', not a number")
    return [duration(value("total (median)")), f"{value('MPJPE (mm)'):.1f} mm", duration(value("baseline (us)")),
            f"{value('speed-up'):.0f}x"]


def machine_words(machine):
    article = "an" if machine[:1].upper() in "AEIOU" else "a"
    return f"{article} {machine}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="report differences instead of rewriting README.md")
    parser.add_argument("--root", default=pathlib.Path(__file__).resolve().parent.parent, type=pathlib.Path)
    args = parser.parse_args()
    readme_path, bench_path = args.root / "README.md", args.root / "results" / "bench.md"
    blocks, machine = read_bench(bench_path)
    readme = readme_path.read_text(encoding="utf-8")
    differences, lines = [], readme.split("\n")
    found = set()
    for i, line in enumerate(lines):
        cells = [c.strip() for c in line.split("|")]
        if len(cells) < 8 or cells[1] not in SCENES:
            continue
        found.add(cells[1])
        block, scene = SCENES[cells[1]]
        want = expected_cells(blocks[block], scene)
        if cells[2:6] != want:
            differences.append(f"README.md line {i + 1} ({cells[1]}): says {cells[2:6]}, results/bench.md gives {want}")
            cells[2:6] = want
            lines[i] = "| " + " | ".join(cells[1:-1]) + " |"
    for label in SCENES:
        if label not in found:
            fail(f"README.md: no speed table row '{label}'")
    text = "\n".join(lines)
    sentence = MACHINE_SENTENCE.search(text)
    if not sentence:
        fail("README.md: no sentence 'From `results/bench.md` (regenerate: ...): one thread of A MACHINE core'")
    if " ".join(sentence.group(2).split()) != machine_words(machine):
        differences.append(f"README.md names the machine '{sentence.group(2)}', results/bench.md '{machine}'")
        text = text[:sentence.start(2)] + machine_words(machine) + text[sentence.end(2):]
    # The loading sentence: `rpt bench --io`'s read time and its metadata check.
    io = re.search(r"read ([0-9.]+) s \(median of \d+\).*?metadata walk in a child process ([0-9.]+) ms",
                   bench_path.read_text(encoding="utf-8"))
    if not io:
        fail(f"{bench_path}: no 'read X s (median of N) ... metadata walk in a child process Y ms' line")
    loading = re.search(r"(HDF5\s+cache\s+takes\s+)([0-9.]+ s)(,\s+of\s+which\s+)([0-9.]+ ms)", text)
    if not loading:
        fail("README.md: no sentence '... HDF5 cache takes X s, of which Y ms ...'")
    want_read, want_walk = f"{float(io.group(1)):.2f} s", f"{float(io.group(2)):.0f} ms"
    if (loading.group(2), loading.group(4)) != (want_read, want_walk):
        differences.append(f"README.md says the cache loads in {loading.group(2)} ({loading.group(4)} of metadata check), "
                           f"results/bench.md {want_read} ({want_walk})")
        text = text[:loading.start(2)] + want_read + loading.group(3) + want_walk + text[loading.end(4):]
    # The sentence on the real Shelf frames' grouping: its `paf_grouping (reader)` and `frame + grouping` rows.
    real = blocks["Real frames"]
    grouping = re.search(r"(grouping\s+of\s+the\s+raw\s+OpenPose\s+candidates\s+into\s+persons\s+adds\s+)([0-9]+ us)"
                         r"(\s+a\s+frame\s+\(`paf_grouping \(reader\)`;\s+)([0-9]+ us)", text)
    if not grouping:
        fail("README.md: no sentence '... grouping of the raw OpenPose candidates into persons adds X us a frame "
             "(`paf_grouping (reader)`; Y us ...'")
    for row in ("paf_grouping (reader)", "frame + grouping"):
        if row not in real or "shelf-4da" not in real[row]:
            fail(f"{bench_path}: the block 'Real frames' has no '{row}' row for shelf-4da")
    want = (f"{float(real['paf_grouping (reader)']['shelf-4da']):.0f} us", f"{float(real['frame + grouping']['shelf-4da']):.0f} us")
    if (grouping.group(2), grouping.group(4)) != want:
        differences.append(f"README.md says the grouping adds {grouping.group(2)} ({grouping.group(4)} with it), "
                           f"results/bench.md {want[0]} ({want[1]})")
        text = text[:grouping.start(2)] + want[0] + grouping.group(3) + want[1] + text[grouping.end(4):]
    if args.check:
        for d in differences:
            print(d, file=sys.stderr)
        if differences:
            print("run `python3 scripts/readme_speed_table.py` to take README's speed table from results/bench.md",
                  file=sys.stderr)
        return 1 if differences else 0
    if text != readme:
        readme_path.write_text(text, encoding="utf-8")
        print(f"README.md: speed table from results/bench.md ({len(differences)} change(s))")
    return 0


if __name__ == "__main__":
    sys.exit(main())
