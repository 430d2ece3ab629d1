"""rpt.metrics.evaluate on arrays with hand-computed numbers, and a generated scene end to end."""
import numpy as np
import pytest

import rpt

COCO = ["nose", "eye_left", "eye_right", "ear_left", "ear_right", "shoulder_left", "shoulder_right",
        "elbow_left", "elbow_right", "wrist_left", "wrist_right", "hip_left", "hip_right", "knee_left",
        "knee_right", "ankle_left", "ankle_right"]


def person(offset=(0.0, 0.0, 0.0)):
    """A standing person: joint j at height 1.7 - 0.1 j, spread in x, score 1."""
    joints = np.zeros((len(COCO), 4))
    joints[:, 0] = np.linspace(-0.3, 0.3, len(COCO)) + offset[0]
    joints[:, 1] = offset[1]
    joints[:, 2] = 1.7 - 0.1 * np.arange(len(COCO)) + offset[2]
    joints[:, 3] = 1.0
    return joints[None]


def test_perfect_predictions():
    summary = rpt.metrics.evaluate([person()], [person()], gt_joints=COCO, joint_names=COCO)
    assert summary["mpjpe_mm"] == 0.0
    assert summary["pcp"] == 100.0
    assert summary["recall100"] == 100.0
    assert summary["invalid"] == 0.0
    assert summary["frames"] == 1 and summary["gt_persons"] == 1 and summary["matches"] == 1


def test_one_joint_off_by_13_cm():
    prediction = person()
    prediction[0, COCO.index("nose"), 0] += 0.13
    summary = rpt.metrics.evaluate([person()], [prediction], gt_joints=COCO, joint_names=COCO)
    # the paper's 13 evaluated joints: 130 mm on one of them
    assert summary["mpjpe_mm"] == pytest.approx(10.0, abs=1e-9)


def test_pcp_per_part():
    # The left wrist 1 m off: the left forearm (0.21 m long here, so 107 mm allowed) is the one wrong
    # part of ten; the head part ends at the nose, the torso at the mid-hip.
    prediction = person()
    prediction[0, COCO.index("wrist_left"), 0] += 1.0
    summary = rpt.metrics.evaluate([person()], [prediction], gt_joints=COCO, joint_names=COCO)
    parts = summary["pcp_parts"]
    assert list(parts) == ["upper_arm_left", "upper_arm_right", "lower_arm_left", "lower_arm_right",
                           "upper_leg_left", "upper_leg_right", "lower_leg_left", "lower_leg_right", "torso", "head"]
    assert parts["lower_arm_left"] == 0.0
    assert all(value == 100.0 for name, value in parts.items() if name != "lower_arm_left")
    assert summary["pcp"] == 90.0


def test_missed_person_and_false_positive():
    gt = [person(), person()]
    predictions = [person(), np.zeros((0, len(COCO), 4))]
    summary = rpt.metrics.evaluate(gt, predictions, gt_joints=COCO, joint_names=COCO)
    assert summary["recall500"] == 50.0
    predictions = [np.concatenate([person(), person((3.0, 0.0, 0.0))]), person()]
    summary = rpt.metrics.evaluate(gt, predictions, gt_joints=COCO, joint_names=COCO)
    assert summary["invalid"] == pytest.approx(100 / 3)  # 1 of 3 predictions matches nobody
    assert summary["recall500"] == 100.0
    # ... and it stands 3 m from the only GT person of its frame: far from every GT person
    assert summary["invalid_causes"] == {"duplicate": 0, "near_matched_gt": 0, "near_missed_gt": 0,
                                         "far_from_gt": 1, "no_gt": 0}


def test_options_change_the_metric():
    prediction = person()
    prediction[0, :, 0] += 0.2  # 200 mm everywhere
    gt, pred = [person()], [prediction]
    assert rpt.metrics.evaluate(gt, pred, gt_joints=COCO, joint_names=COCO)["recall100"] == 0.0
    aligned = rpt.metrics.evaluate(gt, pred, gt_joints=COCO, joint_names=COCO, alignment="pelvis")
    assert aligned["mpjpe_mm"] == pytest.approx(0.0, abs=1e-9)


def test_generated_scene_end_to_end(tmp_path):
    scene = rpt.synthetic.scene(cameras=4, people=2, frames=30, noise="realistic", seed=5)
    assert rpt.synthetic.detector_profiles() == ["perfect", "clean", "realistic", "hard"]
    predictions = rpt.Triangulator.for_sequence(scene).process_sequence(scene)
    summary = rpt.metrics.evaluate(scene, predictions)
    assert summary["frames"] == 30 and summary["gt_persons"] == 60
    assert summary["recall500"] >= 90 and summary["mpjpe_mm"] < 80
    perfect = rpt.synthetic.simulate(scene, detector="perfect")
    exact = rpt.metrics.evaluate(perfect, rpt.Triangulator.for_sequence(perfect).process_sequence(perfect))
    assert exact["mpjpe_mm"] < summary["mpjpe_mm"]
    assert exact["recall100"] == 100.0
    written = rpt.export.write(tmp_path, predictions, ["json", "csv"])
    assert all(p.exists() for p in written)
