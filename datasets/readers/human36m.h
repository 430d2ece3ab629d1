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
#include <memory>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "datasets/dataset_params.h"
#include "datasets/frame_source.h"
#include "datasets/sequence.h"

namespace rpt {

// The lens model of the stored Human3.6M coefficients (Human3.6M and H3WB readers).
enum class H36mLens { kH36m, kOpenCV, kNone };
template <>
struct EnumNames<H36mLens> {
  static constexpr std::array<std::pair<H36mLens, std::string_view>, 3> values = {
      {{H36mLens::kH36m, "h36m"}, {H36mLens::kOpenCV, "opencv"}, {H36mLens::kNone, "none"}}};
};
DistortionModel ToDistortionModel(H36mLens lens);

enum class H36mLabels { kAuto, kAnnot, kNpy };
template <>
struct EnumNames<H36mLabels> {
  static constexpr std::array<std::pair<H36mLabels, std::string_view>, 3> values = {
      {{H36mLabels::kAuto, "auto"}, {H36mLabels::kAnnot, "annot"}, {H36mLabels::kNpy, "npy"}}};
};

enum class H36mNoseProxy { kHead, kNeckNose };
template <>
struct EnumNames<H36mNoseProxy> {
  static constexpr std::array<std::pair<H36mNoseProxy, std::string_view>, 2> values = {
      {{H36mNoseProxy::kHead, "head"}, {H36mNoseProxy::kNeckNose, "neck_nose"}}};
};

struct Human36mParams {
  ParamList subjects = {"S9", "S11"};
  ParamList actions;  // empty = all
  ParamList exclude;  // "<subject>/<action>"
  H36mLabels labels = H36mLabels::kAuto;
  std::string labels_file = "auto";
  std::string cameras_file = "auto";
  H36mLens distortion = H36mLens::kH36m;
  H36mNoseProxy nose_proxy = H36mNoseProxy::kHead;
  int every = 1;
  int max_frames = 0;

  // "" or "human36m.subjects: no subject given" (core/options_check.h).
  std::string Check() const;
};

template <class Visitor, OptionsOf<Human36mParams> Self>
void VisitFields(Visitor& v, Self& o) {
  v("subjects", o.subjects, OptionSpec{.help = "subjects"});
  v("actions", o.actions,
    OptionSpec{.help = "actions ('Directions' = all its sub-actions, 'Directions-1' = one); empty = all"});
  v("exclude", o.exclude, OptionSpec{.help = "<subject>/<action> to skip, e.g. S9/Greeting-2"});
  v("labels", o.labels,
    OptionSpec{.help = "annot = processed/*/annot.h5, npy = learnable-triangulation labels, auto = whichever is there"});
  v("labels_file", o.labels_file, OptionSpec{.help = "labels npy path (relative to root); auto = extra/ or root"});
  v("cameras_file", o.cameras_file,
    OptionSpec{.help = "metadata.xml | cameras.pkl | labels npy path, or 'labels'; auto = metadata.xml, cameras.pkl, "
                       "annotation_body3d/cameras.pkl, else the labels npy"});
  v("distortion", o.distortion, OptionSpec{.help = "lens model for the stored coefficients"});
  v("nose_proxy", o.nose_proxy, OptionSpec{.help = "GT joint copied to 'nose': head (raw 15) or neck_nose (raw 14)"});
  v("every", o.every,
    OptionSpec{.help = "keep every n-th labelled frame of each sequence (annot.h5 already holds every 64th frame of "
                       "S9/S11)",
               .min = 1});
  v("max_frames", o.max_frames, OptionSpec{.help = "at most this many frames per sequence (0 = all)", .min = 0});
}

DatasetInfo Human36mInfo();
// One source per subject and action: cameras and the labels (each annot.h5, or the labels npy once)
// are read when it opens, each frame converted when it is pulled. The frames are the ground truth:
// without it (DatasetRequest::ground_truth false) a ConfigError.
std::vector<std::unique_ptr<FrameSource>> OpenHuman36m(const DatasetRequest& request);

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
