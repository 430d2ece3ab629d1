// SPDX-License-Identifier: MIT
#include "cli/config.h"

#include <algorithm>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/errors.h"
#include "core/text.h"
#include "datasets/io/json_file.h"

namespace rpt::cli {
namespace {

using Json = nlohmann::ordered_json;

struct Descriptor {
  ConfigOptionInfo info;
  std::function<void(Config&, const Json&, const std::string&)> set;  // from a JSON value
  std::function<Json(const Config&)> get;
  std::function<Json(const std::string&, const std::string&)> parse;  // text -> JSON value
};

[[noreturn]] void Bad(const std::string& where, const std::string& key, const std::string& problem) {
  throw ConfigError(where + ": " + key + ": " + problem);
}

std::string Trim(std::string s) {
  s.erase(0, s.find_first_not_of(" \t"));
  s.erase(s.find_last_not_of(" \t") + 1);
  return s;
}

double ParseNumber(const std::string& text, const std::string& key, const std::string& where) {
  try {
    size_t used = 0;
    const double value = std::stod(text, &used);
    if (used == text.size()) return value;
  } catch (const std::exception&) {
  }
  Bad(where, key, "'" + text + "' is not a number");
}

template <class Access>
Descriptor Bool(std::string key, std::string help, Access access) {
  Descriptor d{{key, "bool", std::move(help)}, {}, {}, {}};
  d.set = [access, key](Config& c, const Json& v, const std::string& where) {
    if (!v.is_boolean()) Bad(where, key, "expected true or false, got " + v.dump());
    access(c) = v.get<bool>();
  };
  d.get = [access](const Config& c) { return Json(access(const_cast<Config&>(c))); };
  d.parse = [key](const std::string& text, const std::string& where) {
    if (text == "true" || text == "1" || text == "on") return Json(true);
    if (text == "false" || text == "0" || text == "off") return Json(false);
    Bad(where, key, "expected true or false, got '" + text + "'");
  };
  return d;
}

template <class Access>
Descriptor Number(std::string key, std::string help, Access access, bool integer = false) {
  Descriptor d{{key, integer ? "int" : "number", std::move(help)}, {}, {}, {}};
  d.set = [access, key, integer](Config& c, const Json& v, const std::string& where) {
    if (!v.is_number()) Bad(where, key, "expected a number, got " + v.dump());
    if (integer && !v.is_number_integer()) Bad(where, key, "expected an integer, got " + v.dump());
    access(c) = v.get<double>();
  };
  d.get = [access, integer](const Config& c) {
    const double value = access(const_cast<Config&>(c));
    return integer ? Json(static_cast<long>(value)) : Json(value);
  };
  d.parse = [key, integer](const std::string& text, const std::string& where) {
    const double value = ParseNumber(text, key, where);
    if (integer) {
      if (value != static_cast<long>(value)) Bad(where, key, "expected an integer, got '" + text + "'");
      return Json(static_cast<long>(value));
    }
    return Json(value);
  };
  return d;
}

// Integer fields are stored as int; adapt them to the double-based Number descriptor.
template <class Access>
Descriptor Int(std::string key, std::string help, Access access) {
  struct Proxy {
    int* target;
    operator double() const { return *target; }
    Proxy& operator=(double v) {
      *target = static_cast<int>(v);
      return *this;
    }
  };
  auto proxy_access = [access](Config& c) { return Proxy{&access(c)}; };
  Descriptor d = Number(std::move(key), std::move(help), [proxy_access](Config& c) { return proxy_access(c); }, true);
  return d;
}

template <class E, class Access>
Descriptor Enum(std::string key, std::string help, std::vector<std::pair<std::string, E>> names, Access access) {
  std::string type;
  for (const auto& [name, value] : names) AppendItem(&type, name, "|");
  Descriptor d{{key, type, std::move(help)}, {}, {}, {}};
  d.set = [access, key, names, type](Config& c, const Json& v, const std::string& where) {
    if (v.is_string()) {
      for (const auto& [name, value] : names) {
        if (name == v.get<std::string>()) {
          access(c) = value;
          return;
        }
      }
    }
    Bad(where, key, "expected one of " + type + ", got " + v.dump());
  };
  d.get = [access, names](const Config& c) {
    for (const auto& [name, value] : names) {
      if (value == access(const_cast<Config&>(c))) return Json(name);
    }
    return Json("?");
  };
  d.parse = [](const std::string& text, const std::string&) { return Json(text); };
  return d;
}

template <class Access>
Descriptor NameList(std::string key, std::string help, Access access) {
  Descriptor d{{key, "list of joint names", std::move(help)}, {}, {}, {}};
  d.set = [access, key](Config& c, const Json& v, const std::string& where) {
    if (!v.is_array()) Bad(where, key, "expected a list of joint names, got " + v.dump());
    JointNames names;
    for (const Json& item : v) {
      if (!item.is_string()) Bad(where, key, "expected a list of joint names, got " + v.dump());
      names.push_back(item.get<std::string>());
    }
    access(c) = names;
  };
  d.get = [access](const Config& c) { return Json(access(const_cast<Config&>(c))); };
  d.parse = [](const std::string& text, const std::string&) {
    Json list = Json::array();
    std::stringstream s(text);
    for (std::string item; std::getline(s, item, ',');) {
      if (!Trim(item).empty()) list.push_back(Trim(item));
    }
    return list;
  };
  return d;
}

template <class Access>
Descriptor Vector3(std::string key, std::string help, Access access) {
  Descriptor d{{key, "[x, y, z]", std::move(help)}, {}, {}, {}};
  d.set = [access, key](Config& c, const Json& v, const std::string& where) {
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number()) {
      Bad(where, key, "expected [x, y, z], got " + v.dump());
    }
    access(c) = Eigen::Vector3d(v[0].get<double>(), v[1].get<double>(), v[2].get<double>());
  };
  d.get = [access](const Config& c) {
    const Eigen::Vector3d& x = access(const_cast<Config&>(c));
    return Json::array({x.x(), x.y(), x.z()});
  };
  d.parse = [key](const std::string& text, const std::string& where) {
    Json list = Json::array();
    std::stringstream s(text);
    for (std::string item; std::getline(s, item, ',');) list.push_back(ParseNumber(Trim(item), key, where));
    return list;
  };
  return d;
}

const std::vector<Descriptor>& Descriptors() {
  using metrics::Alignment;
  using metrics::LegacyPcpLayout;
  using metrics::MatchingMode;
  using metrics::PcpMatching;
  using metrics::PckDenominator;
  static const std::vector<Descriptor> table = {
      Number("undistort.min_joint_score", "2D joints with a lower score are missing",
             [](Config& c) -> double& { return c.triangulator.undistort.min_joint_score; }),
      Bool("undistort.add_derived_joints", "append hip_middle, shoulder_middle, head (computed in 2D)",
           [](Config& c) -> bool& { return c.triangulator.undistort.add_derived_joints; }),
      Bool("prefilter.enabled", "step 2: filter pairs with the last frame's persons (ablation: false)",
           [](Config& c) -> bool& { return c.triangulator.prefilter.enabled; }),
      Number("prefilter.max_distance_rel", "match radius at zero elapsed time, fraction of the pose's bbox diagonal",
             [](Config& c) -> double& { return c.triangulator.prefilter.max_distance_rel; }),
      Number("prefilter.person_speed_m_s", "m/s, widens the match radius with the time since the last frame",
             [](Config& c) -> double& { return c.triangulator.prefilter.person_speed_m_s; }),
      Number("prefilter.ambiguity_ratio", "second-closest person must be this much farther for a match",
             [](Config& c) -> double& { return c.triangulator.prefilter.ambiguity_ratio; }),
      Int("prefilter.max_pairs_per_person", "pairs kept per tracked person, best triangulation angle first (<= 0: all)",
          [](Config& c) -> int& { return c.triangulator.prefilter.max_pairs_per_person; }),
      Enum<TriangulationMethod>("triangulate.method", "steps 4 and 10: ray mid-point or linear DLT (SVD)",
                                {{"midpoint", TriangulationMethod::kMidpoint}, {"dlt", TriangulationMethod::kDlt}},
                                [](Config& c) -> TriangulationMethod& { return c.triangulator.triangulate.method; }),
      NameList("triangulate.core_joints", "step 3: joints used for association (empty = shoulders, hips, elbows, wrists, knees, ankles)",
               [](Config& c) -> JointNames& { return c.triangulator.triangulate.core_joints; }),
      Int("triangulate.min_core_joints", "a pair needs this many core joints seen in both views",
          [](Config& c) -> int& { return c.triangulator.triangulate.min_core_joints; }),
      Vector3("room_check.center_m", "m, room centre (used when room_check.size_m is set; else the dataset's room)",
              [](Config& c) -> Eigen::Vector3d& { return c.triangulator.room_check.center_m; }),
      Vector3("room_check.size_m", "m, room size per axis (<= 0: unbounded; all zero: the dataset's room)",
              [](Config& c) -> Eigen::Vector3d& { return c.triangulator.room_check.size_m; }),
      Number("room_check.margin_m", "m, tolerance around the room box",
             [](Config& c) -> double& { return c.triangulator.room_check.margin_m; }),
      Enum<ScoreMode>("score.mode", "steps 6-7: combined, or only one error term (paper ablations)",
                      {{"combined", ScoreMode::kCombined},
                       {"reprojection", ScoreMode::kReprojectionOnly},
                       {"triangulation", ScoreMode::kTriangulationOnly}},
                      [](Config& c) -> ScoreMode& { return c.triangulator.score.mode; }),
      Bool("score.use_confidence", "weight joints by 2D confidence (ablation: false)",
           [](Config& c) -> bool& { return c.triangulator.score.use_confidence; }),
      Enum<ScoreScale>("score.scale", "kernel scale: adaptive (estimated detection noise) or fixed (first release)",
                       {{"adaptive", ScoreScale::kAdaptive}, {"fixed", ScoreScale::kFixed}},
                       [](Config& c) -> ScoreScale& { return c.triangulator.score.scale; }),
      Number("score.scale_factor", "adaptive: kernel scale = factor x estimated noise",
             [](Config& c) -> double& { return c.triangulator.score.scale_factor; }),
      Number("score.noise_prior_m", "adaptive: m, noise level assumed before the data has spoken",
             [](Config& c) -> double& { return c.triangulator.score.noise_prior_m; }),
      Number("score.trim_fraction", "the pair score leaves out this share of its worst joints",
             [](Config& c) -> double& { return c.triangulator.score.trim_fraction; }),
      Number("score.reprojection_scale_rel", "fixed: relative reprojection error giving score factor e^-1",
             [](Config& c) -> double& { return c.triangulator.score.reprojection_scale_rel; }),
      Number("score.ray_gap_scale_m", "fixed: m, ray gap giving score factor e^-1",
             [](Config& c) -> double& { return c.triangulator.score.ray_gap_scale_m; }),
      Bool("score.prune_limbs", "invalidate joints of implausibly short or long limbs",
           [](Config& c) -> bool& { return c.triangulator.score.prune_limbs; }),
      Number("filter.min_match_score", "step 8: pairs with a lower score are dropped",
             [](Config& c) -> double& { return c.triangulator.filter.min_match_score; }),
      Number("group.max_distance_m", "step 9: m, mean core-joint distance to join a group",
             [](Config& c) -> double& { return c.triangulator.group.max_distance_m; }),
      Int("group.min_group_size", "step 9: groups with fewer proposals are dropped (0 = auto: 1 below 10 cameras, else 2)",
          [](Config& c) -> int& { return c.triangulator.group.min_group_size; }),
      Bool("group.exclusive_poses", "a 2D pose belongs to one person (removes phantoms)",
           [](Config& c) -> bool& { return c.triangulator.group.exclusive_poses; }),
      Bool("group.drop_mirrored", "drop a group that is another group with left/right swapped",
           [](Config& c) -> bool& { return c.triangulator.group.drop_mirrored; }),
      Number("merge.max_distance_m", "step 11: m, drop joint proposals farther from the mean (<= 0: keep all)",
             [](Config& c) -> double& { return c.triangulator.merge.max_distance_m; }),
      Int("merge.top_k", "step 11: keep the k closest joint proposals (<= 0: all)",
          [](Config& c) -> int& { return c.triangulator.merge.top_k; }),
      Bool("merge.score_weighted", "step 11: weighted average by joint score",
           [](Config& c) -> bool& { return c.triangulator.merge.score_weighted; }),
      Number("merge.min_joint_score", "step 11: joint proposals below are ignored",
             [](Config& c) -> double& { return c.triangulator.merge.min_joint_score; }),
      Bool("merge.keep_best_when_all_far", "step 11: keep the best candidate when the distance filter drops all",
           [](Config& c) -> bool& { return c.triangulator.merge.keep_best_when_all_far; }),
      Bool("verify.enabled", "step 11b: drop persons that more views see nobody at than see them",
           [](Config& c) -> bool& { return c.triangulator.verify.enabled; }),
      Int("verify.min_empty_views", "step 11b: empty views needed (and more than supporting views) to drop a person",
          [](Config& c) -> int& { return c.triangulator.verify.min_empty_views; }),
      Number("verify.min_inside_fraction", "step 11b: a view counts as empty only if this share of the joints is in the image",
             [](Config& c) -> double& { return c.triangulator.verify.min_inside_fraction; }),
      Bool("single_view.enabled", "step 12b: place persons seen by one camera at the depth their limb lengths imply",
           [](Config& c) -> bool& { return c.triangulator.single_view.enabled; }),
      Number("single_view.min_joint_score", "step 12b: confidence of the joints used",
             [](Config& c) -> double& { return c.triangulator.single_view.min_joint_score; }),
      Int("single_view.min_core_joints", "step 12b: confident core joints a pose needs",
          [](Config& c) -> int& { return c.triangulator.single_view.min_core_joints; }),
      Number("single_view.score_factor", "step 12b: joint scores = 2D confidence x this",
             [](Config& c) -> double& { return c.triangulator.single_view.score_factor; }),
      Number("single_view.duplicate_distance_m", "step 12b: m, centre distance under which a lifted person is a duplicate",
             [](Config& c) -> double& { return c.triangulator.single_view.duplicate_distance_m; }),
      Number("single_view.max_overlap_iou", "step 12b: poses overlapping a found person's projection this much are that person",
             [](Config& c) -> double& { return c.triangulator.single_view.max_overlap_iou; }),
      Bool("postprocess.enabled", "step 12 (ablation: false)",
           [](Config& c) -> bool& { return c.triangulator.postprocess.enabled; }),
      Int("postprocess.min_valid_joints", "persons with fewer valid joints are dropped",
          [](Config& c) -> int& { return c.triangulator.postprocess.min_valid_joints; }),
      Number("postprocess.min_extent_m", "m, drop persons with a smaller bounding-box diagonal",
             [](Config& c) -> double& { return c.triangulator.postprocess.min_extent_m; }),
      Number("postprocess.max_extent_m", "m, drop persons with a larger bounding-box diagonal",
             [](Config& c) -> double& { return c.triangulator.postprocess.max_extent_m; }),
      Bool("postprocess.drop_outside_room", "drop persons whose centre is outside the room",
           [](Config& c) -> bool& { return c.triangulator.postprocess.drop_outside_room; }),
      Bool("postprocess.replace_wrong_joints", "joints of implausible limbs take their neighbour's place",
           [](Config& c) -> bool& { return c.triangulator.postprocess.replace_wrong_joints; }),
      Bool("postprocess.fill_missing_joints", "missing joints take their neighbour's position",
           [](Config& c) -> bool& { return c.triangulator.postprocess.fill_missing_joints; }),
      Number("postprocess.filled_joint_score", "score of filled joints (> 0)",
             [](Config& c) -> double& { return c.triangulator.postprocess.filled_joint_score; }),
      Bool("track.enabled", "step 13: persistent ids (ablation: false)",
           [](Config& c) -> bool& { return c.triangulator.track.enabled; }),
      Number("track.max_distance_m", "m, mean core-joint distance to continue a track",
             [](Config& c) -> double& { return c.triangulator.track.max_distance_m; }),
      Number("track.max_gap_s", "s, frames further apart (or with unknown time) start afresh: no coasting, no pre-filter",
             [](Config& c) -> double& { return c.triangulator.track.max_gap_s; }),
      Int("track.max_missing_frames", "a lost person is returned with its last pose this many frames",
          [](Config& c) -> int& { return c.triangulator.track.max_missing_frames; }),
      Bool("clip_speed.enabled", "step 14: clip joint speed (needs tracking)",
           [](Config& c) -> bool& { return c.triangulator.clip_speed.enabled; }),
      Number("clip_speed.max_speed_m_s", "m/s, maximum joint speed",
             [](Config& c) -> double& { return c.triangulator.clip_speed.max_speed_m_s; }),
      Bool("bone_lengths.enabled", "step 15: mark joints whose bones disagree with their track's lengths (needs tracking)",
           [](Config& c) -> bool& { return c.triangulator.bone_lengths.enabled; }),
      Number("bone_lengths.tolerance_rel", "a limb disagrees beyond this fraction of its track's running length",
             [](Config& c) -> double& { return c.triangulator.bone_lengths.tolerance_rel; }),
      Number("bone_lengths.min_tolerance_m", "m, floor of the tolerance (short bones: hands, face)",
             [](Config& c) -> double& { return c.triangulator.bone_lengths.min_tolerance_m; }),
      Int("bone_lengths.min_observations", "a limb is checked once its track has observed it this often",
          [](Config& c) -> int& { return c.triangulator.bone_lengths.min_observations; }),
      Int("bone_lengths.window", "observations per limb the running median is taken over",
          [](Config& c) -> int& { return c.triangulator.bone_lengths.window; }),
      Enum<SmoothMode>("smooth.mode",
                       "smoothing of tracked persons: causal (step 16, Kalman filter) or offline (two-sided, whole sequences)",
                       {{"off", SmoothMode::kOff}, {"causal", SmoothMode::kCausal}, {"offline", SmoothMode::kOffline}},
                       [](Config& c) -> SmoothMode& { return c.triangulator.smooth.mode; }),
      Number("smooth.measurement_noise_m", "causal: m, standard deviation of a triangulated joint's error",
             [](Config& c) -> double& { return c.triangulator.smooth.measurement_noise_m; }),
      Number("smooth.acceleration_m_s2", "causal: m/s^2, standard deviation of a joint's acceleration (higher: smooths less)",
             [](Config& c) -> double& { return c.triangulator.smooth.acceleration_m_s2; }),
      Number("smooth.offline_sigma_s", "offline: s, sigma of the Gaussian time weights (window +-3 sigma)",
             [](Config& c) -> double& { return c.triangulator.smooth.offline_sigma_s; }),
      Int("smooth.offline_degree", "offline: degree of the local polynomial fit (1-3)",
          [](Config& c) -> int& { return c.triangulator.smooth.offline_degree; }),
      NameList("metrics.evaluated_joints", "joints evaluated and matched (empty = the paper's 13)",
               [](Config& c) -> JointNames& { return c.metrics.evaluated_joints; }),
      Number("metrics.min_gt_score", "GT joints with a lower or equal score are invalid",
             [](Config& c) -> double& { return c.metrics.min_gt_score; }),
      Number("metrics.min_pred_score", "predicted joints with a lower or equal score are missing",
             [](Config& c) -> double& { return c.metrics.min_pred_score; }),
      Enum<MatchingMode>("metrics.matching", "score-ranked greedy over the dataset (VoxelPose) or per-frame Hungarian",
                         {{"greedy", MatchingMode::kGreedyScore}, {"hungarian", MatchingMode::kHungarian}},
                         [](Config& c) -> MatchingMode& { return c.metrics.matching; }),
      Number("metrics.match_threshold_mm", "mm, a pair matches iff its MPJPE is below",
             [](Config& c) -> double& { return c.metrics.match_threshold_mm; }),
      Enum<PckDenominator>("metrics.pck_denominator", "joints of all GT persons, or of matched ones only",
                           {{"all_gt", PckDenominator::kAllGt}, {"matched_gt", PckDenominator::kMatchedGt}},
                           [](Config& c) -> PckDenominator& { return c.metrics.pck_denominator; }),
      Bool("metrics.count_preds_without_gt", "predictions in frames without GT count as invalid",
           [](Config& c) -> bool& { return c.metrics.count_preds_without_gt; }),
      Enum<Alignment>("metrics.alignment", "reported MPJPE absolute or pelvis-aligned",
                      {{"none", Alignment::kNone}, {"pelvis", Alignment::kPelvis}},
                      [](Config& c) -> Alignment& { return c.metrics.alignment; }),
      Enum<PcpMatching>("metrics.pcp_matching", "generic PCP against the nearest prediction or the matched one",
                        {{"nearest", PcpMatching::kNearestPrediction}, {"matched", PcpMatching::kMatched}},
                        [](Config& c) -> PcpMatching& { return c.metrics.pcp_matching; }),
      Number("metrics.pcp_alpha", "part correct iff mean endpoint error <= alpha * part length",
             [](Config& c) -> double& { return c.metrics.pcp_alpha; }),
      Bool("metrics.wholebody_groups", "MPJPE per whole-body group All|Body|Face|Hands",
           [](Config& c) -> bool& { return c.metrics.wholebody_groups; }),
      Enum<LegacyPcpLayout>("metrics.legacy_pcp", "legacy Shelf/Campus PCP with VoxelPose head synthesis",
                            {{"none", LegacyPcpLayout::kNone}, {"shelf", LegacyPcpLayout::kShelf}, {"campus", LegacyPcpLayout::kCampus}},
                            [](Config& c) -> LegacyPcpLayout& { return c.metrics.legacy_pcp.layout; }),
      Bool("metrics.legacy_pcp_skip_empty_frames", "legacy PCP: skip frames without predictions (Faster-VoxelPose)",
           [](Config& c) -> bool& { return c.metrics.legacy_pcp.skip_frames_without_predictions; }),
      Int("metrics.legacy_pcp_actors", "legacy PCP: average over actors 0..n-1",
          [](Config& c) -> int& { return c.metrics.legacy_pcp.num_averaged_actors; }),
  };
  return table;
}

const Descriptor& Find(const std::string& key, const std::string& where) {
  for (const Descriptor& d : Descriptors()) {
    if (d.info.key == key) return d;
  }
  std::vector<std::string> sections;
  for (const Descriptor& d : Descriptors()) {
    const std::string section = d.info.key.substr(0, d.info.key.find('.'));
    if (std::find(sections.begin(), sections.end(), section) == sections.end()) sections.push_back(section);
  }
  const std::string list = Join(sections);
  throw ConfigError(where + ": unknown option '" + key + "' (sections: " + list +
                    "; `rpt config --dump` lists every option)");
}

}  // namespace

