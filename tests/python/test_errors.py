"""Every class of bad input raises the right Python exception with the CLI's words, never crashes:
arrays of the wrong dtype, shape or layout, NaN, empty arrays; bad options, parameters and files."""
import signal
import time

import numpy as np
import pytest

import rpt
from conftest import SHARED_DATA

from conftest import run_cli

JOINTS = 17


@pytest.fixture(scope="module")
def rig():
    scene = rpt.synthetic.scene(cameras=3, people=1, frames=2, noise="perfect")
    return scene, rpt.Triangulator(scene.cameras, scene.joint_names)


def good_views(rig):
    scene, _ = rig
    return [v.copy() for v in scene[0].views]


def test_good_views_pass(rig):
    _, triangulator = rig
    assert repr(triangulator) == "Triangulator(3 cameras, 17 joints)"
    persons, track_ids = triangulator.process(good_views(rig), 0.0)
    assert persons.shape == (1, 20, 4)  # 17 joints and the 3 derived ones
    assert track_ids.shape == (1,)


def test_dtypes_that_are_no_real_numbers_raise_type_error(rig):
    _, triangulator = rig
    views = good_views(rig)
    views[1] = np.array([["a"]], dtype=object)
    with pytest.raises(TypeError, match=r"views\[1\]: dtype object, expected real numbers"):
        triangulator.process(views)
    views[1] = good_views(rig)[1] > 0
    with pytest.raises(TypeError, match=r"views\[1\]: dtype bool, expected real numbers"):
        triangulator.process(views)
    views[1] = good_views(rig)[1].astype(np.complex128)
    with pytest.raises(TypeError, match=r"views\[1\]: dtype complex128"):
        triangulator.process(views)


def test_integer_pixels_are_read_as_numbers(rig):
    """Integer arrays are converted, as lists of integers are (a K of ints was refused as an array and
    taken as a list)."""
    _, triangulator = rig
    views = [np.round(v * [1, 1, 0]).astype(np.int64) for v in good_views(rig)]
    for v in views:
        v[..., 2] = 1
    as_float = [v.astype(np.float64) for v in views]
    triangulator.reset()
    expected = triangulator.process(as_float)[0]
    triangulator.reset()
    # Read, and said: an integer array's scores can only be whole numbers (a cast of a detector's
    # float scores to int makes every joint missing and nobody triangulated, without a word).
    with pytest.warns(rpt.InputWarning, match=r"^views\[0\]: an array of integers \(int64\): its scores are whole "
                                              r"numbers, so every joint scored below 1 reads as missing"):
        assert np.array_equal(triangulator.process(views)[0], expected)
    triangulator.reset()
    assert np.array_equal(triangulator.process([v.tolist() for v in views])[0], expected)
    K = np.array([[1000, 0, 960], [0, 1000, 540], [0, 0, 1]])
    assert np.array_equal(rpt.Camera(name="a", width=1920, height=1080, K=K, t=[0, 0, 5]).K, K)


def test_float32_is_accepted(rig):
    _, triangulator = rig
    views = [v.astype(np.float32) for v in good_views(rig)]
    persons, _ = triangulator.process(views)
    assert persons.shape[0] == 1


def test_wrong_shape_raises_value_error(rig):
    _, triangulator = rig
    views = good_views(rig)
    views[0] = views[0][..., :2].copy()
    with pytest.raises(ValueError, match=r"views\[0\]: shape \(1, 17, 2\), expected \(n, n, 3\)"):
        triangulator.process(views)
    views = good_views(rig)
    views[2] = np.zeros((1, 13, 3))
    with pytest.raises(ValueError, match=r"views\[2\]: 13 joints, expected 17"):
        triangulator.process(views)
    views[2] = np.zeros((17, 3))
    with pytest.raises(ValueError, match=r"views\[2\]: shape \(17, 3\), expected 3 dimensions"):
        triangulator.process(views)


def test_wrong_number_of_views_raises(rig):
    _, triangulator = rig
    with pytest.raises(ValueError, match=r"views: 2 views for 3 cameras"):
        triangulator.process(good_views(rig)[:2])
    with pytest.raises(TypeError, match=r"views: expected a list"):
        triangulator.process({"a": 1})


