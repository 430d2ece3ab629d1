// SPDX-License-Identifier: MIT
#include "engine/config.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/config_args.h"
#include "core/errors.h"
#include "core/option_codec.h"
#include "datasets/dataset_params.h"
#include "tests/cli/cli_test_util.h"
#include "tests/error_message.h"

namespace rpt::cli {
namespace {

std::filesystem::path WriteTemp(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

// The ConfigError of applying `assignment` to `config` and checking it, or "no error".
std::string ErrorOf(const std::string& assignment, engine::Config* config) {
  try {
    engine::ApplyConfigOverride(assignment, config);
    engine::CheckConfig(*config);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Config, SetReachesTriangulatorAndMetricOptions) {
  engine::Config c;
  engine::ApplyConfigOverride("prefilter.enabled=false", &c);
  engine::ApplyConfigOverride("merge.top_k=0", &c);
  engine::ApplyConfigOverride("score.mode=triangulation", &c);
  engine::ApplyConfigOverride("triangulate.core_joints=shoulder_left, hip_left ,knee_left", &c);
  engine::ApplyConfigOverride("room_check.size_m=8,8,3", &c);
  engine::ApplyConfigOverride("metrics.matching=hungarian", &c);
  engine::ApplyConfigOverride("metrics.evaluated_joints=nose,wrist_left", &c);
  EXPECT_FALSE(c.triangulator.prefilter.enabled);
  EXPECT_EQ(c.triangulator.merge.top_k, 0);
  EXPECT_EQ(c.triangulator.score.mode, ScoreMode::kTriangulationOnly);
  EXPECT_EQ(c.triangulator.triangulate.core_joints, (JointNames{"shoulder_left", "hip_left", "knee_left"}));
  EXPECT_EQ(c.triangulator.room_check.size_m, Eigen::Vector3d(8, 8, 3));
  EXPECT_EQ(c.metrics.matching, metrics::MatchingMode::kHungarian);
  EXPECT_EQ(c.metrics.evaluated_joints, (JointNames{"nose", "wrist_left"}));
}

TEST(Config, EveryOptionRoundTripsThroughTextAndJson) {
  const engine::Config defaults;
  for (const engine::ConfigOptionInfo& option : engine::ConfigOptions()) {
    engine::Config c;
    engine::SetConfigOption(option.key, engine::GetConfigOption(defaults, option.key), "test", &c);
    EXPECT_EQ(engine::GetConfigOption(c, option.key), engine::GetConfigOption(defaults, option.key)) << option.key;
  }
  engine::Config changed;
  engine::ApplyConfigOverride("group.min_group_size=3", &changed);
  engine::ApplyConfigOverride("metrics.alignment=pelvis", &changed);
  const auto path = WriteTemp("rpt_config_roundtrip.json", engine::DumpConfig(changed, /*with_comments=*/false));
  engine::Config loaded;
  engine::LoadConfigFile(path, &loaded);
  EXPECT_EQ(loaded.triangulator.group.min_group_size, 3);
  EXPECT_EQ(loaded.metrics.alignment, metrics::Alignment::kPelvis);
  EXPECT_EQ(engine::DumpConfig(loaded, false), engine::DumpConfig(changed, false));
}

TEST(Config, UnknownKeysAndBadValuesAreErrorsNamingThePlace) {
  engine::Config c;
  auto message = [&c](const std::string& assignment) { return ErrorOf(assignment, &c); };
  EXPECT_NE(message("prefilter.enabld=true").find("unknown option 'prefilter.enabld'"), std::string::npos);
  EXPECT_NE(message("filter.nothing=1").find("filter"), std::string::npos);
  EXPECT_EQ(
      message("prefilter.enabled=maybe"),
      "--set prefilter.enabled=maybe: prefilter.enabled: 'maybe' is not true or false (also yes/no, on/off, 1/0)");
  EXPECT_EQ(message("merge.top_k=2.5"), "--set merge.top_k=2.5: merge.top_k: '2.5' is not an integer in [0, 1000000]");
  EXPECT_EQ(message("triangulate.method=svd"),
            "--set triangulate.method=svd: triangulate.method: 'svd' is not one of midpoint, dlt");
  EXPECT_EQ(message("room_check.size_m=1,2"),
            "--set room_check.size_m=1,2: room_check.size_m: '1,2' is not three numbers [x, y, z] (or x,y,z)");
  EXPECT_NE(message("no_equals_sign").find("section.key=value"), std::string::npos);
  c = engine::Config{};
  EXPECT_NE(message("filter.min_match_score=1.5").find("filter.min_match_score"), std::string::npos);

  const auto unknown = WriteTemp("rpt_config_unknown.json", R"({"merge": {"top_k": 2, "topk": 3}})");
  try {
    engine::LoadConfigFile(unknown, &c);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("rpt_config_unknown.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("merge.topk"), std::string::npos);
  }
  const auto wrong_type = WriteTemp("rpt_config_type.json", R"({"track": {"enabled": "maybe"}})");
  EXPECT_EQ(
      test::ConfigErrorOf([&] { engine::LoadConfigFile(wrong_type, &c); }),
      wrong_type.string() + ": /track/enabled: track.enabled: 'maybe' is not true or false (also yes/no, on/off, 1/0)");
  EXPECT_THROW(engine::LoadConfigFile("/nonexistent/rpt.json", &c), InputError);
}

TEST(ConfigCommand, DumpIsLoadableAndOverridesApply) {
  const test::CommandResult dump = test::RunRpt("config --dump --set track.enabled=false");
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  EXPECT_TRUE(nlohmann::json::accept(dump.out)) << dump.out;
  const auto path = WriteTemp("rpt_config_dump.json", dump.out);
  engine::Config c;
  engine::LoadConfigFile(path, &c);
  EXPECT_FALSE(c.triangulator.track.enabled);
  EXPECT_EQ(engine::DumpConfig(c, false), dump.out);  // reads back identically
  // --json is the default (kept for older scripts).
  EXPECT_EQ(test::RunRpt("config --dump --json --set track.enabled=false").out, dump.out);
  const test::CommandResult commented = test::RunRpt("config --dump --comments");
  ASSERT_EQ(commented.exit_code, 0) << commented.err;
  EXPECT_NE(commented.out.find("\"enabled\": true,  // true | false: "), std::string::npos);
  EXPECT_NE(commented.out.find("\"max_speed_m_s\": 10.0  // number > 0, m/s: "), std::string::npos);
  EXPECT_FALSE(nlohmann::json::accept(commented.out));  // clearly not JSON
  EXPECT_EQ(test::RunRpt("config --set nope.nope=1").exit_code, 2);
  EXPECT_EQ(test::RunRpt("demo --frames 5 --set filter.min_match_score=7").exit_code, 2);
  EXPECT_EQ(test::RunRpt("demo --frames 5 --set triangulate.robust_min_m=-1").exit_code, 2);
}

TEST(Config, DumpReadsBackIdenticallyWithEveryKindOfValue) {
  engine::Config changed;
  engine::ApplyConfigOverride("triangulate.method=dlt", &changed);
  engine::ApplyConfigOverride("triangulate.core_joints=[\"hip_left\", \"hip_right\", \"knee_left\"]", &changed);
  engine::ApplyConfigOverride("room_check.size_m=[8, 8, 3]", &changed);
  engine::ApplyConfigOverride("room_check.center_m=1.5,-2,0", &changed);
  engine::ApplyConfigOverride("merge.top_k=7", &changed);
  engine::ApplyConfigOverride("score.scale_factor=4.25", &changed);
  engine::ApplyConfigOverride("smooth.mode=offline", &changed);
  engine::ApplyConfigOverride("metrics.legacy_pcp=campus", &changed);
  engine::ApplyConfigOverride("metrics.legacy_pcp_alpha=0.4", &changed);
  engine::ApplyConfigOverride("metrics.count_preds_without_gt=false", &changed);
  const std::string dump = engine::DumpConfig(changed, /*with_comments=*/false);
  const nlohmann::json parsed = nlohmann::json::parse(dump);
  EXPECT_EQ(parsed["room_check"]["size_m"], nlohmann::json::array({8.0, 8.0, 3.0}));
  EXPECT_EQ(parsed["metrics"]["legacy_pcp_alpha"], 0.4);
  engine::Config loaded;
  engine::LoadConfigFile(WriteTemp("rpt_config_every_kind.json", dump), &loaded);
  EXPECT_EQ(engine::DumpConfig(loaded, false), dump);
  EXPECT_EQ(loaded.triangulator.triangulate.core_joints, (JointNames{"hip_left", "hip_right", "knee_left"}));
  EXPECT_EQ(loaded.triangulator.room_check.center_m, Eigen::Vector3d(1.5, -2, 0));
  EXPECT_EQ(loaded.metrics.legacy_pcp, metrics::LegacyPcpLayout::kCampus);
  EXPECT_DOUBLE_EQ(loaded.metrics.legacy_pcp_alpha, 0.4);
  // The sections and keys of the dump are the options, in order.
  std::vector<std::string> dumped_keys;
  const nlohmann::ordered_json ordered = nlohmann::ordered_json::parse(dump);
  for (const auto& [section, values] : ordered.items()) {
    for (const auto& [name, value] : values.items()) dumped_keys.push_back(section + "." + name);
  }
  std::vector<std::string> keys;
  for (const engine::ConfigOptionInfo& option : engine::ConfigOptions()) keys.push_back(option.key);
  EXPECT_EQ(dumped_keys, keys);
}

TEST(Config, ListValuesAcceptJsonAndCommaLists) {
  engine::Config c;
  engine::ApplyConfigOverride("metrics.evaluated_joints=[\"nose\",\"wrist_left\"]", &c);
  EXPECT_EQ(c.metrics.evaluated_joints, (JointNames{"nose", "wrist_left"}));
  engine::ApplyConfigOverride("metrics.evaluated_joints=nose, wrist_right", &c);
  EXPECT_EQ(c.metrics.evaluated_joints, (JointNames{"nose", "wrist_right"}));
  engine::ApplyConfigOverride("metrics.evaluated_joints=[]", &c);
  EXPECT_TRUE(c.metrics.evaluated_joints.empty());
  // "" is the empty list, as the docs say (it was a joint named '""'); so is an empty value.
  engine::ApplyConfigOverride("metrics.evaluated_joints=nose", &c);
  engine::ApplyConfigOverride("metrics.evaluated_joints=\"\"", &c);
  EXPECT_TRUE(c.metrics.evaluated_joints.empty());
  engine::ApplyConfigOverride("metrics.evaluated_joints=nose", &c);
  engine::ApplyConfigOverride("metrics.evaluated_joints= \"\" ", &c);
  EXPECT_TRUE(c.metrics.evaluated_joints.empty());
  engine::ApplyConfigOverride("metrics.evaluated_joints=nose", &c);
  engine::ApplyConfigOverride("metrics.evaluated_joints=", &c);
  EXPECT_TRUE(c.metrics.evaluated_joints.empty());
  // The example of the docs and of every --set help runs with the defaults (two joints did not:
  // triangulate.min_core_joints is 3).
  engine::Config example;
  engine::ApplyConfigOverride("triangulate.core_joints=shoulder_left,shoulder_right,hip_left,hip_right", &example);
  EXPECT_NO_THROW(engine::CheckConfig(example));
  engine::ApplyConfigOverride("room_check.size_m=[1,2,3]", &c);
  EXPECT_EQ(c.triangulator.room_check.size_m, Eigen::Vector3d(1, 2, 3));
  auto message = [&c](const std::string& assignment) { return ErrorOf(assignment, &c); };
  // The old trap: a JSON list was taken as the joint names '["a"' and '"b"]'.
  EXPECT_NE(message("triangulate.core_joints=[\"a\",\"b\"").find("is not a list of names"), std::string::npos);
  EXPECT_NE(message("triangulate.core_joints=[1, 2]").find("'[1, 2]' is not a list of names"), std::string::npos);
  EXPECT_NE(message("room_check.size_m=[1, 2]").find("'[1, 2]' is not three numbers [x, y, z]"), std::string::npos);
}

TEST(Config, TyposGetADidYouMean) {
  engine::Config c;
  auto message = [&c](const std::string& assignment) { return ErrorOf(assignment, &c); };
  EXPECT_NE(message("score.scale_facter=4").find("did you mean 'score.scale_factor'?"), std::string::npos);
  EXPECT_NE(message("sore.scale_factor=4").find("did you mean 'score.scale_factor'?"), std::string::npos);
  EXPECT_NE(message("score.mode=combind").find("did you mean 'combined'?"), std::string::npos);
  // Far from every key: the section's keys are listed instead.
  const std::string far = message("filter.nothing=1");
  EXPECT_EQ(far.find("did you mean"), std::string::npos) << far;
  EXPECT_NE(far.find("filter has: min_match_score"), std::string::npos) << far;

  const auto key_typo = WriteTemp("rpt_config_key_typo.json", R"({"merge": {"top_k": 2, "topk": 3}})");
  try {
    engine::LoadConfigFile(key_typo, &c);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("rpt_config_key_typo.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("did you mean 'merge.top_k'?"), std::string::npos) << e.what();
  }
  const auto section_typo = WriteTemp("rpt_config_section_typo.json", R"({"mege": {"top_k": 2}})");
  try {
    engine::LoadConfigFile(section_typo, &c);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("rpt_config_section_typo.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("unknown section 'mege' (did you mean 'merge'?"), std::string::npos)
        << e.what();
  }
  const test::CommandResult r = test::RunRpt("config --set group.max_distnce_m=0.3");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--set group.max_distnce_m=0.3: unknown option 'group.max_distnce_m' (did you mean "
                       "'group.max_distance_m'?"),
            std::string::npos)
      << r.err;
}

TEST(Config, ChecksNameSectionAndKeyWithRangesFromTheMetadata) {
  auto problem = [](const std::string& assignment) {
    engine::Config c;
    return ErrorOf(assignment, &c);
  };
  // Ranges are checked as the value is read, in the codec's words.
  EXPECT_EQ(problem("filter.min_match_score=1.5"),
            "--set filter.min_match_score=1.5: filter.min_match_score: '1.5' is not a number in [0, 1]");
  EXPECT_EQ(problem("score.scale_factor=0"), "--set score.scale_factor=0: score.scale_factor: '0' is not a number > 0");
  EXPECT_EQ(problem("prefilter.ambiguity_ratio=0.5"),
            "--set prefilter.ambiguity_ratio=0.5: prefilter.ambiguity_ratio: '0.5' is not a number in [1, 1000]");
  EXPECT_EQ(problem("metrics.pcp_alpha=0"), "--set metrics.pcp_alpha=0: metrics.pcp_alpha: '0' is not a number > 0");
  EXPECT_EQ(problem("metrics.legacy_pcp_actors=0"),
            "--set metrics.legacy_pcp_actors=0: metrics.legacy_pcp_actors: '0' is not an integer in [1, 10000]");
  EXPECT_EQ(problem("metrics.legacy_pcp_alpha=-1"),
            "--set metrics.legacy_pcp_alpha=-1: metrics.legacy_pcp_alpha: '-1' is not a number > 0");
  // Checks beyond the ranges run after all settings (CheckConfig), as "section.key: problem".
  EXPECT_EQ(problem("metrics.evaluated_joints=nose,nose"), "metrics.evaluated_joints: lists 'nose' twice");
  // The checks between fields stay.
  EXPECT_EQ(problem("postprocess.max_extent_m=0.1"),
            "postprocess.max_extent_m: 0.1 is below postprocess.min_extent_m (0.2)");
  EXPECT_EQ(problem("bone_lengths.min_observations=60"),
            "bone_lengths.min_observations: 60 is above bone_lengths.window (50)");
  EXPECT_EQ(problem("merge.top_k=0"), "no error");
  // Negative "keep all" values were accepted (issue 10): 0 is the one way to say "keep all".
  EXPECT_EQ(problem("merge.top_k=-1"), "--set merge.top_k=-1: merge.top_k: '-1' is not an integer in [0, 1000000]");
  EXPECT_EQ(problem("merge.max_distance_m=-0.5"),
            "--set merge.max_distance_m=-0.5: merge.max_distance_m: '-0.5' is not a number in [0, 1000000]");
  EXPECT_EQ(problem("prefilter.max_pairs_per_person=-1"),
            "--set prefilter.max_pairs_per_person=-1: prefilter.max_pairs_per_person: '-1' is not an integer in [0, "
            "1000000000]");
  EXPECT_EQ(problem("triangulate.max_persons_per_view=0"),
            "--set triangulate.max_persons_per_view=0: triangulate.max_persons_per_view: '0' is not an integer in [1, "
            "100000]");
  EXPECT_EQ(problem("triangulate.robust_min_m=0"),
            "--set triangulate.robust_min_m=0: triangulate.robust_min_m: '0' is not a number in (0, 100]");
  EXPECT_EQ(problem("triangulate.robust_ratio=0.5"),
            "--set triangulate.robust_ratio=0.5: triangulate.robust_ratio: '0.5' is not a number in [1, 1000000]");
  EXPECT_EQ(problem("triangulate.robust_views=maybe"),
            "--set triangulate.robust_views=maybe: triangulate.robust_views: 'maybe' is not true or false (also "
            "yes/no, on/off, 1/0)");
  EXPECT_EQ(problem("metrics.min_gt_score=2"),
            "--set metrics.min_gt_score=2: metrics.min_gt_score: '2' is not a number in [0, 1]");
  EXPECT_EQ(problem("metrics.legacy_pcp_actors=1000000000"),
            "--set metrics.legacy_pcp_actors=1000000000: metrics.legacy_pcp_actors: '1000000000' is not an integer in "
            "[1, 10000]");
  // Values set in code get the same words from Check().
  engine::Config in_code;
  in_code.triangulator.filter.min_match_score = 1.5;
  EXPECT_EQ(test::ConfigErrorOf([&] { engine::CheckConfig(in_code); }),
            "filter.min_match_score: '1.5' is not a number in [0, 1]");
  // Every option is described.
  for (const engine::ConfigOptionInfo& option : engine::ConfigOptions()) {
    EXPECT_FALSE(option.spec.help.empty()) << option.key;
    EXPECT_FALSE(option.type.empty()) << option.key;
  }
}

// Settings changed from their defaults that have no effect; a default that an ablation turns
// useless is not one (track.enabled=false warned about clip_speed.enabled=true, set by nobody).
TEST(Config, SettingsWithoutEffectAreWarnings) {
  engine::Config c;
  EXPECT_TRUE(engine::ConfigWarnings(c).empty());
  engine::ApplyConfigOverride("track.enabled=false", &c);
  EXPECT_TRUE(engine::ConfigWarnings(c).empty());
  engine::ApplyConfigOverride("bone_lengths.enabled=true", &c);
  engine::ApplyConfigOverride("smooth.mode=causal", &c);
  const std::vector<std::string> warnings = engine::ConfigWarnings(c);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], "bone_lengths.enabled=true has no effect with track.enabled=false (it needs track ids)");
  EXPECT_EQ(warnings[1], "smooth.mode=causal has no effect with track.enabled=false (it needs track ids)");
  EXPECT_NO_THROW(engine::CheckConfig(c));  // not an error
  const test::CommandResult r = test::RunRpt("demo --frames 3 --set track.enabled=false --set smooth.mode=causal");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: smooth.mode=causal has no effect with track.enabled=false"), std::string::npos)
      << r.err;
  EXPECT_EQ(test::RunRpt("demo --frames 3").err.find("warning"), std::string::npos);
  EXPECT_EQ(test::RunRpt("demo --frames 3 --set track.enabled=false").err.find("warning"), std::string::npos);
  // Settings of steps that are off; refine.one_view_joints is on by default, so refine.enabled=false
  // alone says nothing.
  engine::Config off;
  engine::ApplyConfigOverride("refine.enabled=false", &off);
  EXPECT_TRUE(engine::ConfigWarnings(off).empty());
  engine::ApplyConfigOverride("single_view.track_assist=true", &off);
  engine::ApplyConfigOverride("single_view.ground_prior=true", &off);
  EXPECT_EQ(engine::ConfigWarnings(off),
            (std::vector<std::string>{"single_view.track_assist=true has no effect with single_view.enabled=false",
                                      "single_view.ground_prior=true has no effect with single_view.enabled=false"}));
  engine::Config untracked;
  engine::ApplyConfigOverride("single_view.enabled=true", &untracked);
  engine::ApplyConfigOverride("single_view.track_assist=true", &untracked);
  engine::ApplyConfigOverride("track.enabled=false", &untracked);
  EXPECT_EQ(engine::ConfigWarnings(untracked),
            (std::vector<std::string>{
                "single_view.track_assist=true has no effect with track.enabled=false (it needs track ids)"}));
}

TEST(Config, DocsOptionTablesAreGeneratedFromTheMetadata) {
  const std::filesystem::path docs = std::filesystem::path(RPT_SOURCE_DIR) / "docs" / "options.md";
  EXPECT_EQ(test::ReadAll(docs), engine::ConfigMarkdown())
      << "docs/options.md differs from the options' metadata; regenerate it with "
         "`./build/rpt config --markdown > docs/options.md`";
  const test::CommandResult r = test::RunRpt("config --markdown");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, engine::ConfigMarkdown());
  EXPECT_NE(r.out.find("| `prefilter.max_pairs_per_person` | `30` | integer in [0, 1000000000] |  |"),
            std::string::npos);
  EXPECT_NE(r.out.find("| `metrics.matching` | `greedy` | greedy \\| hungarian |"), std::string::npos);
  EXPECT_NE(r.out.find("| `metrics.evaluated_joints` | (empty) | list of names |"), std::string::npos);
}

// The codec writes numbers as JSON does, so `rpt config --dump` and GetConfigOption agree.
TEST(OptionCodec, NumbersAreWrittenAsNlohmannJsonWritesThem) {
  for (const double value : {0.1, 25.0, -2.0, 0.0, 1e15, 1e16, 123456789012345.0, 1e-5, 0.0001, -1.25e-7, 6.02214076e23,
                             1.0 / 3.0, 5e-324, 1.7976931348623157e308}) {
    EXPECT_EQ(FormatNumber(value), nlohmann::json(value).dump());
  }
}

// --set, a config file and --param read a value through the one codec (core/option_codec.h): the
// same text is accepted with the same result or refused with the same problem. CodecParams is a
// dataset-params struct with the key names and OptionSpecs of six config options, one per type.
struct CodecParams {
  bool enabled = true;
  int top_k = 3;
  double min_match_score = 0.7;
  JointNames core_joints;
  ScoreMode mode = ScoreMode::kCombined;
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();
};

const char* const kCodecKeys[] = {"prefilter.enabled",       "merge.top_k", "filter.min_match_score",
                                  "triangulate.core_joints", "score.mode",  "room_check.size_m"};

OptionSpec SpecOf(const std::string& key) {
  for (const engine::ConfigOptionInfo& option : engine::ConfigOptions()) {
    if (option.key == key) return option.spec;
  }
  ADD_FAILURE() << "no option " << key;
  return {};
}

template <class Visitor, OptionsOf<CodecParams> Self>
void VisitFields(Visitor& v, Self& o) {
  v("enabled", o.enabled, SpecOf(kCodecKeys[0]));
  v("top_k", o.top_k, SpecOf(kCodecKeys[1]));
  v("min_match_score", o.min_match_score, SpecOf(kCodecKeys[2]));
  v("core_joints", o.core_joints, SpecOf(kCodecKeys[3]));
  v("mode", o.mode, SpecOf(kCodecKeys[4]));
  v("size_m", o.size_m, SpecOf(kCodecKeys[5]));
}

// The value of `name` in `params` as text.
std::string ParamValue(const CodecParams& params, const std::string& name) {
  std::string text;
  auto visitor = [&](std::string_view key, const auto& field, const OptionSpec&) {
    if (key == name) text = FormatOption(field);
  };
  VisitFields(visitor, params);
  return text;
}

struct Outcome {
  std::string error;  // "" when accepted
  std::string value;  // the value read, as text
};

Outcome BySet(const std::string& key, const std::string& text) {
  engine::Config c;
  try {
    engine::ApplyConfigOverride(key + "=" + text, &c);
  } catch (const ConfigError& e) {
    return {e.what(), ""};
  }
  return {"", engine::GetConfigOption(c, key)};
}

Outcome ByParam(const std::string& name, const std::string& text) {
  DatasetRequest request;
  request.params[name] = text;
  try {
    return {"", ParamValue(ParseDatasetParams<CodecParams>("codec", request), name)};
  } catch (const ConfigError& e) {
    return {e.what(), ""};
  }
}

Outcome ByFile(const std::string& key, const nlohmann::json& value, const std::filesystem::path& path) {
  const std::string section = key.substr(0, key.find('.'));
  std::ofstream(path) << nlohmann::json{{section, {{key.substr(section.size() + 1), value}}}}.dump();
  engine::Config c;
  try {
    engine::LoadConfigFile(path, &c);
  } catch (const ConfigError& e) {
    return {e.what(), ""};
  }
  return {"", engine::GetConfigOption(c, key)};
}

TEST(OptionCodec, SetParamAndConfigFilesReadValuesAlike) {
  struct Case {
    int option;           // index into kCodecKeys
    std::string text;     // as typed
    std::string problem;  // "" when accepted
    std::string value;    // the value read, as text
  };
  const std::string not_bool = " is not true or false (also yes/no, on/off, 1/0)";
  const std::string not_int = " is not an integer in [0, 1000000]";
  const std::string not_unit = " is not a number in [0, 1]";
  const std::string not_names = " is not a list of names ([\"a\", \"b\"] or a,b)";
  const std::string not_vector = " is not three numbers [x, y, z] (or x,y,z)";
  const std::vector<Case> cases = {
      {0, "true", "", "true"},
      {0, "yes", "", "true"},
      {0, "off", "", "false"},
      {0, "0", "", "false"},
      {0, " on ", "", "true"},
      {0, "maybe", "'maybe'" + not_bool, ""},
      {0, "", "''" + not_bool, ""},
      {0, "True", "'True'" + not_bool, ""},
      {1, "7", "", "7"},
      {1, "+7", "", "7"},
      {1, "1e3", "'1e3'" + not_int, ""},
      {1, "3.0", "'3.0'" + not_int, ""},
      {1, "", "''" + not_int, ""},
      {1, "-1", "'-1'" + not_int, ""},
      {1, "1000001", "'1000001'" + not_int, ""},
      {1, "nan", "'nan'" + not_int, ""},
      {2, "0.5", "", "0.5"},
      {2, "1e-3", "", "0.001"},
      {2, "1", "", "1.0"},
      {2, "1.5", "'1.5'" + not_unit, ""},
      {2, "NaN", "'NaN'" + not_unit, ""},
      {2, "nan", "'nan'" + not_unit, ""},
      {2, "inf", "'inf'" + not_unit, ""},
      {2, "", "''" + not_unit, ""},
      {3, " a , b , c ", "", "a,b,c"},  // three: a pose needs triangulate.min_core_joints (3) of them
      {3, "", "", ""},
      {3, "[\"a\", \"b\", \"c\"]", "", "a,b,c"},
      {3, "a,,b,c,", "", "a,b,c"},
      {3, "[1,2", "'[1,2'" + not_names, ""},
      {3, "[1, 2]", "'[1, 2]'" + not_names, ""},
      {4, "triangulation", "", "triangulation"},
      {4, "combind", "'combind' is not one of combined, reprojection, triangulation (did you mean 'combined'?)", ""},
      {4, "", "'' is not one of combined, reprojection, triangulation", ""},
      {5, "8,8,3", "", "8.0,8.0,3.0"},
      {5, "[8, 8, 3.5]", "", "8.0,8.0,3.5"},
      {5, "1,2", "'1,2'" + not_vector, ""},
      {5, "[1,2", "'[1,2'" + not_vector, ""},
      {5, "1,nan,3", "'1,nan,3'" + not_vector, ""},
  };
  const auto path = std::filesystem::temp_directory_path() / "rpt_config_codec.json";
  for (const Case& c : cases) {
    const std::string key = kCodecKeys[c.option];
    const std::string name = key.substr(key.find('.') + 1);
    SCOPED_TRACE(key + "=" + c.text);
    const Outcome set = BySet(key, c.text);
    const Outcome param = ByParam(name, c.text);
    const Outcome file = ByFile(key, c.text, path);  // the text as a JSON string
    if (c.problem.empty()) {
      EXPECT_EQ(set.error, "");
      EXPECT_EQ(param.error, "");
      EXPECT_EQ(file.error, "");
      EXPECT_EQ(set.value, c.value);
      EXPECT_EQ(param.value, c.value);
      EXPECT_EQ(file.value, c.value);
    } else {
      EXPECT_EQ(set.error, "--set " + key + "=" + c.text + ": " + key + ": " + c.problem);
      EXPECT_EQ(param.error, "--param " + name + "=" + c.text + ": codec." + name + ": " + c.problem);
      EXPECT_EQ(file.error,
                path.string() + ": /" + key.substr(0, key.find('.')) + "/" + name + ": " + key + ": " + c.problem);
    }
  }
  // JSON values other than strings are read as JSON writes them: the same as typing that text.
  const std::vector<std::pair<int, nlohmann::json>> json_values = {
      {0, true},
      {0, 1},
      {0, 2},
      {1, 7},
      {1, 3.0},
      {1, 1e3},
      {2, 1},
      {2, -0.5},
      {2, false},
      {3, nlohmann::json::array({"a", "b", "c"})},
      {3, nlohmann::json::array({1, 2})},
      {5, nlohmann::json::array({8, 8, 3})},
      {5, nlohmann::json::array({8, "8", 3})},
  };
  for (const auto& [option, value] : json_values) {
    const std::string key = kCodecKeys[option];
    SCOPED_TRACE(key + " = " + value.dump());
    const Outcome set = BySet(key, value.dump());
    const Outcome file = ByFile(key, value, path);
    EXPECT_EQ(file.value, set.value);
    EXPECT_EQ(file.error.empty(), set.error.empty());
    if (!set.error.empty()) {
      const std::string problem = set.error.substr(set.error.find(key + ": ") + key.size() + 2);
      EXPECT_EQ(file.error, path.string() + ": /" + key.substr(0, key.find('.')) + "/" + key.substr(key.find('.') + 1) +
                                ": " + key + ": " + problem);
    }
  }
  EXPECT_EQ(ByFile(kCodecKeys[1], 3.0, path).error,
            path.string() + ": /merge/top_k: merge.top_k: '3.0' is not an integer in [0, 1000000]");
  EXPECT_EQ(ByFile(kCodecKeys[0], 1, path).value, "true");
  // An object or null is no value (as text it could pass for a name).
  EXPECT_EQ(ByFile(kCodecKeys[3], nlohmann::json::object({{"a", 1}}), path).error,
            path.string() +
                ": /triangulate/core_joints: triangulate.core_joints: '{\"a\":1}' is not a value (a string, "
                "number, boolean or list)");
  EXPECT_EQ(ByFile(kCodecKeys[1], nullptr, path).error,
            path.string() + ": /merge/top_k: merge.top_k: 'null' is not a value (a string, number, boolean or list)");
}

}  // namespace
}  // namespace rpt::cli
