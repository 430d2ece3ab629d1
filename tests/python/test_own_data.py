"""Files in, as a user's own data: generic labels and detections JSON (written by `rpt convert`),
read by rpt.datasets.open_labels / open_cameras, give what `rpt eval --labels` and
`rpt triangulate --cameras` give."""
import json

import numpy as np

import pytest

import rpt

from conftest import run_cli, scene_params

TIMING_KEYS = {"fps", "frame_time_us_median", "eval_frames_per_s", "step_time_us_median"}


@pytest.fixture(scope="module")
def files(tmp_path_factory):
    folder = tmp_path_factory.mktemp("own_data")
    run_cli("convert", "--dataset", "synthetic", *scene_params(), "--labels-out", folder / "labels.json",
            "--detections-out", folder / "detections.json")
    return folder


def test_labels_and_detections_equal_rpt_eval(files, tmp_path):
    done = run_cli("eval", "--labels", files / "labels.json", "--detections", files / "detections.json", "--json",
                   "--quiet", "--out", tmp_path / "run")
    cli_summary = json.loads(done.stdout)
    sequences = rpt.datasets.open_labels(str(files / "labels.json"),
                                         detections_file=str(files / "detections.json")).load()
    predictions = [rpt.Triangulator.for_sequence(s).process_sequence(s) for s in sequences]
    summary = rpt.metrics.evaluate(sequences, predictions)
    for key, value in cli_summary.items():
        if key not in TIMING_KEYS and key not in ("run_id", "output"):
            assert summary[key] == value, key


def test_cameras_and_detections_equal_rpt_triangulate(files, tmp_path):
    run_cli("triangulate", "--cameras", files / "labels.json", "--detections", files / "detections.json", "--fps",
            25, "--export", "csv,trc", "--out", tmp_path / "cli")
    dataset = rpt.datasets.open_cameras(str(files / "labels.json"), str(files / "detections.json"), fps=25)
    (sequence,) = dataset.load()
    assert sequence.fps == 25 and len(sequence) == 40
    predictions = rpt.Triangulator.for_sequence(sequence).process_sequence(sequence)
    rpt.export.write(tmp_path / "py", predictions, ["csv", "trc"])
    assert (tmp_path / "py" / "predictions.csv").read_bytes() == (tmp_path / "cli" / "predictions.csv").read_bytes()
    names = sorted(p.name for p in (tmp_path / "cli" / "trc").iterdir())
    assert names and names == sorted(p.name for p in (tmp_path / "py" / "trc").iterdir())
    # Written again (a notebook cell re-run): the same files, replaced; the first write's TRC files
    # were kept and this write's tracks went to *_from1.trc. A link left there is removed, never
    # followed; other files stay.
    outside = tmp_path / "outside.txt"
    outside.write_text("keep")
    (tmp_path / "py" / "trc" / names[0]).unlink()
    (tmp_path / "py" / "trc" / names[0]).symlink_to(outside)
    (tmp_path / "py" / "trc" / "notes.txt").write_text("mine")
    (tmp_path / "py" / "trc" / "stale_track9.trc").write_text("an earlier run's track")
    rpt.export.write(tmp_path / "py", predictions, ["trc"])
    assert sorted(p.name for p in (tmp_path / "py" / "trc").iterdir()) == sorted(names + ["notes.txt"])
    for name in names:
        assert (tmp_path / "py" / "trc" / name).read_bytes() == (tmp_path / "cli" / "trc" / name).read_bytes()
    assert not (tmp_path / "py" / "trc" / names[0]).is_symlink() and outside.read_text() == "keep"
    # That write was trc only: the first write's CSV is gone too (it held the earlier run beside
    # this one's TRC files); a link there is removed, never followed.
    assert not (tmp_path / "py" / "predictions.csv").exists()
    (tmp_path / "py" / "predictions.npz").symlink_to(outside)
    rpt.export.write(tmp_path / "py", predictions, "json")
    assert sorted(p.name for p in (tmp_path / "py").iterdir()) == ["predictions.json", "trc"]
    assert sorted(p.name for p in (tmp_path / "py" / "trc").iterdir()) == ["notes.txt"] and outside.read_text() == "keep"