def test_any_layout_is_read(rig):
    """A detector's (n, J, 4) output sliced to x, y, score, a Fortran-order or a float32 strided array:
    read as the contiguous float64 copy would be."""
    _, triangulator = rig
    views = good_views(rig)
    triangulator.reset()
    expected = triangulator.process(views)[0]
    with_extra = [np.concatenate([v, np.ones(v.shape[:2] + (1,))], axis=2) for v in views]
    sliced = [v[:, :, :3] for v in with_extra]
    assert not sliced[0].flags.c_contiguous
    triangulator.reset()
    assert np.array_equal(triangulator.process(sliced)[0], expected)
    triangulator.reset()
    assert np.array_equal(triangulator.process([np.asfortranarray(v) for v in views])[0], expected)
    triangulator.reset()
    as_float32 = triangulator.process([v.astype(np.float32)[:, :, :3] for v in with_extra])[0]
    triangulator.reset()
    assert np.array_equal(as_float32, triangulator.process([v.astype(np.float32) for v in views])[0])


def test_an_empty_list_is_a_camera_that_saw_nobody(rig):
    _, triangulator = rig
    views = good_views(rig)
    nobody = [views[0], np.zeros((0, JOINTS, 3)), views[2]]
    triangulator.reset()
    expected = triangulator.process(nobody)[0]
    triangulator.reset()
    assert np.array_equal(triangulator.process([views[0].tolist(), [], views[2].tolist()])[0], expected)


def test_nan_and_bad_scores_raise_input_error(rig):
    _, triangulator = rig
    views = good_views(rig)
    views[1][0, 5, 0] = np.nan
    with pytest.raises(rpt.InputError, match=r"camera '.*': detection 0, joint '.*' contains NaN or infinity"):
        triangulator.process(views)
    # A joint of score 0 is missing: NaN coordinates there are numpy's way to say so, and accepted,
    # in a list of views and in one array of all views alike.
    views[1][0, 5, 2] = 0.0
    views[1][0, 6] = np.nan
    views[1][0, 6, 2] = 0.0
    persons = triangulator.process(views)[0]
    assert np.isfinite(persons).all()
    assert triangulator.process(np.stack(views))[0].shape == persons.shape
    views = good_views(rig)
    views[0][0, 3, 2] = 1.7
    with pytest.raises(ValueError, match=r"camera '.*': detection 0, joint '.*': score 1.7 outside \[0, 1\] "
                                          r"\(values up to 1.5 are clamped to 1"):
        triangulator.process(views)
    views[0][0, 3, 2] = 1.5000001  # written as given, not rounded to a value that would be accepted
    with pytest.raises(ValueError, match=r"score 1.5000001 outside"):
        triangulator.process(views)
    # A detector's 1.02 is clamped to 1 and warned about, as the file readers and live lines do.
    views[0][0, 3, 2] = 1.02
    triangulator.reset()
    with pytest.warns(rpt.InputWarning, match=r"^Triangulator.process: 1 scores above 1 clamped to 1 \(largest = 1.02\)"):
        clamped = triangulator.process(views, 0.0)[0]
    views[0][0, 3, 2] = 1.0
    triangulator.reset()
    assert np.array_equal(clamped, triangulator.process(views, 0.0)[0])
    with pytest.warns(rpt.InputWarning, match=r"^process_sequence: 2 scores above 1 clamped to 1 \(largest = 1.3\)"):
        views[0][0, 3, 2] = 1.3
        views[1][0, 4, 2] = 1.1
        triangulator.process_sequence([(views, 0.0)])
    with pytest.raises(ValueError, match=r"timestamp: must be finite seconds, or None \(unknown\); got inf"):
        triangulator.process(good_views(rig), float("inf"))
    # NaN is not "unknown" (None is): a failing clock would end every track unseen.
    with pytest.raises(ValueError, match=r"timestamp: must be finite seconds, or None \(unknown\); got nan"):
        triangulator.process(good_views(rig), float("nan"))
    with pytest.raises(ValueError, match=r"got nan"):
        triangulator.process_sequence([(good_views(rig), float("nan"))])
    with pytest.raises(TypeError, match=r"^timestamp: expected seconds \(a number\) or None, got str$"):
        triangulator.process(good_views(rig), "x")
    assert triangulator.process(good_views(rig), np.float64(2.0))[0].shape == (1, 20, 4)  # numpy scalars are numbers
    # A flag is no time (True has a float value, 1.0).
    for flag in (True, np.bool_(True)):
        with pytest.raises(TypeError, match=r"^timestamp: expected seconds \(a number\) or None, got (bool|bool_)$"):
            triangulator.process(good_views(rig), flag)
    # process_sequence's errors of a frame say which frame; a (views, "x") pair is a bad time, not a
    # frame of two views.
    frames = [(good_views(rig), float(i)) for i in range(4)]
    frames[2] = (good_views(rig), "x")
    with pytest.raises(TypeError, match=r"^process_sequence: frames\[2\]: timestamp: expected seconds"):
        triangulator.process_sequence(frames)
    frames[2] = (good_views(rig), np.float32(2.0))  # a numpy float32 time (no Python float) is a time
    assert len(triangulator.process_sequence(frames)) == 4
    frames[3] = (good_views(rig)[:2], 3.0)
    with pytest.raises(ValueError, match=r"^process_sequence: frames\[3\]: views: 2 views for 3 cameras$"):
        triangulator.process_sequence(frames)
    frames[3] = (good_views(rig)[:2] + [np.zeros((1, 5, 3))], 3.0)
    with pytest.raises(ValueError, match=r"^process_sequence: frames\[3\]: views\[2\]: 5 joints, expected 17"):
        triangulator.process_sequence(frames)
    # A ragged list of views is the argument's ValueError, not an internal error.
    ragged = [[[[1.0, 2.0, 0.5]] * JOINTS, [[1.0, 2.0]] * JOINTS]] + good_views(rig)[1:]
    with pytest.raises(ValueError, match=r"not an array of numbers"):
        triangulator.process(ragged)


