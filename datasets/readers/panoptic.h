// SPDX-License-Identifier: MIT
// CMU Panoptic Studio (Joo et al.), read from the panoptic-toolbox data folder:
//
//   <root>/<seq>/calibration_<seq>.json                       all cameras of the dome
//   <root>/<seq>/hdPose3d_stage1_coco19/body3DScene_%08d.json  3D bodies per HD frame
//
// File conventions: world in centimetres with y pointing DOWN (gravity), floor near y = 0;
// cameras "R" world->camera (an R within 1e-3 of a rotation is replaced by the nearest rotation
// and counted in Sequence::warnings, farther is an error) and "t" translation in cm
// (x_cam = R X + t), "K" 3x3, "distCoef" [k1, k2, p1, p2, k3] of the OpenCV radial-tangential
// model, "resolution" [w, h]. Bodies:
// "joints19" = 19 x (x, y, z, c), c = confidence, a missing joint is (0, 0, 0, -1).
//
// rpt conventions: metres, z up. A point maps as (x, y, z) -> (x, z, -y) / 100 (the axis
// permutation VoxelPose uses, a proper rotation A, then cm -> m); a camera becomes
// R' = R A^T, t' = t / 100, so every projection (distortion included) is unchanged.
//
// GT joints (PanopticJoints()): the 19 coco19 joints renamed; score = the file's confidence c
// clamped to [0, 1] (missing joints get 0; a joint counts as visible when > 0.1, VoxelPose's
// rule). As in VoxelPose, a body whose body_center (root) has c <= 0.1 is dropped. Track id =
// the body "id" (per sequence; may change for the same person).
// Frame ids "panoptic_<seq>_<file number, 6 digits>" (the file number is the HD frame index of
// hdImgs/00_XX/00_XX_%08d.jpg); timestamp = frame / 29.97 (HD rate).
// Room: VoxelPose's Panoptic space (configs/panoptic/.../prn64_cpn80x80x20_960x512_cam5.yaml),
// centre (0, -0.5, 0.8) m and size (8, 8, 2) m in the converted frame.
#pragma once

#include <Eigen/Core>
#include <array>
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

// neck, nose, body_center, shoulder_left, elbow_left, wrist_left, hip_left, knee_left,
// ankle_left, shoulder_right, elbow_right, wrist_right, hip_right, knee_right, ankle_right,
// eye_left, ear_left, eye_right, ear_right.
const JointNames& PanopticJoints();

// Panoptic world point (cm, y down) -> rpt world (m, z up).
Eigen::Vector3d PanopticPointToWorld(const Eigen::Vector3d& point_cm);

// A Panoptic camera (R world->camera, t in cm, both in the Panoptic world) in rpt's world.
Camera ConvertPanopticCamera(const std::string& name, int width, int height, const Eigen::Matrix3d& K,
                             const std::array<double, 5>& dist_coef, const Eigen::Matrix3d& R_panoptic,
                             const Eigen::Vector3d& t_cm);

// The cameras of a calibration_<seq>.json in rpt's world (ConvertPanopticCamera), in the order
// asked for: `selection` is a comma-separated list of names, "hd" (every HD camera) or "" (every
// camera of the file, in file order). An R within 1e-3 of a rotation is replaced by the nearest
// rotation and counted in `warnings`. Throws InputError naming the file and the JSON pointer, or
// an unknown camera (listing the HD cameras).
std::vector<Camera> ReadPanopticCameras(const std::filesystem::path& path, const std::string& selection,
                                        InputWarnings* warnings);

// The VoxelPose validation sequences and cameras (lib/dataset/panoptic.py).
inline constexpr const char* kPanopticDefaultSequences = "160906_pizza1,160422_haggling1,160906_ian5,160906_band4";
inline constexpr const char* kPanopticDefaultCameras = "00_03,00_06,00_12,00_13,00_23";

// Params:
//   sequences   list of sequence folders under the root (default: the VoxelPose validation set).
//   cameras     list of camera names (default: VoxelPose's 5 HD cameras); "hd" = all 31 HD cameras.
//   every       take the annotation files whose index in the sorted file list is a multiple of
//               this (default 12, VoxelPose's validation interval; 1 = every frame).
//   max_frames  keep at most this many frames per sequence after sampling (0 = all).
//   skip_empty  true (default, as VoxelPose): drop frames without any GT person (empty "bodies",
//               or all roots invisible). false: keep them as frames with no persons, which
//               makes every reconstruction there a false positive.
// One sequence per sequence folder ("panoptic/<seq>"). Throws ConfigError for malformed params
// and InputError for a missing sequence folder, an unknown camera (listing the available ones)
// and missing/malformed files (naming the file and the JSON pointer).
struct PanopticParams {
  ParamList sequences = SplitList(kPanopticDefaultSequences);
  std::string cameras = kPanopticDefaultCameras;  // camera names, or "hd"
  int every = 12;
  int max_frames = 0;
  bool skip_empty = true;

  // "" or "panoptic.sequences: no sequences selected" (core/options_check.h).
  std::string Check() const;
};

template <class Visitor, OptionsOf<PanopticParams> Self>
void VisitFields(Visitor& v, Self& o) {
  v("sequences", o.sequences, OptionSpec{.help = "sequence folders under the root (default: VoxelPose validation)"});
  v("cameras", o.cameras, OptionSpec{.help = "comma-separated camera names, or hd = all 31 HD cameras"});
  v("every", o.every,
    OptionSpec{.help = "take annotation files whose sorted-list index is a multiple of this (VoxelPose: 12)", .min = 1});
  v("max_frames", o.max_frames, OptionSpec{.help = "at most this many frames per sequence (0 = all)", .min = 0});
  v("skip_empty", o.skip_empty, OptionSpec{.help = "drop frames without GT persons (as VoxelPose); false keeps them"});
}

DatasetInfo PanopticInfo();
// One source per sequence: cameras and the file list are read when it opens (all errors about
// folders, calibrations and cameras surface here), one annotation file per frame pulled. The
// frames are the ground-truth files: without the ground truth (DatasetRequest::ground_truth
// false) there is nothing to read, a ConfigError.
std::vector<std::unique_ptr<FrameSource>> OpenPanoptic(const DatasetRequest& request);

}  // namespace rpt
