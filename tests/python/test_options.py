"""rpt.Options: every key of `rpt config --dump`, typed; round trips through dicts and JSON files."""
import copy
import json
import pickle

import pytest

import rpt

from conftest import run_cli


def test_every_cli_key_is_there_typed():
    dumped = json.loads(run_cli("config", "--dump").stdout)
    keys = [f"{section}.{name}" for section, values in dumped.items() for name in values]
    assert rpt.Options.keys() == keys
    options = rpt.Options()
    for key in keys:
        section, name = key.split(".", 1)
        value = options[key]
        expected = dumped[section][name]
        if isinstance(value, tuple):
            assert list(value) == expected, key
        else:
            assert value == expected and type(value) is type(expected), key


def test_types():
    options = rpt.Options()
    assert options["track.enabled"] is True
    assert isinstance(options["group.min_group_size"], int)
    assert options["filter.min_match_score"] == 0.7
    assert options["metrics.matching"] == "greedy"
    assert isinstance(options["metrics.evaluated_joints"], list)
    options["room_check.size_m"] = [8, 8, 3]
    assert options["room_check.size_m"] == (8.0, 8.0, 3.0)
    options["metrics.evaluated_joints"] = ["nose", "hip_left"]
    assert options["metrics.evaluated_joints"] == ["nose", "hip_left"]
    info = rpt.Options.describe("filter.min_match_score")
    assert info["type"] == "number in [0, 1]" and info["default"] == "0.7"


def test_round_trips(tmp_path):
    options = rpt.Options({"filter": {"min_match_score": 0.55}, "track.enabled": False,
                           "metrics.matching": "hungarian", "room_check.size_m": (6, 7, 3)})
    assert "filter.min_match_score=0.55" in repr(options)
    assert rpt.Options.from_dict(options.to_dict()) == options
    path = tmp_path / "config.json"
    path.write_text(options.to_json())
    assert rpt.Options.from_json(path) == options
    assert json.loads(run_cli("config", "--dump", "--config", path).stdout) == json.loads(options.to_json())
    assert options != rpt.Options()
    copy = options.copy()
    copy["track.enabled"] = True
    assert options["track.enabled"] is False


def test_check_between_fields_names_the_key():
    options = rpt.Options({"postprocess.min_extent_m": 1.0})
    options["postprocess.max_extent_m"] = 0.5  # each value in range, together not
    expected = "postprocess.max_extent_m: 0.5 is below postprocess.min_extent_m (1)"
    with pytest.raises(rpt.ConfigError, match=expected.replace("(", r"\(").replace(")", r"\)")):
        options.check()
    with pytest.raises(rpt.ConfigError, match=r"postprocess.max_extent_m: 0.5 is below"):
        rpt.Triangulator(rpt.synthetic.scene(frames=1).cameras, ["nose"], options)
    with pytest.raises(rpt.ConfigError, match=r"postprocess.max_extent_m: 0.5 is below"):
        rpt.Options.from_dict(options.to_dict())


def test_core_joints_too_few_for_what_a_pose_needs_fail_the_check():
    # check() said nothing; the Triangulator then refused the same options.
    options = rpt.Options({"triangulate.core_joints": ["nose"]})
    with pytest.raises(rpt.ConfigError, match=r"^triangulate.min_core_joints: 3 exceeds the number of core joints "
                                              r"\(1, triangulate.core_joints\)$"):
        options.check()
    options["triangulate.min_core_joints"] = 1
    with pytest.raises(rpt.ConfigError, match=r"^undistort.min_core_joints: 3 exceeds"):
        options.check()
    options["undistort.min_core_joints"] = 1
    options.check()


def test_copied_pickled_and_given_to_options():
    options = rpt.Options({"filter.min_match_score": 0.6, "room_check.size_m": (6, 7, 3)})
    for twin in (copy.copy(options), copy.deepcopy(options), pickle.loads(pickle.dumps(options)), rpt.Options(options)):
        assert twin == options
        twin["filter.min_match_score"] = 0.7
        assert options["filter.min_match_score"] == 0.6, "a copy, not the same object"
    with pytest.raises(TypeError, match=r"^Options: expected a dict of values or an rpt.Options, got list$"):
        rpt.Options([1])


def test_warnings_of_settings_without_effect():
    options = rpt.Options({"track.enabled": False, "smooth.mode": "causal", "clip_speed.enabled": False})
    assert options.warnings() == ["smooth.mode=causal has no effect with track.enabled=false (it needs track ids)"]
    assert rpt.Options().warnings() == []