def test_frames_index_like_a_python_sequence(predictions):
    last = len(predictions) - 1
    assert np.array_equal(predictions.provenance(-1), predictions.provenance(last))
    assert predictions.stats(-1) == predictions.stats(last)
    for bad in (len(predictions), -len(predictions) - 1):
        for call in (lambda: predictions[bad], lambda: predictions.provenance(bad), lambda: predictions.stats(bad)):
            with pytest.raises(IndexError, match=r"^frame index out of range$"):
                call()
    # Slices as Python sequences slice (they were pybind11's overload error).
    part = predictions[1:4]
    assert len(part) == 3 and np.array_equal(part[0][0], predictions[1][0])
    assert len(predictions[::-1]) == len(predictions) and np.array_equal(predictions[::-1][0][1], predictions[-1][1])


def test_sequences_slice_into_frames_process_sequence_takes(scene):
    frames = scene[2:5]
    assert [frame.id for frame in frames] == [scene[i].id for i in range(2, 5)]
    assert len(rpt.Triangulator.for_sequence(scene).process_sequence(frames)) == 3
    assert scene[10:2] == []


def test_empty_arrays(rig):
    _, triangulator = rig
    # a camera that sees nobody: None or (0, joints, 3)
    views = good_views(rig)
    views[0] = None
    views[1] = np.zeros((0, JOINTS, 3))
    triangulator.process(views)
    views[1] = np.zeros((0,))
    with pytest.raises(ValueError, match=r"views\[1\]: shape \(0,\), expected 3 dimensions"):
        triangulator.process(views)
    with pytest.raises(ValueError, match=r"process_sequence: no frames"):
        triangulator.process_sequence([])
    with pytest.raises(ValueError, match=r"cameras: empty list"):
        rpt.Triangulator([], ["nose"])


def test_bad_frames_in_a_sequence_name_the_frame(rig):
    _, triangulator = rig
    views = good_views(rig)
    views[2][0, 0, 1] = np.inf
    with pytest.raises(rpt.InputError, match=r"process_sequence: frames\[1\]: frame '1', camera"):
        triangulator.process_sequence([good_views(rig), views])


