"""rpt.Camera and rpt.cameras: projection with hand-computed pixels, undistortion, every calibration
format the CLI reads (written here and read back, the real fixtures when ../shared/data exists)."""
import copy
import pickle

import numpy as np
import pytest

import rpt

from conftest import SHARED_DATA, run_cli

K = np.array([[1000.0, 0, 500], [0, 1000, 400], [0, 0, 1]])


def test_pinhole_projection_by_hand():
    camera = rpt.Camera(name="c", width=1000, height=800, K=K)
    uv, in_front = camera.project(np.array([[0.1, 0.2, 2.0], [0.0, 0.0, -1.0]]))
    assert uv[0].tolist() == [550.0, 500.0]  # 1000 * 0.1 / 2 + 500, 1000 * 0.2 / 2 + 400
    assert in_front.tolist() == [True, False]
    single, _ = camera.project(np.array([0.1, 0.2, 2.0]))
    assert single.shape == (1, 2)


def test_pose_and_centre():
    # camera 3 m behind the origin along -y, looking along +y: R maps world y to camera z
    R = np.array([[1.0, 0, 0], [0, 0, -1], [0, 1, 0]])
    camera = rpt.Camera(width=1000, height=800, K=K, R=R, center=[0, -3, 0])
    np.testing.assert_allclose(camera.t, [0, 0, 3])
    np.testing.assert_allclose(camera.center, [0, -3, 0])
    uv, in_front = camera.project([[0.3, 0.0, 0.0]])
    np.testing.assert_allclose(uv, [[600.0, 400.0]])  # 1000 * 0.3 / 3 + 500
    assert in_front[0]


def test_undistort_points_inverts_the_lens():
    camera = rpt.Camera(width=1000, height=800, K=K, dist=[-0.2, 0.05, 0.001, -0.002, 0.0], model="opencv")
    pinhole = rpt.Camera(width=1000, height=800, K=K)
    points = np.array([[0.3, -0.2, 2.0], [-0.5, 0.4, 3.0], [0.0, 0.0, 1.0]])
    distorted, _ = camera.project(points)
    undistorted = camera.undistort_points(distorted)
    expected, _ = pinhole.project(points)
    np.testing.assert_allclose(undistorted, expected, atol=1e-9)
    assert not np.allclose(distorted[:2], expected[:2], atol=1)  # the lens does move them


def test_to_json():
    camera = rpt.Camera(name="cam0", width=1000, height=800, K=K, center=[1, 2, 3])
    record = camera.to_json()
    assert record["name"] == "cam0"
    assert record["K"] == K.tolist()
    assert np.ravel(record["T"]).tolist() == [1.0, 2.0, 3.0]


@pytest.mark.parametrize("name,format_name", [("cameras.json", "json"), ("calib.yml", "opencv"),
                                              ("intri.yml", "easymocap"), ("calib.toml", "toml")])
def test_written_formats_read_back(tmp_path, name, format_name):
    scene = rpt.synthetic.scene(cameras=3, frames=1, distortion="opencv")
    path = tmp_path / name
    rpt.cameras.save(path, scene.cameras)
    cameras = rpt.cameras.load(tmp_path if format_name == "easymocap" else path)
    assert [c.name for c in cameras] == [c.name for c in scene.cameras]
    for a, b in zip(cameras, scene.cameras):
        np.testing.assert_allclose(a.K, b.K, atol=1e-9)
        np.testing.assert_allclose(a.R, b.R, atol=1e-9)
        np.testing.assert_allclose(a.t, b.t, atol=1e-9)
        np.testing.assert_allclose(a.dist, b.dist, atol=1e-12)
        assert (a.width, a.height, a.model) == (b.width, b.height, b.model)
    # the CLI reads the same file to the same cameras
    shown = run_cli("cameras", "show", tmp_path if format_name == "easymocap" else path).stdout
    assert all(c.name in shown for c in cameras)


def real_calibrations():
    """(format, path) of the real fixtures: VoxelPose, Panoptic, 4D-Association, COLMAP."""
    candidates = [("voxelpose", "shelf/calibration_shelf.json"), ("voxelpose", "campus/calibration_campus.json"),
                  ("4da", "shelf/4d_association/calibration.json")]
    found = [(f, SHARED_DATA / p) for f, p in candidates if (SHARED_DATA / p).exists()]
    found += [("panoptic", p) for p in sorted(SHARED_DATA.glob("**/calibration_1*.json"))[:1]]
    return found


