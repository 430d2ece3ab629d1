// SPDX-License-Identifier: MIT
// "synthetic": a generated scene with simulated detections, as a dataset (no files needed).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "datasets/dataset_params.h"
#include "datasets/frame_source.h"
#include "datasets/sequence.h"
#include "datasets/synthetic/camera_rig.h"

namespace rpt {

enum class SyntheticJoints { kBody, kWholeBody };
enum class SyntheticLens { kNone, kOpenCV, kFisheye };

template <>
struct EnumNames<SyntheticJoints> {
  static constexpr std::array<std::pair<SyntheticJoints, std::string_view>, 2> values = {
      {{SyntheticJoints::kBody, "body"}, {SyntheticJoints::kWholeBody, "wholebody"}}};
};
template <>
struct EnumNames<SyntheticLens> {
  static constexpr std::array<std::pair<SyntheticLens, std::string_view>, 3> values = {
      {{SyntheticLens::kNone, "none"}, {SyntheticLens::kOpenCV, "opencv"}, {SyntheticLens::kFisheye, "fisheye"}}};
};
template <>
struct EnumNames<synthetic::RigLayout> {
  static constexpr std::array<std::pair<synthetic::RigLayout, std::string_view>, 2> values = {
      {{synthetic::RigLayout::kRing, "ring"}, {synthetic::RigLayout::kRandom, "random"}}};
};

// The scene and detector of the synthetic dataset (`rpt demo` passes its options through these).
struct SyntheticParams {
  int cameras = 5;
  int people = 4;
  int frames = 300;
  int fps = 25;
  SyntheticJoints joints = SyntheticJoints::kBody;
  synthetic::RigLayout layout = synthetic::RigLayout::kRing;
  SyntheticLens distortion = SyntheticLens::kNone;
  std::string noise = "realistic";  // a synthetic::DetectorProfileNames() entry, or "none" (= perfect)
  std::uint64_t seed = 1;

  // "" when valid, else "synthetic.key: problem": the ranges of VisitFields and a known detector
  // profile (core/options_check.h).
  std::string Check() const;
};

template <class Visitor, OptionsOf<SyntheticParams> Self>
void VisitFields(Visitor& v, Self& o) {
  v("cameras", o.cameras, OptionSpec{.help = "number of cameras", .min = 2, .max = 64});
  v("people", o.people, OptionSpec{.help = "number of people", .min = 1, .max = 30});
  v("frames", o.frames, OptionSpec{.help = "number of frames to generate (a count, not indices)", .min = 1, .max = 10000000});
  v("fps", o.fps, OptionSpec{.help = "frames per second", .unit = "Hz", .min = 1, .max = 1000});
  v("joints", o.joints, OptionSpec{.help = "body (17 COCO) or wholebody (133 COCO-WholeBody)"});
  v("layout", o.layout, OptionSpec{.help = "camera placement"});
  v("distortion", o.distortion, OptionSpec{.help = "lens model"});
  v("noise", o.noise,
    OptionSpec{.help = "simulated detector profile: perfect, clean, realistic or hard (none = perfect)"});
  v("seed", o.seed, OptionSpec{.help = "random seed of scene and detector"});
}

DatasetInfo SyntheticInfo();
// The one synthetic sequence: frames are generated when pulled (memory flat in the number of
// frames). Without the ground truth (DatasetRequest::ground_truth false) the frames keep their
// simulated detections and lose their persons and 2D labels.
std::vector<std::unique_ptr<FrameSource>> OpenSynthetic(const DatasetRequest& request);
// The same from parsed parameters (what `rpt demo` passes its options through), with its ground truth.
std::unique_ptr<FrameSource> OpenSyntheticSequence(const SyntheticParams& params);
// OpenSyntheticSequence(params) materialised (what `rpt demo` evaluates).
std::vector<Sequence> MakeSyntheticDataset(const SyntheticParams& params);

}  // namespace rpt
