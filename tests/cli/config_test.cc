// SPDX-License-Identifier: MIT
#include "engine/config.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/config_args.h"
#include "core/errors.h"
#include "tests/cli/cli_test_util.h"

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
  EXPECT_NE(message("prefilter.enabled=maybe").find("expected true or false"), std::string::npos);
  EXPECT_NE(message("merge.top_k=2.5").find("integer"), std::string::npos);
  EXPECT_NE(message("triangulate.method=svd").find("midpoint|dlt"), std::string::npos);
  EXPECT_NE(message("room_check.size_m=1,2").find("[x, y, z]"), std::string::npos);
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
  const auto wrong_type = WriteTemp("rpt_config_type.json", R"({"track": {"enabled": "yes"}})");
  try {
    engine::LoadConfigFile(wrong_type, &c);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/track/enabled"), std::string::npos);
  }
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
  EXPECT_NE(commented.out.find("\"enabled\": true,  // bool: "), std::string::npos);
  EXPECT_NE(commented.out.find("\"max_speed_m_s\": 10.0  // number, m/s, > 0: "), std::string::npos);
  EXPECT_FALSE(nlohmann::json::accept(commented.out));  // clearly not JSON
  EXPECT_EQ(test::RunRpt("config --set nope.nope=1").exit_code, 2);
  EXPECT_EQ(test::RunRpt("demo --frames 5 --set filter.min_match_score=7").exit_code, 2);
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
  engine::ApplyConfigOverride("room_check.size_m=[1,2,3]", &c);
  EXPECT_EQ(c.triangulator.room_check.size_m, Eigen::Vector3d(1, 2, 3));
  auto message = [&c](const std::string& assignment) { return ErrorOf(assignment, &c); };
  // The old trap: a JSON list was taken as the joint names '["a"' and '"b"]'.
  EXPECT_NE(message("triangulate.core_joints=[\"a\",\"b\"").find("is not a JSON list"), std::string::npos);
  EXPECT_NE(message("triangulate.core_joints=[1, 2]").find("expected a list of joint names"), std::string::npos);
  EXPECT_NE(message("room_check.size_m=[1, 2]").find("[x, y, z]"), std::string::npos);
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
  EXPECT_EQ(problem("filter.min_match_score=1.5"), "filter.min_match_score: 1.5 is outside [0, 1]");
  EXPECT_EQ(problem("score.scale_factor=0"), "score.scale_factor: 0 must be > 0");
  EXPECT_EQ(problem("prefilter.ambiguity_ratio=0.5"), "prefilter.ambiguity_ratio: 0.5 is outside [1, 1000]");
  EXPECT_EQ(problem("metrics.pcp_alpha=0"), "metrics.pcp_alpha: 0 must be > 0");
  EXPECT_EQ(problem("metrics.legacy_pcp_actors=0"), "metrics.legacy_pcp_actors: 0 is outside [1, 10000]");
  EXPECT_EQ(problem("metrics.legacy_pcp_alpha=-1"), "metrics.legacy_pcp_alpha: -1 must be > 0");
  EXPECT_EQ(problem("metrics.evaluated_joints=nose,nose"), "metrics.evaluated_joints: lists 'nose' twice");
  // The checks between fields stay.
  EXPECT_EQ(problem("postprocess.max_extent_m=0.1"),
            "postprocess.max_extent_m: 0.1 is below postprocess.min_extent_m (0.2)");
  EXPECT_EQ(problem("bone_lengths.min_observations=60"),
            "bone_lengths.min_observations: 60 is above bone_lengths.window (50)");
  EXPECT_EQ(problem("merge.top_k=0"), "no error");
  // Negative "keep all" values were accepted (issue 10): 0 is the one way to say "keep all".
  EXPECT_EQ(problem("merge.top_k=-1"), "merge.top_k: -1 is outside [0, 1000000]");
  EXPECT_EQ(problem("merge.max_distance_m=-0.5"), "merge.max_distance_m: -0.5 is outside [0, 1000000]");
  EXPECT_EQ(problem("prefilter.max_pairs_per_person=-1"),
            "prefilter.max_pairs_per_person: -1 is outside [0, 1000000000]");
  EXPECT_EQ(problem("triangulate.max_persons_per_view=0"), "triangulate.max_persons_per_view: 0 is outside [1, 100000]");
  EXPECT_EQ(problem("metrics.min_gt_score=2"), "metrics.min_gt_score: 2 is outside [0, 1]");
  EXPECT_EQ(problem("metrics.legacy_pcp_actors=1000000000"),
            "metrics.legacy_pcp_actors: 1000000000 is outside [1, 10000]");
  // Every option is described.
  for (const engine::ConfigOptionInfo& option : engine::ConfigOptions()) {
    EXPECT_FALSE(option.spec.help.empty()) << option.key;
    EXPECT_FALSE(option.type.empty()) << option.key;
  }
}

TEST(Config, SettingsWithoutEffectAreWarnings) {
  engine::Config c;
  EXPECT_TRUE(engine::ConfigWarnings(c).empty());
  engine::ApplyConfigOverride("track.enabled=false", &c);
  engine::ApplyConfigOverride("bone_lengths.enabled=true", &c);
  engine::ApplyConfigOverride("smooth.mode=causal", &c);
  const std::vector<std::string> warnings = engine::ConfigWarnings(c);
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_EQ(warnings[0], "clip_speed.enabled=true has no effect with track.enabled=false (it needs track ids)");
  EXPECT_NE(warnings[1].find("bone_lengths.enabled=true"), std::string::npos);
  EXPECT_NE(warnings[2].find("smooth.mode=causal"), std::string::npos);
  EXPECT_NO_THROW(engine::CheckConfig(c));  // not an error
  const test::CommandResult r = test::RunRpt("demo --frames 3 --set track.enabled=false");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: clip_speed.enabled=true has no effect with track.enabled=false"), std::string::npos)
      << r.err;
  EXPECT_EQ(test::RunRpt("demo --frames 3").err.find("warning"), std::string::npos);
}

TEST(Config, DocsOptionTablesAreGeneratedFromTheMetadata) {
  const std::filesystem::path docs = std::filesystem::path(RPT_SOURCE_DIR) / "docs" / "options.md";
  EXPECT_EQ(test::ReadAll(docs), engine::ConfigMarkdown())
      << "docs/options.md differs from the options' metadata; regenerate it with "
         "`./build/rpt config --markdown > docs/options.md`";
  const test::CommandResult r = test::RunRpt("config --markdown");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, engine::ConfigMarkdown());
  EXPECT_NE(r.out.find("| `prefilter.max_pairs_per_person` | 30 | int |"), std::string::npos);
  EXPECT_NE(r.out.find("| `metrics.matching` | greedy | greedy \\| hungarian |"), std::string::npos);
}

}  // namespace
}  // namespace rpt::cli