def test_bad_option_values_name_the_key():
    with pytest.raises(rpt.ConfigError) as error:
        rpt.Options({"filter.min_match_score": 1.5})
    assert str(error.value) == "Options: filter.min_match_score: '1.5' is not a number in [0, 1]"
    assert isinstance(error.value, ValueError)
    options = rpt.Options()
    with pytest.raises(rpt.ConfigError, match=r"Options: group.min_group_size: '2.5' is not an integer"):
        options["group.min_group_size"] = 2.5
    with pytest.raises(rpt.ConfigError, match=r"did you mean 'filter.min_match_score'"):
        options["filter.min_match_scor"] = 0.5
    with pytest.raises(rpt.ConfigError, match=r"metrics.matching: 'best' is not one of greedy, hungarian"):
        options["metrics.matching"] = "best"
    with pytest.raises(rpt.ConfigError, match=r"None is not a value"):
        options["track.enabled"] = None
    with pytest.raises(TypeError, match=r"options: expected None, a dict or an rpt.Options"):
        rpt.Triangulator([], [], options=3)


def test_option_messages_equal_the_clis(tmp_path):
    done = run_cli("config", "--dump", "--set", "filter.min_match_score=1.5", check=False)
    assert done.returncode == 2
    with pytest.raises(rpt.ConfigError) as error:
        rpt.Options({"filter.min_match_score": "1.5"})
    assert done.stderr.strip().endswith(str(error.value).removeprefix("Options"))
    config = tmp_path / "config.json"
    config.write_text('{"filter": {"min_match_score": 2}}')
    done = run_cli("config", "--dump", "--config", config, check=False)
    with pytest.raises(rpt.ConfigError) as error:
        rpt.Options.from_json(config)
    assert str(error.value) in done.stderr


def test_dataset_errors_are_the_clis(tmp_path):
    done = run_cli("eval", "--dataset", "shelf", "--root", tmp_path / "missing", check=False)
    with pytest.raises(FileNotFoundError) as error:
        rpt.datasets.open("shelf", str(tmp_path / "missing"))
    assert isinstance(error.value, rpt.InputError)
    assert str(error.value) in done.stderr
    done = run_cli("eval", "--dataset", "shelve", "--root", "x", check=False)
    with pytest.raises(rpt.ConfigError) as error:
        rpt.datasets.open("shelve", "x")
    assert str(error.value).startswith("unknown dataset 'shelve' (known: shelf, ")
    assert str(error.value) in done.stderr
    done = run_cli("eval", "--dataset", "synthetic", "--param", "people=0", check=False)
    with pytest.raises(rpt.ConfigError) as error:
        rpt.datasets.open("synthetic", people=0)
    # The CLI's words, but naming the keyword argument instead of --param.
    assert str(error.value).startswith("datasets: keyword argument people=0: ")
    assert str(error.value).replace("datasets: keyword argument ", "--param ") in done.stderr
    with pytest.raises(rpt.ConfigError, match=r"synthetic.noise: 'loud' is not one of perfect, clean, realistic, hard, none"):
        rpt.synthetic.scene(noise="loud")
    # Labels without detections: the arguments to give are the module's, not the CLI's flags.
    labels = tmp_path / "labels.json"
    run_cli("convert", "--dataset", "synthetic", "--param", "frames=2", "--labels-out", labels)
    with pytest.raises(rpt.InputError, match=r"has no 2D detections: pass detections_file=FILE or simulate=True$"):
        rpt.datasets.open_labels(labels)
    done = run_cli("eval", "--labels", labels, check=False)
    assert "has no 2D detections: pass --detections FILE or --simulate" in done.stderr


def test_a_camera_given_twice_is_refused(rig):
    scene, _ = rig
    with pytest.raises(rpt.InputError, match=r"^cameras: camera name 'cam0' appears twice \(cameras\[0\] and cameras\[2\]\)$"):
        rpt.Triangulator([scene.cameras[0], scene.cameras[1], scene.cameras[0]], scene.joint_names)


