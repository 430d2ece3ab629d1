"""The module's results equal the CLI's on the same input: `rpt eval --json` on a synthetic scene
against rpt.datasets.open + Triangulator.process_sequence + metrics.evaluate, and the exports."""
import json
import math

import numpy as np
import pytest

import rpt
from conftest import SCENE, run_cli, scene_params

# Keys that measure this run's time, not its results.
TIMING_KEYS = {"fps", "frame_time_us_median", "eval_frames_per_s", "step_time_us_median"}
# What `rpt eval --json` says of its run folder (the module writes none).
RUN_KEYS = {"run_id", "output"}


def test_summary_equals_rpt_eval_json(cli_eval, scene, predictions):
    cli_summary, _ = cli_eval
    summary = rpt.metrics.evaluate(scene, predictions)
    assert list(summary.keys()) == [key for key in cli_summary if key not in RUN_KEYS]
    for key, value in cli_summary.items():
        if key in TIMING_KEYS or key in RUN_KEYS:
            continue
        assert summary[key] == value, key  # bit for bit: JSON doubles round-trip exactly
    assert summary["frames"] == 40
    assert summary["gt_persons"] == 160
    assert summary["recall500"] > 90


def test_predictions_equal_predictions_json(cli_eval, predictions):
    _, out = cli_eval
    written = json.loads((out / "predictions.json").read_text())
    assert written["joints"] == predictions.joint_names
    assert len(written["frames"]) == len(predictions) == 40
    for i, frame in enumerate(written["frames"]):
        persons, track_ids = predictions[i]
        assert frame["id"] == predictions.frame_ids[i]
        assert frame["track_ids"] == track_ids.tolist()
        expected = np.array([[[math.nan if v is None else v for v in joint] for joint in person]
                             for person in frame["persons"]]).reshape(persons.shape)
        present = persons[..., 3] > 0
        # predictions.json holds 6 decimals (scores 4)
        np.testing.assert_allclose(expected[..., :3][present], persons[..., :3][present], rtol=0, atol=5e-7)
        np.testing.assert_allclose(expected[..., 3], persons[..., 3], rtol=0, atol=5e-5)
        assert frame["provenance"] == predictions.provenance(i).tolist()


def test_exports_equal_the_clis(cli_eval, predictions, tmp_path):
    _, out = cli_eval
    written = rpt.export.write(tmp_path, predictions, "json,csv,trc,npz")
    assert [p.name for p in written] == ["predictions.json", "predictions.csv", "trc", "predictions.npz"]
    with np.load(tmp_path / "predictions.npz") as ours, np.load(out / "predictions.npz") as theirs:
        assert sorted(ours.files) == sorted(theirs.files)
        assert str(ours["run_id"]) == "python"
        for name in ours.files:
            if name != "run_id":
                np.testing.assert_array_equal(ours[name], theirs[name], err_msg=name)
    assert (tmp_path / "predictions.csv").read_bytes() == (out / "predictions.csv").read_bytes()
    cli_trc = sorted(p.name for p in (out / "trc").iterdir())
    assert cli_trc and sorted(p.name for p in (tmp_path / "trc").iterdir()) == cli_trc
    for name in cli_trc:
        assert (tmp_path / "trc" / name).read_bytes() == (out / "trc" / name).read_bytes(), name
    ours = json.loads((tmp_path / "predictions.json").read_text())
    theirs = json.loads((out / "predictions.json").read_text())
    assert ours.pop("run_id") == "python"
    theirs.pop("run_id")
    assert ours == theirs


def test_export_without_filled_and_predicted_joints_equals_the_clis(tmp_path):
    """filled_joints=False and predicted_joints=False write what --no-filled-joints and
    --no-predicted-joints write: those joints missing (provenance kept), every other as by default.
    The hard detector's scene has both (its tracks coast)."""
    hard = dict(SCENE, noise="hard")
    sequence = rpt.synthetic.scene(**hard)
    predictions = rpt.Triangulator.for_sequence(sequence).process_sequence(sequence)
    out = tmp_path / "cli"
    run_cli("eval", "--dataset", "synthetic", *scene_params(hard), "--quiet", "--export", "npz", "--no-filled-joints",
            "--no-predicted-joints", "--out", out)
    rpt.export.write(tmp_path / "py", predictions, "npz", filled_joints=False, predicted_joints=False)
    rpt.export.write(tmp_path / "all", predictions, "npz")
    with np.load(tmp_path / "py" / "predictions.npz") as ours, np.load(out / "predictions.npz") as theirs, \
            np.load(tmp_path / "all" / "predictions.npz") as everything:
        np.testing.assert_array_equal(ours["poses"], theirs["poses"])
        provenance, poses, all_poses = ours["provenance"], ours["poses"], everything["poses"]
    dropped = np.isin(provenance, (1, 4)) & (all_poses[..., 3] > 0)
    assert (provenance[dropped] == 1).sum() > 10 and (provenance[dropped] == 4).sum() > 10
    assert np.isnan(poses[dropped][:, :3]).all() and (poses[dropped][:, 3] == 0).all()
    np.testing.assert_array_equal(poses[~dropped], all_poses[~dropped])


def test_frame_by_frame_equals_process_sequence(scene, predictions):
    triangulator = rpt.Triangulator.for_sequence(scene)
    for i, frame in enumerate(scene):
        persons, track_ids = triangulator.process(frame.views, frame.timestamp)
        expected_persons, expected_ids = predictions[i]
        assert np.array_equal(persons, expected_persons)
        assert np.array_equal(track_ids, expected_ids)
        assert np.array_equal(triangulator.last_provenance, predictions.provenance(i))