def test_export_refuses_what_one_write_cannot_hold(files, tmp_path):
    dataset = rpt.datasets.open_cameras(str(files / "labels.json"), str(files / "detections.json"), fps=25)
    (sequence,) = dataset.load()
    take1 = rpt.Triangulator.for_sequence(sequence).process_sequence(sequence)
    take2 = rpt.Triangulator.for_sequence(sequence).process_sequence(sequence)
    # Two takes of one name were one sequence in the CSV: refused before anything is written.
    with pytest.raises(rpt.ConfigError, match=r"sequences 0 and 1 are both named 'detections': set each Predictions' "
                                              r"\.sequence"):
        rpt.export.write(tmp_path / "same", [take1, take2], "csv,trc")
    assert not (tmp_path / "same").exists()
    take1.sequence, take2.sequence = "take1", "take2"
    rpt.export.write(tmp_path / "named", [take1, take2], "csv,trc")
    assert sorted({line.split(",")[0] for line in (tmp_path / "named" / "predictions.csv").read_text().splitlines()[1:]}) \
        == ["take1", "take2"]
    # Other joints: refused before the JSON (whose one joint list they would contradict) is written.
    body = rpt.synthetic.scene(people=1, frames=5, joints="body")
    whole = rpt.synthetic.scene(people=1, frames=5, joints="wholebody")
    a = rpt.Triangulator.for_sequence(body).process_sequence(body)
    b = rpt.Triangulator.for_sequence(whole).process_sequence(whole)
    b.sequence = "whole"
    with pytest.raises(rpt.ConfigError, match=r"sequence 1 \('whole'\) has other output joints than sequence 0"):
        rpt.export.write(tmp_path / "mixed", [a, b], "json,trc")
    assert not (tmp_path / "mixed").exists()


def test_missing_detections_file(files):
    with pytest.raises(FileNotFoundError, match=r"nothing.json: file not found"):
        rpt.datasets.open_cameras(str(files / "labels.json"), str(files / "nothing.json"))


def test_open_cameras_takes_the_reading_options_of_the_cli(files, tmp_path):
    # A rig whose detections name the cameras "1".."N" and whose calibration is in millimetres: the
    # options of `rpt triangulate --cameras` (--rename-camera, --cameras-units), '_' for '-'.
    cameras = rpt.cameras.load(files / "labels.json")
    rpt.cameras.save(tmp_path / "mm.yml", cameras, units="mm")
    detections = json.loads((files / "detections.json").read_text())
    renames = {c.name: str(i + 1) for i, c in enumerate(cameras)}
    for frame in detections["frames"]:
        for view in frame["views"]:
            view["camera"] = renames[view["camera"]]
    (tmp_path / "numbered.json").write_text(json.dumps(detections))
    (expected,) = rpt.datasets.open_cameras(str(files / "labels.json"), str(files / "detections.json"), fps=25).load()
    (renamed,) = rpt.datasets.open_cameras(str(tmp_path / "mm.yml"), str(tmp_path / "numbered.json"), fps=25,
                                           cameras_units="mm",
                                           rename_camera={number: name for name, number in renames.items()}).load()
    assert [c.name for c in renamed.cameras] == [c.name for c in expected.cameras]
    for a, b in zip(renamed.cameras, expected.cameras):
        assert abs(a.t - b.t).max() < 1e-9
    assert len(renamed) == len(expected)
    for a, b in zip(renamed, expected):
        assert all((x == y).all() for x, y in zip(a.views, b.views))
    with pytest.raises(rpt.ConfigError, match=r"datasets.open_cameras: unknown option 'rename_cameras' \(known: "):
        rpt.datasets.open_cameras(str(files / "labels.json"), str(files / "detections.json"), rename_cameras={})
    with pytest.raises(rpt.ConfigError, match=r"cameras_units"):
        rpt.datasets.open_cameras(str(files / "labels.json"), str(files / "detections.json"), cameras_units="inch")


def test_times_in_milliseconds_and_going_back_are_warned_as_runs_warn():
    """process() and process_sequence() say what `rpt triangulate` says of frame times: milliseconds
    where seconds are expected end every track after one frame; a time going back ends them."""
    import warnings

    scene = rpt.synthetic.scene(cameras=3, people=2, frames=30, noise="clean")
    triangulator = rpt.Triangulator(scene.cameras, scene.joint_names)
    with pytest.warns(rpt.InputWarning, match=r"are the times in milliseconds\?") as caught:
        for k in range(30):
            triangulator.process(scene[k].views, 40.0 * k)  # a 25 fps video's times in ms
    assert sum("milliseconds" in str(w.message) for w in caught) == 1, "once, not per frame"

    triangulator.reset()
    with warnings.catch_warnings():
        warnings.simplefilter("error", rpt.InputWarning)  # seconds: nothing to say
        for k in range(30):
            triangulator.process(scene[k].views, 0.04 * k)
    with pytest.warns(rpt.InputWarning, match=r"1 frames whose time is not after the previous frame's"):
        triangulator.process(scene[0].views, 0.0)

    with pytest.warns(rpt.InputWarning, match=r"are the times in milliseconds\?"):
        triangulator.process_sequence([(scene[k].views, 40.0 * k) for k in range(30)])


