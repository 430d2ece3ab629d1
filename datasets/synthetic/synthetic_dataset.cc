// SPDX-License-Identifier: MIT
#include "datasets/synthetic/synthetic_dataset.h"

#include <algorithm>
#include <memory>
#include <utility>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/options_check.h"
#include "datasets/synthetic/detector_options.h"
#include "datasets/synthetic/synthetic_sequence.h"

namespace rpt {
namespace {

constexpr const char* kName = "synthetic";

DistortionModel ToDistortionModel(SyntheticLens lens) {
  switch (lens) {
    case SyntheticLens::kOpenCV:
      return DistortionModel::kOpenCV;
    case SyntheticLens::kFisheye:
      return DistortionModel::kFisheye;
    case SyntheticLens::kNone:
      break;
  }
  return DistortionModel::kNone;
}

// The generated frames without what they were generated from: no persons, no 2D labels, no GT
// joints (DatasetRequest::ground_truth false).
class DetectionsOnlySource final : public FrameSource {
 public:
  explicit DetectionsOnlySource(std::unique_ptr<FrameSource> scene)
      : scene_(std::move(scene)), header_(scene_->header()) {
    header_.gt_joints.clear();
  }
  const SequenceHeader& header() const override { return header_; }
  long num_frames() const override { return scene_->num_frames(); }
  bool Pull(SequenceFrame* frame) override { return scene_->Pull(frame); }
  // After the wrapped Complete: the simulated detector needs the persons.
  void Complete(long frame_idx, SequenceFrame* frame) const override {
    scene_->Complete(frame_idx, frame);
    frame->gt.Clear(0);
    frame->labels_2d.clear();
  }
  const InputWarnings& warnings() const override { return scene_->warnings(); }

 private:
  std::unique_ptr<FrameSource> scene_;
  SequenceHeader header_;
};

}  // namespace

std::string SyntheticParams::Check() const {
  OptionsChecker checker(kName);
  VisitFields(checker, *this);
  std::vector<std::string> profiles = synthetic::DetectorProfileNames();
  profiles.push_back("none");
  std::size_t index = 0;
  checker.Require(option_codec::ParseName(noise, profiles, &index), "noise");
  return checker.error();
}

DatasetInfo SyntheticInfo() {
  DatasetInfo info;
  info.name = kName;
  info.description = "generated scene (walking people, camera rig) with a simulated 2D detector; no files needed";
  info.layout = "nothing on disk (generated; --root is refused)";
  info.params = DescribeDatasetParams<SyntheticParams>();
  return info;
}

std::unique_ptr<FrameSource> OpenSyntheticSequence(const SyntheticParams& params) {
  ThrowIfInvalid(params);
  synthetic::SceneOptions options;
  options.rig.num_cameras = params.cameras;
  options.num_people = params.people;
  options.num_frames = params.frames;
  options.fps = params.fps;
  options.whole_body = params.joints == SyntheticJoints::kWholeBody;
  options.rig.layout = params.layout;
  options.rig.distortion = ToDistortionModel(params.distortion);
  options.seed = params.seed;
  return std::make_unique<synthetic::SyntheticSource>(options, synthetic::DetectorProfile(params.noise), options.seed,
                                                      kName);
}

std::vector<std::unique_ptr<FrameSource>> OpenSynthetic(const DatasetRequest& request) {
  // The datasets read from disk take frame indices (frames=0-12); a generated scene takes a count.
  if (const auto frames = request.params.find("frames");
      frames != request.params.end() && frames->second.find_first_of("-,:") != std::string::npos) {
    throw ConfigError("--param frames=" + frames->second + ": " + kName +
                      ".frames is the number of frames to generate (frames=N: frames 0 to N-1); frame indices such as "
                      "'0-12' select frames of the datasets read from disk");
  }
  std::unique_ptr<FrameSource> scene = OpenSyntheticSequence(ParseDatasetParams<SyntheticParams>(kName, request));
  std::vector<std::unique_ptr<FrameSource>> sources;
  sources.push_back(request.ground_truth ? std::move(scene) : std::make_unique<DetectionsOnlySource>(std::move(scene)));
  return sources;
}

std::vector<Sequence> MakeSyntheticDataset(const SyntheticParams& params) {
  std::vector<std::unique_ptr<FrameSource>> sources;
  sources.push_back(OpenSyntheticSequence(params));
  return MaterializeAll(std::move(sources));
}

}  // namespace rpt
