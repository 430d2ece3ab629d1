"""Both examples of docs/python.md run, and the first stays under 30 lines."""
import os
import subprocess
import sys

from conftest import SOURCE_DIR

EXAMPLES = SOURCE_DIR / "python" / "examples"


def run_example(name, cwd):
    env = dict(os.environ, MPLBACKEND="Agg")
    return subprocess.run([sys.executable, str(EXAMPLES / name)], cwd=cwd, env=env, capture_output=True, text=True,
                          check=True, timeout=300)


def test_triangulate_dataset_example(tmp_path):
    lines = (EXAMPLES / "triangulate_dataset.py").read_text().splitlines()
    assert len(lines) < 30
    done = run_example("triangulate_dataset.py", tmp_path)
    assert done.stdout.startswith("synthetic: PCP ")
    assert (tmp_path / "synthetic.png").stat().st_size > 10000


def test_live_detections_example(tmp_path):
    done = run_example("live_detections.py", tmp_path)
    lines = done.stdout.splitlines()
    assert lines[0].startswith("t= 0.00 s: tracks [")
    assert lines[-1].startswith("100 frames in ")
