// SPDX-License-Identifier: MIT
#include "datasets/readers/synthetic_dataset.h"

#include <map>

#include "core/errors.h"
#include "core/text.h"
#include "datasets/synthetic/detector_options.h"
#include "datasets/synthetic/synthetic_sequence.h"

namespace rpt {
namespace {

int ToInt(const std::string& text, const std::string& key, int lo, int hi) {
  try {
    size_t used = 0;
    const long value = std::stol(text, &used);
    if (used == text.size() && value >= lo && value <= hi) return static_cast<int>(value);
  } catch (const std::exception&) {
  }
  throw ConfigError("dataset 'synthetic': " + key + "=" + text + " must be an integer in [" + std::to_string(lo) +
                    ", " + std::to_string(hi) + "]");
}

std::string OneOf(const std::string& value, const std::string& key, std::initializer_list<const char*> allowed) {
  std::string list;
  for (const char* a : allowed) {
    if (value == a) return value;
    AppendItem(&list, a, "|");
  }
  throw ConfigError("dataset 'synthetic': " + key + "=" + value + " must be one of " + list);
}

}  // namespace

DatasetInfo SyntheticInfo() {
  DatasetInfo info;
  info.name = "synthetic";
  info.description = "generated scene (walking people, camera rig) with a simulated 2D detector; no files needed";
  info.layout = "nothing on disk (--root is ignored)";
  info.params = {
      {"cameras", "5", "number of cameras"},
      {"people", "4", "number of people"},
      {"frames", "300", "number of frames"},
      {"fps", "25", "frames per second"},
      {"joints", "body", "body (17 COCO) or wholebody (133 COCO-WholeBody)"},
      {"layout", "ring", "camera placement: ring or random"},
      {"distortion", "none", "lens model: none, opencv or fisheye"},
      {"noise", "realistic", "simulated detector profile: perfect, clean, realistic or hard (none = perfect)"},
      {"seed", "1", "random seed of scene and detector"},
  };
  return info;
}

std::vector<Sequence> ReadSynthetic(const DatasetRequest& request) {
  const DatasetInfo info = SyntheticInfo();
  request.CheckParams(info);
  auto param = [&](const std::string& key) { return request.Param(info, key); };
  synthetic::SceneOptions options;
  options.rig.num_cameras = ToInt(param("cameras"), "cameras", 2, 64);
  options.num_people = ToInt(param("people"), "people", 1, 30);
  options.num_frames = ToInt(param("frames"), "frames", 1, 10000000);
  options.fps = ToInt(param("fps"), "fps", 1, 1000);
  options.whole_body = OneOf(param("joints"), "joints", {"body", "wholebody"}) == "wholebody";
  options.rig.layout = OneOf(param("layout"), "layout", {"ring", "random"}) == "ring" ? synthetic::RigLayout::kRing
                                                                                       : synthetic::RigLayout::kRandom;
  static const std::map<std::string, DistortionModel> kDistortions = {
      {"none", DistortionModel::kNone}, {"opencv", DistortionModel::kOpenCV}, {"fisheye", DistortionModel::kFisheye}};
  options.rig.distortion = kDistortions.at(OneOf(param("distortion"), "distortion", {"none", "opencv", "fisheye"}));
  options.seed = static_cast<uint64_t>(ToInt(param("seed"), "seed", 0, 2147483647));
  const std::string noise = OneOf(param("noise"), "noise", {"perfect", "clean", "realistic", "hard", "none"});
  const synthetic::Scene scene = synthetic::GenerateScene(options);
  const synthetic::DetectorOptions detector = synthetic::DetectorProfile(noise);
  return {synthetic::MakeSyntheticSequence(scene, detector, options.seed, "synthetic")};
}

}  // namespace rpt