std::vector<ConfigOptionInfo> ConfigOptions() {
  std::vector<ConfigOptionInfo> out;
  for (const Descriptor& d : Descriptors()) out.push_back(d.info);
  return out;
}

void SetConfigOption(const std::string& key, const std::string& value, const std::string& where, Config* config) {
  const Descriptor& d = Find(key, where);
  d.set(*config, d.parse(value, where), where);
}

void ApplyConfigOverride(const std::string& assignment, Config* config) {
  const size_t eq = assignment.find('=');
  if (eq == std::string::npos) throw ConfigError("--set " + assignment + ": expected section.key=value");
  SetConfigOption(Trim(assignment.substr(0, eq)), Trim(assignment.substr(eq + 1)), "--set " + assignment, config);
}

std::string GetConfigOption(const Config& config, const std::string& key) {
  const Json value = Find(key, "option").get(config);
  if (value.is_string()) return value.get<std::string>();
  if (value.is_array()) {
    std::string out;
    for (const Json& item : value) AppendItem(&out, item.is_string() ? item.get<std::string>() : item.dump(), ",");
    return out;
  }
  return value.dump();
}

void LoadConfigFile(const std::filesystem::path& path, Config* config) {
  const nlohmann::json root = io::LoadJsonFile(path);
  const std::string source = path.string();
  if (!root.is_object()) throw ConfigError(source + ": expected an object of sections");
  for (const auto& [section, values] : root.items()) {
    if (!values.is_object()) throw ConfigError(source + ": /" + section + ": expected an object of options");
    for (const auto& [name, value] : values.items()) {
      const std::string key = section + "." + name;
      const Descriptor& d = Find(key, source);
      d.set(*config, Json::parse(value.dump()), source + ": /" + section + "/" + name);
    }
  }
  CheckConfig(*config);
}

