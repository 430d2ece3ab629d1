// SPDX-License-Identifier: MIT
#include "cli/config.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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

TEST(Config, SetReachesTriangulatorAndMetricOptions) {
  Config c;
  ApplyConfigOverride("prefilter.enabled=false", &c);
  ApplyConfigOverride("merge.top_k=0", &c);
  ApplyConfigOverride("score.mode=triangulation", &c);
  ApplyConfigOverride("triangulate.core_joints=shoulder_left, hip_left ,knee_left", &c);
  ApplyConfigOverride("room_check.size_m=8,8,3", &c);
  ApplyConfigOverride("metrics.matching=hungarian", &c);
  ApplyConfigOverride("metrics.evaluated_joints=nose,wrist_left", &c);
  EXPECT_FALSE(c.triangulator.prefilter.enabled);
  EXPECT_EQ(c.triangulator.merge.top_k, 0);
  EXPECT_EQ(c.triangulator.score.mode, ScoreMode::kTriangulationOnly);
  EXPECT_EQ(c.triangulator.triangulate.core_joints, (JointNames{"shoulder_left", "hip_left", "knee_left"}));
  EXPECT_EQ(c.triangulator.room_check.size_m, Eigen::Vector3d(8, 8, 3));
  EXPECT_EQ(c.metrics.matching, metrics::MatchingMode::kHungarian);
  EXPECT_EQ(c.metrics.evaluated_joints, (JointNames{"nose", "wrist_left"}));
}

TEST(Config, EveryOptionRoundTripsThroughTextAndJson) {
  const Config defaults;
  for (const ConfigOptionInfo& option : ConfigOptions()) {
    Config c;
    SetConfigOption(option.key, GetConfigOption(defaults, option.key), "test", &c);
    EXPECT_EQ(GetConfigOption(c, option.key), GetConfigOption(defaults, option.key)) << option.key;
  }
  Config changed;
  ApplyConfigOverride("group.min_group_size=3", &changed);
  ApplyConfigOverride("metrics.alignment=pelvis", &changed);
  const auto path = WriteTemp("rpt_config_roundtrip.json", DumpConfig(changed, /*with_comments=*/false));
  Config loaded;
  LoadConfigFile(path, &loaded);
  EXPECT_EQ(loaded.triangulator.group.min_group_size, 3);
  EXPECT_EQ(loaded.metrics.alignment, metrics::Alignment::kPelvis);
  EXPECT_EQ(DumpConfig(loaded, false), DumpConfig(changed, false));
}

TEST(Config, UnknownKeysAndBadValuesAreErrorsNamingThePlace) {
  Config c;
  auto message = [&](const std::string& assignment) {
    try {
      ApplyConfigOverride(assignment, &c);
      CheckConfig(c);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("prefilter.enabld=true").find("unknown option 'prefilter.enabld'"), std::string::npos);
  EXPECT_NE(message("filter.nothing=1").find("filter"), std::string::npos);
  EXPECT_NE(message("prefilter.enabled=maybe").find("expected true or false"), std::string::npos);
  EXPECT_NE(message("merge.top_k=2.5").find("integer"), std::string::npos);
  EXPECT_NE(message("triangulate.method=svd").find("midpoint|dlt"), std::string::npos);
  EXPECT_NE(message("room_check.size_m=1,2").find("[x, y, z]"), std::string::npos);
  EXPECT_NE(message("no_equals_sign").find("section.key=value"), std::string::npos);
  c = Config{};
  EXPECT_NE(message("filter.min_match_score=1.5").find("filter.min_match_score"), std::string::npos);

  const auto unknown = WriteTemp("rpt_config_unknown.json", R"({"merge": {"top_k": 2, "topk": 3}})");
  try {
    LoadConfigFile(unknown, &c);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("rpt_config_unknown.json"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("merge.topk"), std::string::npos);
  }
  const auto wrong_type = WriteTemp("rpt_config_type.json", R"({"track": {"enabled": "yes"}})");
  try {
    LoadConfigFile(wrong_type, &c);
    FAIL();
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/track/enabled"), std::string::npos);
  }
  EXPECT_THROW(LoadConfigFile("/nonexistent/rpt.json", &c), InputError);
}

TEST(ConfigCommand, DumpIsLoadableAndOverridesApply) {
  const test::CommandResult dump = test::RunRpt("config --dump --json --set track.enabled=false");
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  const auto path = WriteTemp("rpt_config_dump.json", dump.out);
  Config c;
  LoadConfigFile(path, &c);
  EXPECT_FALSE(c.triangulator.track.enabled);
  const test::CommandResult commented = test::RunRpt("config --dump");
  EXPECT_NE(commented.out.find("// bool"), std::string::npos);
  EXPECT_EQ(test::RunRpt("config --set nope.nope=1").exit_code, 2);
  EXPECT_EQ(test::RunRpt("demo --frames 5 --set filter.min_match_score=7").exit_code, 2);
}

}  // namespace
}  // namespace rpt::cli
