// SPDX-License-Identifier: MIT
// Human3.6M reader (dataset name "human36m"): the 4 calibrated cameras and the world-frame 3D
// ground truth of one subject per Sequence, one Sequence per subject and action.
//
// Inputs (see docs/datasets/human36m_h3wb_egohumans.md):
//   cameras  metadata.xml (the <w0> block: R = Rx(rx) Ry(ry) Rz(rz) world->camera, centre in mm)
//            or mmpose cameras.pkl (R camera->world, T = centre in m)
//            or the learnable-triangulation labels npy (R world->camera, t = -R C in mm);
//   3D       h36m-fetch processed/<S>/<Action>-<sub>/annot.h5 (pose/3d: camera-frame mm, per camera)
//            or learnable-triangulation human36m-multiview-labels-GTbboxes.npy (world mm).
// Output: metres, H36M world frame (z up), cameras named by their ids ("54138969", ...).
//
// GT joints (Human36mJoints()): pelvis, hip_right, knee_right, ankle_right, hip_left, knee_left,
// ankle_left, spine, thorax, neck_nose (raw 14), head (raw 15), shoulder_left, elbow_left,
// wrist_left, shoulder_right, elbow_right, wrist_right, and "nose" = a copy of head (default) or
// neck_nose (param nose_proxy) for the paper's 13-joint evaluation.
//
// Frame ids: "human36m_<subject>_<Action>-<sub>_<frame>" with the 0-based video frame index in 6
// digits, e.g. "human36m_S9_Directions-1_000064" (annot.h5 `frame` - 1 = labels `frame_idx`).
// Sequence names: "human36m/<subject>/<Action>-<sub>". Timestamps: frame / 50 s.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "datasets/dataset_request.h"
#include "datasets/sequence.h"

namespace rpt {

DatasetInfo Human36mInfo();
std::vector<Sequence> ReadHuman36m(const DatasetRequest& request);

// The four cameras of `subject` ("S1".."S11") in camera-id order, from metadata.xml (*.xml),
// mmpose cameras.pkl (*.pkl) or the learnable-triangulation labels (*.npy). Distortion
// coefficients are stored as (k1, k2, p1, p2, k3) with `model` (kNone zeroes them). Stored
// rotation matrices (pkl, npy) within 1e-3 of a rotation are replaced by the nearest rotation and
// counted in `warnings` when given (AcceptRotation, datasets/input_warnings.h).
// Throws InputError naming the file and the place on missing/malformed input, a matrix that is
// not a rotation, or an unknown subject.
std::vector<Camera> ReadHuman36mCameras(const std::filesystem::path& path, const std::string& subject,
                                        DistortionModel model = DistortionModel::kH36M,
                                        InputWarnings* warnings = nullptr);

// "54138969", "55011271", "58860488", "60457274" (metadata.xml camera order 1..4).
const std::vector<std::string>& Human36mCameraIds();

// The 18 GT joint names listed above (17 H36M joints + "nose").
const JointNames& Human36mJoints();

}  // namespace rpt
