"""Shared fixtures of the Python module's tests (run by ctest: tests/python/CMakeLists.txt sets the
environment: PYTHONPATH to the build tree's module, RPT_CLI to the build's rpt executable)."""
import json
import os
import subprocess
from pathlib import Path

import pytest

import rpt

CLI = os.environ.get("RPT_CLI", "")
SOURCE_DIR = Path(os.environ.get("RPT_SOURCE_DIR", Path(__file__).resolve().parents[2]))
SHARED_DATA = Path(os.environ.get("RPT_SHARED_DATA_DIR", SOURCE_DIR.parent / "shared" / "data"))

# The synthetic input both the CLI and the module read in the comparisons: short, but with tracks,
# misses and false positives (the clean profile).
SCENE = {"cameras": 5, "people": 4, "frames": 40, "noise": "clean", "seed": 3}


def run_cli(*args, check=True):
    """The build's rpt with `args`; returns the completed process (text output)."""
    if not CLI:
        pytest.fail("RPT_CLI is not set: run the tests through ctest")
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, check=check)


def scene_params(scene=SCENE):
    return [arg for key, value in scene.items() for arg in ("--param", f"{key}={value}")]


@pytest.fixture(scope="session")
def cli_eval(tmp_path_factory):
    """`rpt eval` on SCENE with every export: (summary of --json, output folder)."""
    out = tmp_path_factory.mktemp("cli_eval") / "run"
    done = run_cli("eval", "--dataset", "synthetic", *scene_params(), "--export", "json,csv,trc,npz", "--json",
                   "--quiet", "--out", out)
    return json.loads(done.stdout), out


@pytest.fixture(scope="session")
def scene():
    """SCENE loaded through rpt.datasets.open, as the CLI opens it."""
    sequences = rpt.datasets.open("synthetic", **SCENE).load()
    assert len(sequences) == 1
    return sequences[0]


@pytest.fixture(scope="session")
def predictions(scene):
    return rpt.Triangulator.for_sequence(scene).process_sequence(scene)
