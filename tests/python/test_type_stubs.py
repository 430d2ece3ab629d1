"""The type stubs (python/rpt/*.pyi, with py.typed) against the built module: mypy's stubtest finds
every name of the module in them and nothing the module lacks; mypy type-checks the examples with
them, reads the types they declare, and refuses wrong calls. Skips without mypy (Debian
python3-mypy, installed by `bash scripts/install_deps.sh --tests`)."""
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

pytest.importorskip("mypy", reason="mypy not installed (Debian python3-mypy; scripts/install_deps.sh --tests)")

import rpt  # noqa: E402

HERE = Path(__file__).resolve().parent
SOURCE_DIR = Path(os.environ.get("RPT_SOURCE_DIR", HERE.parents[1]))
PACKAGE = Path(rpt.__file__).resolve().parent  # the build tree's rpt/ (PYTHONPATH), with the stubs


def mypy(tmp_path, *files):
    """mypy on `files` with the module's stubs on its path; returns (exit code, output)."""
    config = tmp_path / "mypy.ini"
    config.write_text("[mypy]\ncheck_untyped_defs = True\n[mypy-matplotlib.*]\nignore_missing_imports = True\n")
    env = dict(os.environ, MYPYPATH=str(PACKAGE.parent))
    done = subprocess.run([sys.executable, "-m", "mypy", "--config-file", str(config), "--no-incremental",
                           "--cache-dir", os.devnull, "--no-error-summary", *map(str, files)],
                          capture_output=True, text=True, env=env, cwd=tmp_path)
    return done.returncode, done.stdout + done.stderr


def test_the_stubs_are_installed_beside_the_module():
    for name in ("__init__.pyi", "cameras.pyi", "datasets.pyi", "export.pyi", "metrics.pyi", "synthetic.pyi",
                 "py.typed"):
        assert (PACKAGE / name).is_file(), name


def test_stubtest_finds_the_module_and_the_stubs_equal():
    done = subprocess.run([sys.executable, "-m", "mypy.stubtest", "rpt", "--allowlist",
                           str(HERE / "stubtest_allowlist.txt")], capture_output=True, text=True)
    assert done.returncode == 0, done.stdout + done.stderr


def test_the_examples_type_check(tmp_path):
    code, out = mypy(tmp_path, *sorted((SOURCE_DIR / "python" / "examples").glob("*.py")))
    assert code == 0, out


def test_types_are_read_from_the_stubs_and_wrong_calls_refused(tmp_path):
    snippet = tmp_path / "snippet.py"
    snippet.write_text(textwrap.dedent("""\
        import rpt
        sequence = rpt.synthetic.scene(cameras=3, frames=5)
        predictions = rpt.Triangulator.for_sequence(sequence).process_sequence(sequence)
        persons, track_ids = predictions[0]
        reveal_type(track_ids)
        for frame in sequence:
            reveal_type(frame.timestamp)
        reveal_type(rpt.datasets.open("mvor", "/data", days=[1, 2]).load())
        rpt.Triangulator("cam0", ["nose"])
        rpt.synthetic.scene(camera=3)
        rpt.cameras.load(5)
        rpt.metrics.evaluate(sequence, [predictions])
        rpt.synthetic.scene(fps=25.0)
        import types
        rpt.Options(types.MappingProxyType({"filter.min_match_score": 0.5}))
        import numpy
        persons, track_ids = predictions[numpy.int64(1)]
        rpt.Triangulator.for_sequence(sequence).process(sequence[0].views, numpy.float32(0.04))
        rpt.metrics.evaluate([sequence], [predictions], options={"metrics.matching": "hungarian"})
        """))
    code, out = mypy(tmp_path, snippet)
    assert code == 1, out
    lines = {}  # line number -> mypy's messages about it
    for line in out.splitlines():
        if line.startswith("snippet.py:"):
            number = int(line.split(":")[1])
            lines[number] = lines.get(number, "") + line + "\n"
    assert "numpy.signedinteger[numpy._typing._64Bit]" in lines[5], out
    assert 'Union[builtins.float, None]' in lines[7], out
    assert "builtins.list[rpt.datasets.Sequence]" in lines[8], out
    assert 'incompatible type "str"; expected "Sequence[Camera]"' in lines[9], out
    assert 'Unexpected keyword argument "camera" for "scene"' in lines[10], out
    assert 'incompatible type "int"' in lines[11], out
    # What the runtime refuses, refused by the stubs too (a typed user's findings): a list of
    # predictions for one sequence, a fractional frame rate, a mapping that is no dict.
    assert 'No overload variant of "evaluate" matches' in lines[12], out
    assert 'incompatible type "float"; expected "SupportsIndex"' in lines[13], out
    assert 'incompatible type "MappingProxyType' in lines[15], out
    # What it accepts, accepted: numpy scalars as a frame index and a time, lists of both.
    assert sorted(lines) == [5, 7, 8, 9, 10, 11, 12, 13, 15], out