def test_a_dataset_is_read_once():
    dataset = rpt.datasets.open("synthetic", frames=3)
    assert repr(dataset) == "Dataset(1 sequence(s): 'synthetic')"
    assert sum(1 for _ in dataset) == 3
    assert repr(dataset) == "Dataset(1 sequence(s): 'synthetic'; frames pulled)"
    with pytest.raises(ValueError, match=r"^Dataset: its frames were already pulled"):
        for _ in dataset:  # a second loop silently found no frames
            pass
    with pytest.raises(ValueError, match=r"^Dataset.load: frames were already pulled"):
        dataset.load()


def test_export_of_process_results_is_a_type_error(rig, tmp_path):
    scene, triangulator = rig
    live = [triangulator.process(frame.views, frame.timestamp) for frame in scene]
    with pytest.raises(TypeError, match=r"^export.write: predictions must be rpt.Predictions .* got tuple \(the "
                                        r"\(persons, track_ids\) of process\(\) calls"):
        rpt.export.write(tmp_path, live)
    with pytest.raises(TypeError, match=r"got dict"):
        rpt.export.write(tmp_path, {})


def test_trc_of_untracked_persons_warns(rig, tmp_path):
    scene, _ = rig
    predictions = rpt.Triangulator.for_sequence(scene).process_sequence([frame.views for frame in scene])  # no times
    with pytest.warns(rpt.InputWarning, match=r"trc: no TRC file written: no person was tracked .*give "
                                              r"process_sequence the frames' timestamps"):
        rpt.export.write(tmp_path, predictions, "trc")


def test_paths_and_numpy_lists_as_the_other_calls_take_them(tmp_path):
    labels, detections = tmp_path / "labels.json", tmp_path / "detections.json"
    run_cli("convert", "--dataset", "synthetic", "--param", "frames=2", "--labels-out", labels,
            "--detections-out", detections)
    assert len(rpt.datasets.open_labels(labels, detections_file=detections).load()[0]) == 2  # pathlib.Path
    assert len(rpt.datasets.open_cameras(labels, detections).load()[0]) == 2
    if (SHARED_DATA / "mvor").is_dir():
        by_list = rpt.datasets.open("mvor", SHARED_DATA / "mvor", days=[1, 2]).sequences
        by_array = rpt.datasets.open("mvor", SHARED_DATA / "mvor", days=np.array([1, 2])).sequences
        assert [s.name for s in by_array] == [s.name for s in by_list]


def test_ctrl_c_ends_process_sequence():
    # Python's signal handlers ran only after the whole sequence (Jupyter's interrupt waited).
    scene = rpt.synthetic.scene(cameras=4, people=3, frames=12000, noise="clean")
    triangulator = rpt.Triangulator.for_sequence(scene)
    start = time.perf_counter()
    triangulator.process_sequence(scene)
    whole = time.perf_counter() - start

    def interrupt(*_):
        raise KeyboardInterrupt

    previous = signal.signal(signal.SIGALRM, interrupt)
    try:
        triangulator.reset()
        start = time.perf_counter()
        signal.setitimer(signal.ITIMER_REAL, 0.01)
        with pytest.raises(KeyboardInterrupt):
            triangulator.process_sequence(scene)
        interrupted = time.perf_counter() - start
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    assert interrupted < whole / 4, (interrupted, whole)
    triangulator.reset()
    assert len(triangulator.process_sequence(scene)) == 12000, "usable after the interrupt"