@pytest.mark.parametrize("format_name,path", real_calibrations() or [pytest.param(None, None, marks=pytest.mark.skip(
    reason="../shared/data is absent"))])
def test_real_calibrations_read_like_the_cli(format_name, path):
    cameras = rpt.cameras.load(path, format=format_name)
    assert len(cameras) >= 3
    shown = run_cli("cameras", "show", path, "--format", format_name).stdout
    for camera in cameras:
        assert camera.name in shown
        assert np.all(np.isfinite(camera.K))


def test_colmap_text_model(tmp_path):
    (tmp_path / "cameras.txt").write_text("1 PINHOLE 640 480 500 500 320 240\n")
    (tmp_path / "images.txt").write_text("1 1 0 0 0 0 0 5 1 a.jpg\n\n2 1 0 0 0 1 0 5 1 b.jpg\n\n")
    cameras = rpt.cameras.load(tmp_path, format="colmap")
    assert len(cameras) == 2
    np.testing.assert_allclose(cameras[0].t, [0, 0, 5])
    uv, in_front = cameras[1].project([[0.0, 0.0, 0.0]])
    np.testing.assert_allclose(uv, [[420.0, 240.0]])  # 500 * 1 / 5 + 320
    assert in_front[0]


def test_matrices_are_read_only_and_cameras_copy():
    camera = rpt.Camera(name="c", width=1000, height=800, K=[[500, 0, 500], [0, 500, 400], [0, 0, 1]])
    for name in ("K", "R", "t", "center", "dist"):
        array = getattr(camera, name)
        assert not array.flags.writeable, name
        with pytest.raises(ValueError, match="read-only"):
            array[0] = 1  # was a writeable copy: the write was lost unseen
    twin = copy.deepcopy(camera)
    assert repr(twin) == repr(camera) and np.array_equal(twin.K, camera.K) and twin is not camera
    assert copy.copy(camera).name == "c"


def test_cameras_pickle_for_worker_processes():
    # multiprocessing hands cameras to workers by pickle (it raised 'cannot pickle'); the same
    # camera comes back, through the constructor's checks.
    for camera in rpt.synthetic.scene(cameras=2, frames=1, distortion="fisheye").cameras:
        twin = pickle.loads(pickle.dumps(camera))
        assert repr(twin) == repr(camera)
        for name in ("K", "R", "t", "dist"):
            assert np.array_equal(getattr(twin, name), getattr(camera, name)), name
    state = list(camera.__getstate__())
    assert state[7] == "fisheye"
    state[7] = "barrel"  # a tampered pickle: the constructor's error
    with pytest.raises(rpt.ConfigError, match=r"barrel"):
        rpt.Camera.__new__(rpt.Camera).__setstate__(tuple(state))
    with pytest.raises(rpt.InputError, match=r"^Camera \(unpickled\): expected 8 values, got 2$"):
        rpt.Camera.__new__(rpt.Camera).__setstate__((1, 2))


def test_load_warns_as_cameras_show(tmp_path):
    # A rig in millimetres read as metres: the CLI warned, rpt.cameras.load said nothing and every
    # frame then had 0 persons. Its warnings are now rpt.InputWarning, the CLI's lines.
    (tmp_path / "cameras.txt").write_text("1 PINHOLE 640 480 500 500 320 240\n")
    (tmp_path / "images.txt").write_text("1 1 0 0 0 0 0 5000 1 a.jpg\n\n2 1 0 0 0 1 0 5000 1 b.jpg\n\n")
    with pytest.warns(rpt.InputWarning, match=r"2 cameras more than 1 km from the origin") as caught:
        cameras = rpt.cameras.load(tmp_path, format="colmap")
    assert len(cameras) == 2
    assert issubclass(rpt.InputWarning, UserWarning)
    shown = run_cli("cameras", "show", tmp_path, "--format", "colmap").stderr
    for warning in caught:
        assert "warning: " + str(warning.message) in shown
        assert warning.filename == __file__, "the warning points at the caller's line, not sys:1"