def test_list_of_frames_equals_sequence(scene, predictions):
    from_list = rpt.Triangulator.for_sequence(scene).process_sequence(
        [(frame.views, frame.timestamp) for frame in scene])
    assert len(from_list) == len(predictions)
    for i in range(len(predictions)):
        assert np.array_equal(from_list[i][0], predictions[i][0])
        assert np.array_equal(from_list[i][1], predictions[i][1])
    from_frames = rpt.Triangulator.for_sequence(scene).process_sequence(list(scene))
    assert from_frames.frame_ids == predictions.frame_ids
    assert all(np.array_equal(from_frames[i][0], predictions[i][0]) for i in range(len(predictions)))


def test_streamed_frames_equal_loaded_ones(scene):
    streamed = list(rpt.datasets.open("synthetic", cameras=5, people=4, frames=40, noise="clean", seed=3))
    assert [f.id for f in streamed] == [f.id for f in scene]
    for a, b in zip(streamed, scene):
        assert a.timestamp == b.timestamp
        assert np.array_equal(a.gt, b.gt)
        assert all(np.array_equal(x, y) for x, y in zip(a.views, b.views))


def test_reset_starts_afresh(scene, predictions):
    triangulator = rpt.Triangulator.for_sequence(scene)
    triangulator.process_sequence(scene)
    triangulator.reset()
    again = triangulator.process_sequence(scene)
    assert all(np.array_equal(again[i][0], predictions[i][0]) for i in range(len(predictions)))
    assert all(np.array_equal(again[i][1], predictions[i][1]) for i in range(len(predictions)))


def test_options_change_the_result_like_set(scene, tmp_path):
    from conftest import SCENE, run_cli, scene_params
    done = run_cli("eval", "--dataset", "synthetic", *scene_params(), "--set", "filter.min_match_score=0.9",
                   "--set", "metrics.matching=hungarian", "--json", "--quiet", "--out", tmp_path / "run")
    cli_summary = json.loads(done.stdout)
    options = rpt.Options({"filter.min_match_score": 0.9, "metrics": {"matching": "hungarian"}})
    predictions = rpt.Triangulator.for_sequence(scene, options).process_sequence(scene)
    summary = rpt.metrics.evaluate(scene, predictions, options=options)
    for key in ("pcp", "pcp_parts", "mpjpe_mm", "recall500", "invalid", "predictions", "matches"):
        assert summary[key] == cli_summary[key], key
    # the same through keyword arguments
    assert rpt.metrics.evaluate(scene, predictions, matching="hungarian")["mpjpe_mm"] == cli_summary["mpjpe_mm"]


def test_stats_per_step(scene):
    triangulator = rpt.Triangulator.for_sequence(scene)
    triangulator.process(scene[0].views, scene[0].timestamp)
    stats = triangulator.stats
    assert list(stats["steps"])[:2] == ["undistort", "make_pairs"]
    assert stats["steps"]["merge"]["count"] == 4  # the four people of the scene, each found once
    assert stats["total_us"] > 0
    # every extra counter of the CLI's step table, under its name (verification dropped no copy here)
    assert stats["duplicate_persons"] == 0 and stats["unsupported_persons"] == 0
    assert {"pruned_limbs", "conflicting_proposals", "held_joints", "one_view_joints"} <= set(stats)


def test_offline_smoothing_equals_the_clis(scene, tmp_path):
    from conftest import SCENE, run_cli, scene_params
    done = run_cli("eval", "--dataset", "synthetic", *scene_params(), "--set", "smooth.mode=offline", "--json",
                   "--quiet", "--out", tmp_path / "run")
    cli_summary = json.loads(done.stdout)
    options = {"smooth.mode": "offline"}
    triangulator = rpt.Triangulator.for_sequence(scene, options)
    with pytest.raises(rpt.ConfigError, match=r"smooth.mode=offline smooths whole sequences: use process_sequence"):
        triangulator.process(scene[0].views)
    predictions = triangulator.process_sequence(scene)
    assert 2 in predictions.provenance(10)  # smoothed joints
    summary = rpt.metrics.evaluate(scene, predictions)
    for key, value in cli_summary.items():
        if key not in TIMING_KEYS and key not in RUN_KEYS:
            assert summary[key] == value, key


def test_stored_results_are_read_only_views_without_copies(scene):
    predictions = rpt.Triangulator.for_sequence(scene).process_sequence(scene)
    frame = next(i for i in range(len(predictions)) if predictions[i][0].shape[0] > 0)
    persons, _ = predictions[frame]
    again, _ = predictions[frame]
    assert np.shares_memory(persons, again)  # both views of the one stored result
    assert not persons.flags.writeable
    with pytest.raises(ValueError, match="read-only"):
        persons[0, 0, 0] = 1.0
    provenance = predictions.provenance(frame)
    assert np.shares_memory(provenance, predictions.provenance(frame)) and not provenance.flags.writeable
    expected = persons.copy()
    del predictions, again  # the view keeps the stored result alive
    np.testing.assert_array_equal(persons, expected)
    assert persons.shape[1:] == (len(scene.joint_names) + 3, 4)


def test_frames_hand_out_read_only_views_of_their_detections_and_gt():
    frame = next(iter(rpt.datasets.open("synthetic", frames=2, cameras=3, people=2)))
    views, gt = frame.views, frame.gt
    assert len(views) == 3 and gt.shape == (2, gt.shape[1], 4)
    for view, again in zip(views, frame.views):
        assert view.shape[0] > 0 and np.shares_memory(view, again) and not view.flags.writeable
    assert np.shares_memory(gt, frame.gt) and not gt.flags.writeable
    expected = [v.copy() for v in views]
    del frame  # the views keep the frame alive
    for view, copy in zip(views, expected):
        np.testing.assert_array_equal(view, copy)
