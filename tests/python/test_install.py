"""`cmake --install` puts the module into the Python site folder under the prefix, where it imports
without the build tree."""
import os
import subprocess
import sys

import pytest


def test_installed_module_imports(tmp_path):
    build = os.environ.get("RPT_BUILD_DIR")
    site = os.environ.get("RPT_PYTHON_INSTALL_DIR")
    if not build or not site:
        pytest.fail("RPT_BUILD_DIR / RPT_PYTHON_INSTALL_DIR not set: run the tests through ctest")
    prefix = tmp_path / "prefix"
    subprocess.run(["cmake", "--install", build, "--prefix", str(prefix)], check=True, capture_output=True)
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    env["PYTHONPATH"] = str(prefix / site)
    done = subprocess.run([sys.executable, "-c", "import rpt; print(rpt.__file__); "
                           "print(len(rpt.synthetic.scene(frames=2)))"],
                          env=env, capture_output=True, text=True, check=True, cwd=tmp_path)
    path, frames = done.stdout.split()
    assert path.startswith(str(prefix / site))
    assert frames == "2"
    # The type stubs and their PEP 561 marker go with the package (type checkers of the installed
    # module read them).
    for name in ("py.typed", "__init__.pyi", "datasets.pyi"):
        assert (prefix / site / "rpt" / name).is_file(), name
