"""A host program's numeric locale (Python's locale.setlocale, as Jupyter and GUI toolkits call it)
must not change what the module reads or writes: the C library's printf and strtod follow
LC_NUMERIC, and de_DE's decimal comma once cut MVOR's frame times to whole seconds and split every
CSV number into two fields."""
import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import SHARED_DATA

SCRIPT = r"""
import json, locale, sys, warnings
locale.setlocale(locale.LC_NUMERIC, sys.argv[1])
assert locale.localeconv()["decimal_point"] == sys.argv[3], locale.localeconv()["decimal_point"]
import rpt
warnings.simplefilter("ignore")
out = sys.argv[2]
result = {}
seq = rpt.synthetic.scene(frames=3, seed=3)
pred = rpt.Triangulator.for_sequence(seq).process_sequence(seq)
rpt.export.write(out, pred, "csv,trc,json")
result["synthetic"] = rpt.metrics.evaluate(seq, pred)
if len(sys.argv) > 4:
    mvor = rpt.datasets.open("mvor", sys.argv[4], days=3).load()[0]
    result["mvor_times"] = [frame.timestamp for frame in mvor[:5]]
    mvor_pred = rpt.Triangulator.for_sequence(mvor).process_sequence(mvor)
    result["mvor"] = rpt.metrics.evaluate(mvor, mvor_pred)
print(json.dumps(result, sort_keys=True, default=str))
"""


@pytest.fixture(scope="session")
def comma_locale(tmp_path_factory):
    """(LOCPATH, name) of de_DE.UTF-8 compiled into a scratch folder (no system change)."""
    folder = tmp_path_factory.mktemp("locales")
    try:
        made = subprocess.run(["localedef", "-i", "de_DE", "-f", "UTF-8", str(folder / "de_DE.UTF-8")],
                              capture_output=True, text=True)
    except FileNotFoundError:
        pytest.skip("localedef is not installed")
    if not (folder / "de_DE.UTF-8").exists():
        pytest.skip(f"cannot compile the de_DE.UTF-8 locale (Debian package locales): {made.stderr.strip()}")
    return str(folder), "de_DE.UTF-8"


def run(locale_name, decimal_point, out, locpath=None):
    env = dict(os.environ)
    if locpath:
        env["LOCPATH"] = locpath
    args = [sys.executable, "-c", SCRIPT, locale_name, str(out), decimal_point]
    mvor = SHARED_DATA / "mvor"
    if (mvor / "camma_mvor_2018.json").exists():
        args.append(str(mvor))
    done = subprocess.run(args, capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def without_timing(summary):
    return {key: value for key, value in summary.items()
            if not any(word in key for word in ("fps", "time", "per_s", "run_id", "seconds"))}


def test_a_decimal_comma_locale_changes_no_number_read_or_written(comma_locale, tmp_path):
    locpath, name = comma_locale
    c = run("C", ".", tmp_path / "c")
    de = run(name, ",", tmp_path / "de", locpath)
    assert without_timing(de["synthetic"]) == without_timing(c["synthetic"])
    csv = (tmp_path / "de" / "predictions.csv").read_text()
    assert csv == (tmp_path / "c" / "predictions.csv").read_text()
    assert "0,000000" not in csv  # a time written with a decimal comma
    trc_c = sorted((tmp_path / "c" / "trc").iterdir())
    assert trc_c and [p.name for p in trc_c] == [p.name for p in sorted((tmp_path / "de" / "trc").iterdir())]
    for path in trc_c:
        assert (tmp_path / "de" / "trc" / path.name).read_text() == path.read_text(), path.name
    if "mvor" in c:
        assert de["mvor_times"] == c["mvor_times"]
        assert c["mvor_times"][1] != round(c["mvor_times"][1])  # fractions of a second kept
        assert without_timing(de["mvor"]) == without_timing(c["mvor"])
