// SPDX-License-Identifier: MIT
#include "datasets/readers/synthetic_dataset.h"

#include <algorithm>

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
  info.layout = "nothing on disk (--root is ignored)";
  info.params = DescribeDatasetParams<SyntheticParams>();
  return info;
}

std::vector<Sequence> ReadSynthetic(const DatasetRequest& request) {
  return MakeSyntheticDataset(ParseDatasetParams<SyntheticParams>(kName, request));
}

std::unique_ptr<FrameSource> StreamSynthetic(const SyntheticParams& params) {
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

std::vector<std::unique_ptr<FrameSource>> StreamSyntheticDataset(const DatasetRequest& request) {
  std::vector<std::unique_ptr<FrameSource>> sources;
  sources.push_back(StreamSynthetic(ParseDatasetParams<SyntheticParams>(kName, request)));
  return sources;
}

std::vector<Sequence> MakeSyntheticDataset(const SyntheticParams& params) {
  std::vector<Sequence> sequences;
  sequences.push_back(Materialize(*StreamSynthetic(params)));
  return sequences;
}

}  // namespace rpt
