// SPDX-License-Identifier: MIT
// H3WB reader (dataset name "h3wb"): Human3.6M 3D WholeBody (133 COCO-WholeBody joints) as
// multi-view frames with the four Human3.6M cameras, one Sequence per subject and action.
//
// Two on-disk formats (docs/datasets/human36m_h3wb_egohumans.md):
//  * npz "new format" (utils/prepare_data_h3wb.py, mmpose h3wb_dataset.py): object members
//    train_data[subject][action] = {global_3d (N,133,3) world, frame_id (N,), <camera id> =
//    {camera_3d (N,133,3) mm, pose_2d (N,133,2) px}} and metadata[subject][<camera id>] = {K (1,3,3)
//    divided by 1000, R (1,3,3) world->camera, T (1,1,3) = -R C in metres, Distortion (1,5) =
//    k1 k2 p1 p2 k3}. The GT is global_3d (units: param global_units, default mm), checked against
//    every camera's camera_3d.
//  * json (2Dto3D_*.json, RGBto3D_*.json): sample id -> {keypoints_3d {"0".."132": {x,y,z}} in
//    camera coordinates (mm), optional keypoints_2d, image_path}. Views are assembled into frames:
//    by image_path (subject, "<Action>.<camera id>" folder, frame number) when every sample has a
//    parseable one, otherwise sample ids 4k..4k+3 are the views of one frame in the camera order
//    54138969, 55011271, 58860488, 60457274 (INFERRED from the test-id pattern) and the subject is
//    the one whose cameras (param cameras_file) make the views agree. Either way the views must agree
//    in world coordinates within 1 cm, else InputError.
//
// GT joints: CocoWholeBodyJoints(). Units: metres, Human3.6M world (z up).
// Frame ids: "h3wb_<subject>_<action>_<frame>" (frame = npz frame_id or the image's frame number,
// 6 digits; action sanitised: "Directions 1" -> "Directions-1"); for json without image paths
// "h3wb_<subject>_sample_<first sample id of the frame, 6 digits>" in sequence "h3wb/<subject>/json".
// Times: frame number / 50 s; frames grouped by sample id have unknown times (NaN, fps 0, counted in
// one warning per file: the samples are in no known order).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "datasets/dataset_params.h"
#include "datasets/detections.h"
#include "datasets/frame_source.h"
#include "datasets/readers/human36m.h"
#include "datasets/sequence.h"

namespace rpt {

enum class H3wbFormat { kAuto, kJson, kNpz };
template <>
struct EnumNames<H3wbFormat> {
  static constexpr std::array<std::pair<H3wbFormat, std::string_view>, 3> values = {
      {{H3wbFormat::kAuto, "auto"}, {H3wbFormat::kJson, "json"}, {H3wbFormat::kNpz, "npz"}}};
};
enum class H3wbGlobalUnits { kMm, kM };
template <>
struct EnumNames<H3wbGlobalUnits> {
  static constexpr std::array<std::pair<H3wbGlobalUnits, std::string_view>, 2> values = {
      {{H3wbGlobalUnits::kMm, "mm"}, {H3wbGlobalUnits::kM, "m"}}};
};
enum class H3wbDetections { kNone, kAnnotations };
template <>
struct EnumNames<H3wbDetections> {
  static constexpr std::array<std::pair<H3wbDetections, std::string_view>, 2> values = {
      {{H3wbDetections::kNone, "none"}, {H3wbDetections::kAnnotations, "annotations"}}};
};

struct H3wbParams {
  std::string file = "auto";
  H3wbFormat format = H3wbFormat::kAuto;
  ParamList subjects = {"S8"};
  ParamList actions;  // empty = all
  std::string cameras_file = "auto";
  H36mLens distortion = H36mLens::kH36m;
  H3wbGlobalUnits global_units = H3wbGlobalUnits::kMm;
  int every = 1;
  int max_frames = 0;
  H3wbDetections detections = H3wbDetections::kNone;

  // "" or "h3wb.subjects: no subject given" (core/options_check.h).
  std::string Check() const;
};

template <class Visitor, OptionsOf<H3wbParams> Self>
void VisitFields(Visitor& v, Self& o) {
  v("file", o.file, OptionSpec{.help = "annotation file (relative to root); auto = see layout"});
  v("format", o.format, OptionSpec{.help = "annotation format; auto = by extension"});
  v("subjects", o.subjects, OptionSpec{.help = "subjects"});
  v("actions", o.actions, OptionSpec{.help = "actions (npz keys / image folders); empty = all"});
  v("cameras_file", o.cameras_file,
    OptionSpec{.help = "json only: metadata.xml or cameras.pkl (auto = next to root or the file)"});
  v("distortion", o.distortion, OptionSpec{.help = "lens model for the stored coefficients"});
  v("global_units", o.global_units, OptionSpec{.help = "npz only: units of global_3d (checked against camera_3d)"});
  v("every", o.every, OptionSpec{.help = "keep every n-th frame of each sequence", .min = 1});
  v("max_frames", o.max_frames, OptionSpec{.help = "at most this many frames per sequence (0 = all)", .min = 0});
  v("detections", o.detections,
    OptionSpec{.help = "annotations = the stored 2D (npz pose_2d, json keypoints_2d; score 1)"});
}

DatasetInfo H3wbInfo();
// One source per subject and action. The annotation file is parsed when they open (json: its views
// grouped into frames, subjects identified); each frame's GT and, with param
// detections=annotations, its stored 2D keypoints (npz pose_2d, json keypoints_2d) as one person per
// view with score 1 (CocoWholeBodyJoints(); a view without stored 2D has no person) are converted
// when it is pulled, the views' agreement checked then. The frames are assembled from the ground
// truth: without it (DatasetRequest::ground_truth false) a ConfigError.
std::vector<std::unique_ptr<FrameSource>> OpenH3wb(const DatasetRequest& request);

}  // namespace rpt
