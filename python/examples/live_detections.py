"""Triangulating live: per-frame numpy detections (as a 2D detector such as mmpose hands them over)
fed to rpt.Triangulator.process one frame at a time (docs/python.md). The "detector" here projects
a generated scene's people into the cameras and adds pixel noise."""
import time

import numpy as np
import rpt

scene = rpt.synthetic.scene(cameras=4, people=3, frames=100, noise="perfect")
cameras, joints = scene.cameras, scene.joint_names
triangulator = rpt.Triangulator(cameras, joints, {"room_check": {"size_m": [8, 8, 3]}})
rng = np.random.default_rng(0)


def detect(frame, camera):
    """One camera's detections: (persons, joints, 3) float32 of u_px, v_px, score."""
    gt = frame.gt
    uv, in_front = camera.project(np.ascontiguousarray(gt[..., :3]).reshape(-1, 3))
    uv = uv.reshape(len(gt), len(joints), 2) + rng.normal(0, 2.0, (len(gt), len(joints), 2))
    score = np.where(in_front.reshape(len(gt), len(joints)), 0.9, 0.0)
    return np.concatenate([uv, score[..., None]], axis=2).astype(np.float32)


start = time.perf_counter()
for frame in scene:  # in a real loop: frames from the cameras, detections from the 2D network
    views = [detect(frame, camera) for camera in cameras]
    persons, track_ids = triangulator.process(views, timestamp=frame.timestamp)
    if int(frame.id[-6:]) % 25 == 0:
        heights = persons[:, triangulator.output_joint_names.index("nose"), 2]
        print(f"t={frame.timestamp:5.2f} s: tracks {track_ids.tolist()}, nose heights {np.round(heights, 2).tolist()} m")
print(f"{len(scene)} frames in {time.perf_counter() - start:.2f} s, triangulator {triangulator.stats['total_us']:.0f} us "
      "on the last frame")