def test_camera_errors():
    with pytest.raises(FileNotFoundError, match=r"nothing.yml: file not found"):
        rpt.cameras.load("/nonexistent/nothing.yml")
    with pytest.raises(ValueError, match=r"K: shape \(2, 2\), expected \(3, 3\)"):
        rpt.Camera(width=10, height=10, K=np.eye(2))
    with pytest.raises(ValueError, match=r"K: contains NaN"):
        rpt.Camera(width=10, height=10, K=np.full((3, 3), np.nan))
    with pytest.raises(rpt.InputError, match=r"^camera 'a' \(lens none\): image size must be positive, got 0x10$"):
        rpt.Camera(name="a", width=0, height=10, K=np.eye(3))
    # A ragged list is this argument's ValueError (it was an internal error).
    with pytest.raises(ValueError, match=r"^K: not an array of numbers \("):
        rpt.Camera(width=10, height=10, K=[[1, 0, 0], [0, 1, 0], [0, 0]])
    # Coefficients the model would ignore are refused, not dropped.
    K = [[1000, 0, 960], [0, 1000, 540], [0, 0, 1]]
    with pytest.raises(ValueError, match=r"dist: non-zero coefficients, but model='none' uses none"):
        rpt.Camera(width=1920, height=1080, K=K, dist=[0.3, 0.1, 0, 0, 0.05])
    with pytest.raises(ValueError, match=r"dist: coefficient 5 is 0.05, but model='fisheye' uses the first 4"):
        rpt.Camera(width=1920, height=1080, K=K, dist=[0.3, 0.1, 0, 0, 0.05], model="fisheye")
    assert rpt.Camera(width=1920, height=1080, K=K, dist=[0.3, 0.1, 0, 0, 0.05], model="opencv").model == "opencv"
    # Three coefficients were padded with zeros: the third, meant as k3, became the tangential p1.
    with pytest.raises(ValueError, match=r"dist: 3 coefficients; model='opencv' takes k1 k2 p1 p2 \[k3\] \(4 or 5\)"):
        rpt.Camera(width=1920, height=1080, K=K, dist=[0.3, 0.1, 0.05], model="opencv")
    with pytest.raises(ValueError, match=r"dist: 2 coefficients; model='fisheye' takes k1 k2 k3 k4"):
        rpt.Camera(width=1920, height=1080, K=K, dist=[0.3, 0.1], model="fisheye")
    assert rpt.Camera(width=1920, height=1080, K=K, dist=[0.3, 0.1, 0, 0], model="opencv").model == "opencv"
    with pytest.raises(rpt.ConfigError, match=r"cameras.load: format: 'yaml' is not one of auto, json, opencv"):
        rpt.cameras.load("x.yml", format="yaml")
    camera = rpt.Camera(width=10, height=10, K=np.eye(3))
    with pytest.raises(ValueError, match=r"points: shape \(2, 2\), expected \(n, 3\)"):
        camera.project(np.zeros((2, 2)))


def test_metrics_errors(scene, predictions):
    with pytest.raises(rpt.ConfigError, match=r"metrics.evaluate: metrics.min_gt_score: '2' is not a number in \[0, 1\]"):
        rpt.metrics.evaluate(scene, predictions, min_gt_score=2)
    with pytest.raises(ValueError, match=r"with arrays, give gt_joints= and joint_names="):
        rpt.metrics.evaluate([np.zeros((1, 17, 4))], [np.zeros((1, 17, 4))])
    gt = np.zeros((1, 17, 4))
    gt[0, :, 3] = 1
    gt[0, 2, 0] = np.nan
    with pytest.raises(ValueError, match=r"gt\[0\]: person 0, joint 2: NaN or infinity \(a missing joint has score 0"):
        rpt.metrics.evaluate([gt], [np.zeros((1, 17, 4))], gt_joints=scene.joint_names, joint_names=scene.joint_names)
    # A missing joint (score 0) may be NaN, as rpt's NPZ and HDF5 exports write it: the same
    # numbers as with zeros there.
    gt[0, 2] = [np.nan, np.nan, np.nan, 0]
    pred = gt.copy()
    pred[0, :, 0] += 0.05
    pred[0, 4] = [np.nan, np.nan, np.nan, 0]
    zeros = lambda a: np.where(np.isnan(a), 0.0, a)
    with_nan = rpt.metrics.evaluate([gt], [pred], gt_joints=scene.joint_names, joint_names=scene.joint_names)
    with_zeros = rpt.metrics.evaluate([zeros(gt)], [zeros(pred)], gt_joints=scene.joint_names, joint_names=scene.joint_names)
    assert with_nan["mpjpe_mm"] == with_zeros["mpjpe_mm"]
    assert with_nan["pcp"] == with_zeros["pcp"]
    # Wrong types are TypeErrors naming the argument (pybind11 said "Unable to cast Python instance").
    with pytest.raises(TypeError, match=r"^metrics.evaluate: predictions must be the rpt.Predictions of process_sequence .*got list$"):
        rpt.metrics.evaluate(scene, [])
    with pytest.raises(TypeError, match=r"^metrics.evaluate: gt must be an rpt.datasets.Sequence, a list of them, or per frame an array, got Predictions$"):
        rpt.metrics.evaluate(predictions, scene)
    with pytest.raises(TypeError, match=r"^metrics.evaluate: predictions must be a list of rpt.Predictions"):
        rpt.metrics.evaluate([scene], [predictions[0]])