def test_a_camera_without_data_is_none_and_does_not_vote_against_persons(tmp_path):
    """None is a camera with no data in the frame (dropped out); an empty array one that looked and
    saw nobody. Cameras 2-4 of five: as None the persons cameras 0 and 1 see stay (verification does
    not count them), as empty arrays three empty views outvote two and the persons go. A frame of a
    generic detections file that leaves those cameras out gives None for them."""
    sequence = rpt.datasets.open("synthetic", cameras=5, people=2, frames=3, noise="perfect").load()[0]
    frame = sequence[1]
    full_views = list(frame.views)
    empty = np.zeros((0,) + full_views[0].shape[1:])

    def persons(views):
        triangulator = rpt.Triangulator.for_sequence(sequence)
        return len(triangulator.process(views, None)[0])

    assert persons(full_views) == 2
    assert persons(full_views[:2] + [None, None, None]) == 2
    assert persons(full_views[:2] + [empty, empty, empty]) == 0

    run_cli("convert", "--dataset", "synthetic", "--param", "cameras=5", "--param", "people=2", "--param", "frames=3",
            "--param", "noise=perfect", "--labels-out", tmp_path / "labels.json",
            "--detections-out", tmp_path / "detections.json")
    detections = json.loads((tmp_path / "detections.json").read_text())
    detections["frames"][1]["views"] = detections["frames"][1]["views"][:2]
    (tmp_path / "dropped.json").write_text(json.dumps(detections))
    read = rpt.datasets.open_cameras(tmp_path / "labels.json", tmp_path / "dropped.json", fps=25).load()[0]
    views = list(read[1].views)
    assert views[2] is None and views[3] is None and views[4] is None
    assert views[0] is not None and len(views[0]) == 2
    assert persons(views) == 2


def test_joints_at_pixel_origin_are_missing_in_process_as_in_the_files():
    sequence = rpt.datasets.open("synthetic", cameras=5, people=2, frames=2, noise="perfect").load()[0]
    views = [np.array(view) for view in sequence[0].views]
    for view in views:
        view[:, 5] = [0.0, 0.0, 0.8]  # a detector's "not found" for shoulder_left
    triangulator = rpt.Triangulator.for_sequence(sequence)
    with pytest.warns(rpt.InputWarning, match=r"10 detected joints at pixel \(0, 0\) with a score above 0 read as missing"):
        persons, _ = triangulator.process(views, 0.0)
    clean = [np.array(view) for view in sequence[0].views]
    for view in clean:
        view[:, 5, 2] = 0.0  # the same joints missing
    expected, _ = rpt.Triangulator.for_sequence(sequence).process(clean, 0.0)
    np.testing.assert_array_equal(persons, expected)


def test_views_of_two_cameras_exchanged_are_warned_about_as_the_cli_does():
    """The usual wiring mistake of a detector loop (views in another order than the cameras) gave
    plausible persons without a word in Python, where `rpt triangulate` names both cameras: the
    same check (engine/camera_agreement.h) runs at the end of process_sequence and after 300 calls
    of process."""
    import warnings

    scene = rpt.synthetic.scene(cameras=5, people=3, frames=300, seed=3, noise="clean")
    order = [1, 0, 2, 3, 4]
    frames = [([f.views[i] for i in order], f.timestamp) for f in scene]
    with pytest.warns(rpt.InputWarning) as caught:
        rpt.Triangulator(scene.cameras, scene.joint_names).process_sequence(frames)
    agreement = [str(w.message) for w in caught if "match its detections" in str(w.message)]
    assert len(agreement) == 2, agreement
    assert "camera 'cam0': only" in agreement[0] and "camera 'cam1': only" in agreement[1]

    triangulator = rpt.Triangulator(scene.cameras, scene.joint_names)
    with pytest.warns(rpt.InputWarning) as caught:
        for views, time in frames:
            triangulator.process(views, time)
    assert sum("match its detections" in str(w.message) for w in caught) == 2

    with warnings.catch_warnings():
        warnings.simplefilter("error", rpt.InputWarning)  # the right order: nothing to say
        rpt.Triangulator(scene.cameras, scene.joint_names).process_sequence([(f.views, f.timestamp) for f in scene])
        triangulator = rpt.Triangulator(scene.cameras, scene.joint_names)
        for f in scene:
            triangulator.process(f.views, f.timestamp)