std::string DumpConfig(const Config& config, bool with_comments) {
  // Sections in table order, options in table order.
  std::vector<std::string> sections;
  for (const Descriptor& d : Descriptors()) {
    const std::string section = d.info.key.substr(0, d.info.key.find('.'));
    if (sections.empty() || sections.back() != section) sections.push_back(section);
  }
  std::ostringstream out;
  out << "{\n";
  for (size_t s = 0; s < sections.size(); ++s) {
    out << "  \"" << sections[s] << "\": {\n";
    std::vector<const Descriptor*> members;
    for (const Descriptor& d : Descriptors()) {
      if (d.info.key.rfind(sections[s] + ".", 0) == 0) members.push_back(&d);
    }
    for (size_t m = 0; m < members.size(); ++m) {
      const Descriptor& d = *members[m];
      out << "    \"" << d.info.key.substr(sections[s].size() + 1) << "\": " << d.get(config).dump()
          << (m + 1 < members.size() ? "," : "");
      if (with_comments) out << "  // " << d.info.type << ": " << d.info.help;
      out << "\n";
    }
    out << "  }" << (s + 1 < sections.size() ? "," : "") << "\n";
  }
  out << "}\n";
  return out.str();
}

void CheckConfig(const Config& config) {
  if (const std::string error = config.triangulator.Check(); !error.empty()) throw ConfigError(error);
  config.metrics.Check();
}

}  // namespace rpt::cli