def test_dataset_params_take_lists_as_the_cli_takes_comma_lists():
    # days=[1, 2] was sent as the text "[1, 2]": "mvor.days: '[1' is not a day 1-4".
    root = SHARED_DATA / "mvor"
    if not (root / "camma_mvor_2018.json").exists():
        pytest.skip(f"{root} is absent")
    frames = lambda dataset: sum(len(s) for s in dataset.load())
    by_text = frames(rpt.datasets.open("mvor", str(root), days="1,2"))
    assert by_text > 0
    assert frames(rpt.datasets.open("mvor", str(root), days=[1, 2])) == by_text
    assert frames(rpt.datasets.open("mvor", str(root), days=(1, 2))) == by_text
    assert frames(rpt.datasets.open("mvor", str(root), days=[1])) < by_text


def test_export_errors(predictions, tmp_path):
    with pytest.raises(rpt.ConfigError, match=r"^export.write: formats json,xls: 'xls' is not one of json, csv, trc, npz, h5"):
        rpt.export.write(tmp_path, predictions, "json,xls")
    with pytest.raises(rpt.ConfigError, match=r"^export.write: formats '': no format given"):
        rpt.export.write(tmp_path, predictions, "")
    with pytest.raises(rpt.ConfigError, match=r"trc_axes: 'x-up' is not z-up \| y-up"):
        rpt.export.write(tmp_path, predictions, "trc", trc_axes="x-up")


def test_one_array_for_all_views(rig):
    scene, _ = rig
    views = good_views(rig)
    assert all(v.shape == (1, JOINTS, 3) for v in views)
    a = rpt.Triangulator(scene.cameras, scene.joint_names)
    b = rpt.Triangulator(scene.cameras, scene.joint_names)
    persons_list, _ = a.process(views, 0.0)
    persons_array, _ = b.process(np.stack(views), 0.0)
    assert np.array_equal(persons_list, persons_array)
    with pytest.raises(ValueError, match=r"views: shape \(2, 1, 17, 3\), expected \(3, n, 17, 3\)"):
        b.process(np.stack(views[:2]))


def test_unknown_joint_names_are_refused_as_in_files(rig):
    # 'left_ear' for 'ear_left' was accepted and carried along unused: the derived head moved 8 cm.
    scene, _ = rig
    names = [n.replace("ear_left", "left_ear") for n in scene.joint_names]
    with pytest.raises(rpt.InputError, match=r"rpt.Triangulator: joint_names: unknown joint name 'left_ear' "
                                             r"\(did you mean 'ear_left'\?\)"):
        rpt.Triangulator(scene.cameras, names)
    gt = [np.zeros((0, 17, 4))]
    with pytest.raises(rpt.InputError, match=r"metrics.evaluate: joint_names: unknown joint name 'left_ear'"):
        rpt.metrics.evaluate(gt, [np.zeros((0, 17, 4))], gt_joints=scene.joint_names, joint_names=names)


def test_an_output_that_cannot_be_written_is_an_os_error(rig, tmp_path):
    scene, triangulator = rig
    predictions = rpt.Triangulator.for_sequence(scene).process_sequence(scene)
    (tmp_path / "file").write_text("x")
    # A file where the output folder goes: an OSError (it was a ValueError), still an rpt.InputError.
    with pytest.raises(rpt.OutputError, match=r"file/out: cannot create the folder \(Not a directory\)$") as raised:
        rpt.export.write(tmp_path / "file" / "out", predictions)
    assert isinstance(raised.value, OSError) and isinstance(raised.value, rpt.InputError)
    assert not isinstance(raised.value, FileNotFoundError)