def test_mirrored_images_in_every_camera_are_warned_about_as_the_cli_does():
    """Detections of mirrored images (u -> width - u in every camera: a webcam's selfie view) gave
    junk persons without a word; the CLI's mirror-image check runs at the end of process_sequence."""
    scene = rpt.synthetic.scene(cameras=5, people=4, frames=60, noise="clean")
    frames = []
    for f in scene:
        views = []
        for camera, view in zip(scene.cameras, f.views):
            mirrored = view.copy()
            seen = mirrored[..., 2] > 0
            mirrored[..., 0][seen] = camera.width - mirrored[..., 0][seen]
            views.append(mirrored)
        frames.append((views, f.timestamp))
    with pytest.warns(rpt.InputWarning, match=r"persons with nose, shoulders and hips triangulated \(\d+ %\) have the "
                                              r"nose behind the shoulders, as mirror images have"):
        rpt.Triangulator(scene.cameras, scene.joint_names).process_sequence(frames)


def test_whole_body_detections_with_the_hands_exchanged_are_warned_about():
    """Left and right hand blocks exchanged in every view (a whole-body user's converter): the hands
    landed 0.5 m off without a word; the check of the CLI runs at the end of process_sequence, and
    says nothing of the same detections in order."""
    import warnings

    scene = rpt.synthetic.scene(cameras=4, people=2, frames=60, joints="wholebody", noise="clean")
    names = scene.joint_names
    left = [j for j, n in enumerate(names) if n.startswith("hand_") and n.endswith("_left")]
    right = [j for j, n in enumerate(names) if n.startswith("hand_") and n.endswith("_right")]
    assert len(left) == len(right) == 21
    frames = []
    for f in scene:
        views = [v.copy() for v in f.views]
        for v in views:
            v[:, left + right] = v[:, right + left]
        frames.append((views, f.timestamp))
    with pytest.warns(rpt.InputWarning, match=r"^synthetic: (\d+) of the \1 hands with 5 or more joints triangulated "
                                              r"\(100 %\) lie at the other wrist: are the detections' left and right "
                                              r"hands exchanged"):
        rpt.Triangulator.for_sequence(scene).process_sequence(frames)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        rpt.Triangulator.for_sequence(scene).process_sequence(scene)
    assert not [w for w in caught if "other wrist" in str(w.message)]
    # checks=False: the same persons, without the checks (they cost more than the triangulation).
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        unchecked = rpt.Triangulator.for_sequence(scene).process_sequence(frames, checks=False)
    assert not [w for w in caught if "other wrist" in str(w.message)]
    with pytest.warns(rpt.InputWarning):
        checked = rpt.Triangulator.for_sequence(scene).process_sequence(frames)
    assert len(unchecked) == len(checked)
    for i in range(len(checked)):
        assert np.array_equal(unchecked[i][0], checked[i][0]) and np.array_equal(unchecked[i][1], checked[i][1])


def test_settings_without_effect_and_frames_without_times_are_warned_about():
    scene = rpt.synthetic.scene(cameras=3, people=1, frames=5, noise="clean")
    with pytest.warns(rpt.InputWarning, match=r"smooth.mode=offline has no effect with track.enabled=false"):
        rpt.Triangulator(scene.cameras, scene.joint_names, {"smooth.mode": "offline", "track.enabled": False})
    with pytest.warns(rpt.InputWarning, match=r"^python: 5 frames without a timestamp: nothing is carried between "
                                              r"frames \(no tracking, no smoothing\)"):
        rpt.Triangulator(scene.cameras, scene.joint_names).process_sequence([f.views for f in scene])


def test_a_camera_whose_frames_are_off_the_others_is_named_by_process_sequence():
    """The CLI's check of each camera's frames against the others' (engine/camera_sync_check.h):
    camera 2's views of frame i taken from frame i + 3 (its clock 3 frames early)."""
    import warnings

    scene = rpt.synthetic.scene(cameras=5, people=3, frames=200, noise="clean")
    frames = [(list(f.views), f.timestamp) for f in scene]
    shifted = [([v if c != 2 else (frames[i + 3][0][2] if i + 3 < len(frames) else None)
                 for c, v in enumerate(views)], t) for i, (views, t) in enumerate(frames)]
    with pytest.warns(rpt.InputWarning, match=r"camera 'cam2': its detections agree best with the other cameras' of "
                                              r"about 3 frames \(0.12 s\) later"):
        rpt.Triangulator(scene.cameras, scene.joint_names).process_sequence(shifted)
    with warnings.catch_warnings():
        warnings.simplefilter("error", rpt.InputWarning)
        rpt.Triangulator(scene.cameras, scene.joint_names).process_sequence(frames)
