// SPDX-License-Identifier: MIT
// rpt eval's diagnostics end to end: step counts in the outputs, and each warning firing on a
// broken generic labels + detections pair written here (from a converted synthetic scene) while
// a clean run and the real MVOR fixture stay quiet (except what honestly applies to MVOR).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/pipeline/steps.h"
#include "tests/cli/cli_test_util.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

Json ReadJson(const fs::path& path) { return Json::parse(test::ReadAll(path)); }

std::vector<std::string> Codes(const Json& summary) {
  std::vector<std::string> codes;
  for (const Json& w : summary.at("warnings")) codes.push_back(w.at("code").get<std::string>());
  return codes;
}

long Count(const std::vector<std::string>& codes, const std::string& code) {
  return std::count(codes.begin(), codes.end(), code);
}

long WarningLines(const std::string& err) {
  long n = 0;
  for (size_t at = err.find("warning: "); at != std::string::npos; at = err.find("warning: ", at + 1)) ++n;
  return n;
}

// A generic labels + detections pair of a 60-frame synthetic scene (5 cameras cam0..cam4, 4
// walking people, 25 fps), edited by `edit_labels` / `edit_detections`, then evaluated.
struct Case {
  test::CommandResult result;
  Json summary;
};

Case EvalEdited(const std::string& name, const std::function<void(Json*)>& edit_labels,
                const std::function<void(Json*)>& edit_detections) {
  const fs::path dir = test::TempDir("diag_" + name);
  const test::CommandResult converted =
      test::RunRpt("convert --dataset synthetic --param frames=60 --labels-out " + (dir / "labels.json").string() +
                   " --detections-out " + (dir / "detections.json").string());
  EXPECT_EQ(converted.exit_code, 0) << converted.err;
  Json labels = ReadJson(dir / "labels.json");
  Json detections = ReadJson(dir / "detections.json");
  if (edit_labels) edit_labels(&labels);
  if (edit_detections) edit_detections(&detections);
  std::ofstream(dir / "labels.json") << labels.dump();
  std::ofstream(dir / "detections.json") << detections.dump();
  Case c;
  c.result = test::RunRpt("eval --labels " + (dir / "labels.json").string() + " --detections " +
                          (dir / "detections.json").string() + " --out " + (dir / "out").string() + " --quiet");
  EXPECT_EQ(c.result.exit_code, 0) << c.result.err;
  if (fs::exists(dir / "out" / "summary.json")) c.summary = ReadJson(dir / "out" / "summary.json");
  fs::remove_all(dir);
  return c;
}

TEST(EvalDiagnostics, CleanSyntheticRunHasCountsAndNoWarning) {
  const fs::path out = test::TempDir("diag_clean");
  const test::CommandResult r =
      test::RunRpt("eval --dataset synthetic --simulate --param frames=60 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.find("warning:"), std::string::npos) << r.err;
  EXPECT_NE(r.out.find("count / frame"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("estimated detection noise"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("frame shift (detections of frame f vs GT of frame f+k): none"), std::string::npos) << r.out;
  const Json summary = ReadJson(out / "summary.json");
  EXPECT_TRUE(summary.at("warnings").empty()) << summary["warnings"].dump();
  const Json& counts = summary.at("step_count_per_frame");
  ASSERT_EQ(counts.size(), static_cast<size_t>(kNumSteps)) << "one count per step (core/pipeline/steps.h)";
  EXPECT_NEAR(counts.at("merge").get<double>(), 4.0, 0.2) << "4 people per frame";
  EXPECT_GT(counts.at("make_pairs").get<double>(), counts.at("merge").get<double>());
  EXPECT_TRUE(summary.at("counter_per_frame").contains("filled_joints"));
  EXPECT_TRUE(summary.contains("detection_noise_m"));
  ASSERT_EQ(summary.at("data_checks").size(), 1u);
  EXPECT_TRUE(summary["data_checks"][0]["frame_shift"]["tested"].get<bool>());
  const std::string steps = test::ReadAll(out / "steps.csv");
  EXPECT_EQ(std::count(steps.begin(), steps.end(), '\n'), kNumSteps + 1) << "header and one row per step\n" << steps;
  EXPECT_EQ(steps.rfind("step,items,count_per_frame,time_us_median,time_us_mean\n", 0), 0u) << steps;
  fs::remove_all(out);
}

// Every number of summary.json (eval's and triangulate's) has its unit in "units": only the
// headline columns had one (detection_noise_m, step_time_us_median, ... had none).
TEST(EvalDiagnostics, EveryNumberOfTheSummaryHasAUnit) {
  const fs::path dir = test::TempDir("diag_units");
  for (const std::string command : {"eval", "triangulate"}) {
    const test::CommandResult r = test::RunRpt(command + " --dataset synthetic --param frames=20 --quiet --out " +
                                               (dir / command).string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json summary = ReadJson(dir / command / "summary.json");
    const Json& units = summary.at("units");
    for (const auto& [key, value] : summary.items()) {
      if (key == "units" || key == "run_id" || key == "evaluated" || key == "warnings" || key == "data_checks" ||
          key == "per_sequence" || value.is_null()) {
        continue;
      }
      EXPECT_TRUE(units.contains(key)) << command << ": " << key;
    }
  }
  fs::remove_all(dir);
}

// Identity switches against the GT's ids (metrics/identity_counts.h): the 4 walking people keep
// their tracks over the 60 frames; with the GT ids of persons 0 and 1 swapped from frame 30 on,
// each of the two is matched to the other's track once: 2 switches. MVOR's person_id numbers the
// persons of a frame: no identity counts there.
TEST(EvalDiagnostics, IdentitySwitchesAgainstTheGtIds) {
  const Case kept = EvalEdited("ids_kept", nullptr, nullptr);
  EXPECT_EQ(kept.summary.at("gt_identities"), 4);
  EXPECT_EQ(kept.summary.at("gt_identities_matched"), 4);
  EXPECT_EQ(kept.summary.at("track_ids"), 4);
  EXPECT_EQ(kept.summary.at("id_switches"), 0);
  EXPECT_EQ(kept.summary.at("units").at("id_switches"), "count");
  EXPECT_NE(kept.result.out.find("tracking: 4 track ids for 4 GT persons (4 of them matched), 0 identity switches over 240 matches"),
            std::string::npos)
      << kept.result.out;
  const Case swapped = EvalEdited("ids_swapped", [](Json* labels) {
    for (size_t f = 30; f < labels->size(); ++f) {
      Json& ids = (*labels)[f]["bodyids"];
      std::swap(ids[0], ids[1]);
    }
  }, nullptr);
  EXPECT_EQ(swapped.summary.at("id_switches"), 2);
  EXPECT_EQ(swapped.summary.at("gt_identities"), 4);
  const fs::path root = test::SharedDataDir() / "mvor";
  if (!fs::exists(root)) return;
  const fs::path out = test::TempDir("diag_ids_mvor");
  const test::CommandResult r =
      test::RunRpt("eval --dataset mvor --root " + root.string() + " --quiet --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(ReadJson(out / "summary.json").contains("id_switches"));
  EXPECT_EQ(r.out.find("tracking:"), std::string::npos) << r.out;
  // Converted, its ids are written as none (they were read back as identities: 668 switches).
  const test::CommandResult converted = test::RunRpt("convert --dataset mvor --root " + root.string() + " --labels-out " +
                                                     (out / "labels.json").string() + " --detections-out " +
                                                     (out / "detections.json").string());
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  for (const Json& label : ReadJson(out / "labels.json")) {
    for (const Json& id : label.value("bodyids", Json::array())) ASSERT_EQ(id, -1) << label.at("id");  // or none written
  }
  const test::CommandResult again = test::RunRpt("eval --labels " + (out / "labels.json").string() + " --detections " +
                                                 (out / "detections.json").string() +
                                                 " --set metrics.evaluated_joints=shoulder_left,shoulder_right,hip_left,"
                                                 "hip_right --quiet --out " + (out / "run").string());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.out.find("tracking:"), std::string::npos) << again.out;
  fs::remove_all(out);
}

// Speed clipping that moves many joints (fast motion against clip_speed.max_speed_m_s) is said,
// with the option and its value: people walking 0.6-1.5 m/s against 0.5 m/s; not at the default.
TEST(EvalDiagnostics, ManyJointsSpeedClippedAreSaid) {
  const Case kept = EvalEdited("clip_default", nullptr, nullptr);
  EXPECT_EQ(Count(Codes(kept.summary), "speed_clipped"), 0) << kept.result.err;
  const fs::path out = test::TempDir("diag_clip");
  const test::CommandResult r = test::RunRpt("eval --dataset synthetic --param frames=60 --set clip_speed.max_speed_m_s=0.5 "
                                             "--quiet --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(Count(Codes(ReadJson(out / "summary.json")), "speed_clipped"), 1);
  EXPECT_NE(r.err.find("of the joints output were moved by speed clipping"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("clip_speed.max_speed_m_s = 0.5 m/s"), std::string::npos) << r.err;
  fs::remove_all(out);
}

// Labels without 3D persons: said, not shown as a triangulator whose every prediction is Invalid.
TEST(EvalDiagnostics, LabelsWithoutGroundTruthAreSaid) {
  const Case c = EvalEdited("no_gt", [](Json* labels) {
    for (Json& label : *labels) {
      label["bodies3D"] = Json::array();
      label.erase("bodyids");
    }
  }, nullptr);
  const std::vector<std::string> codes = Codes(c.summary);
  EXPECT_EQ(codes, std::vector<std::string>{"no_ground_truth"}) << c.result.err;
  EXPECT_NE(c.result.err.find("warning: no ground truth: the input has no 3D GT person in any of its 60 frames, so every "
                              "one of the "),
            std::string::npos)
      << c.result.err;
  EXPECT_NE(c.result.err.find("`rpt triangulate`"), std::string::npos) << c.result.err;
}

TEST(EvalDiagnostics, JsonOutputCarriesTheWarnings) {
  const fs::path out = test::TempDir("diag_json");
  const test::CommandResult r =
      test::RunRpt("eval --dataset synthetic --param frames=30 --out " + out.string() + " --json --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json summary = Json::parse(r.out);
  EXPECT_TRUE(summary.at("warnings").is_array());
  EXPECT_TRUE(summary.contains("step_count_per_frame"));
  // The run and its folder, as summary.json and triangulate --json have them.
  EXPECT_EQ(summary.at("run_id"), ReadJson(out / "summary.json").at("run_id"));
  EXPECT_EQ(summary.at("output"), out.string());
  fs::remove_all(out);
}

// --loss-table: printed, in losses.csv and summary.json (also with --json); a later run without it
// leaves no table of the earlier run in the folder.
TEST(EvalDiagnostics, LossTableIsPrintedAndWrittenOnlyWhenAsked) {
  const fs::path out = test::TempDir("diag_losses");
  const std::string eval = "eval --dataset synthetic --simulate --param frames=30 --quiet --out " + out.string();
  const test::CommandResult r = test::RunRpt(eval + " --loss-table");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("where the GT persons are lost"), std::string::npos) << r.out;
  const Json summary = ReadJson(out / "summary.json");
  const Json& table = summary.at("loss_table");
  const long gt = table.at("gt_persons").get<long>();
  EXPECT_EQ(gt, 120) << "4 people x 30 frames";
  long sum = 0;
  for (const auto& [key, persons] : table.at("categories").items()) sum += persons.get<long>();
  EXPECT_EQ(sum, gt);
  EXPECT_EQ(table.at("categories").size(), 7u);
  const std::string csv = test::ReadAll(out / "losses.csv");
  EXPECT_EQ(csv.rfind("category,detail,persons,percent_of_gt\nfound,,", 0), 0u) << csv;
  EXPECT_NE(csv.find("\nall,,120,100.00\n"), std::string::npos) << csv;
  // The PCP parts (10 per GT person here) and the joint references, printed as summary.json has them.
  const Json& parts = table.at("parts");
  EXPECT_EQ(parts.at("evaluated").get<long>(), 10 * gt);
  char line[120];
  std::snprintf(line, sizeof line, "PCP parts: %ld evaluated, %ld wrong (PCP %.2f %%)\n", parts.at("evaluated").get<long>(),
                parts.at("wrong").get<long>(), summary.at("pcp").get<double>());
  EXPECT_NE(r.out.find(line), std::string::npos) << r.out << "\nexpected: " << line;
  const Json& joints = table.at("joint_references");
  EXPECT_GT(joints.at("joints").get<long>(), 0);
  std::snprintf(line, sizeof line, "  output %.1f, all those views fitted", joints.at("output_mm").get<double>());
  EXPECT_NE(r.out.find(line), std::string::npos) << r.out << "\nexpected: " << line;

  const test::CommandResult json = test::RunRpt(eval + " --loss-table --json");
  ASSERT_EQ(json.exit_code, 0) << json.err;
  EXPECT_EQ(Json::parse(json.out).at("loss_table").at("gt_persons").get<long>(), 120);

  const test::CommandResult plain = test::RunRpt(eval);
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_EQ(plain.out.find("where the GT persons are lost"), std::string::npos) << plain.out;
  EXPECT_FALSE(fs::exists(out / "losses.csv"));
  EXPECT_FALSE(ReadJson(out / "summary.json").contains("loss_table"));
  fs::remove_all(out);
}

TEST(EvalDiagnostics, EmptyCameraIsNamed) {
  const Case c = EvalEdited("empty_camera", nullptr, [](Json* d) {
    for (Json& frame : (*d)["frames"]) {
      for (Json& view : frame["views"]) {
        if (view["camera"] == "cam1") view["poses"] = Json::array();
      }
    }
  });
  EXPECT_EQ(Codes(c.summary), std::vector<std::string>{"camera_without_detections"}) << c.result.err;
  EXPECT_NE(c.result.err.find("warning: synthetic, camera cam1: no detections in any of the 60 frames"),
            std::string::npos)
      << c.result.err;
  EXPECT_EQ(WarningLines(c.result.err), 1);
}

TEST(EvalDiagnostics, DetectionsShiftedByThreeFrames) {
  // The detections stored under frame f are those of frame f + 3.
  const Case c = EvalEdited("shifted", nullptr, [](Json* d) {
    Json& frames = (*d)["frames"];
    std::vector<std::string> ids;
    for (const Json& frame : frames) ids.push_back(frame["id"]);
    Json shifted = Json::array();
    for (size_t i = 3; i < frames.size(); ++i) {
      Json frame = frames[i];
      frame["id"] = ids[i - 3];
      shifted.push_back(frame);
    }
    frames = shifted;
  });
  const std::vector<std::string> codes = Codes(c.summary);
  EXPECT_EQ(Count(codes, "detections_frame_shifted"), 1) << c.result.err;
  EXPECT_NE(c.result.err.find("fit the GT of frame f+3"), std::string::npos) << c.result.err;
  EXPECT_EQ(c.summary["data_checks"][0]["frame_shift"]["best_shift"], 3);
  for (const std::string& code : codes) {
    EXPECT_TRUE(code == "detections_frame_shifted") << "nothing else is wrong: " << c.result.err;
  }
}

// One camera's detections 6 frames ahead of the others' (its frame f holds what it saw at f + 6):
// named with the offset (engine/camera_sync_check.h), which the shift of all detections against
// the GT cannot see.
TEST(EvalDiagnostics, OneCameraSixFramesAheadIsNamed) {
  const Case c = EvalEdited("camera_sync", nullptr, [](Json* d) {
    Json& frames = (*d)["frames"];
    const Json original = frames;
    for (size_t i = 0; i < frames.size(); ++i) {
      for (Json& view : frames[i]["views"]) {
        if (view["camera"] != "cam2") continue;
        view["poses"] = Json::array();
        if (i + 6 >= original.size()) continue;
        for (const Json& other : original[i + 6]["views"]) {
          if (other["camera"] == "cam2") view["poses"] = other["poses"];
        }
      }
    }
  });
  const std::vector<std::string> codes = Codes(c.summary);
  EXPECT_EQ(Count(codes, "camera_sync"), 1) << c.result.err;
  EXPECT_NE(c.result.err.find("warning: synthetic, camera 'cam2': its detections agree best with the other cameras' of "
                              "about "),
            std::string::npos)
      << c.result.err;
  EXPECT_NE(c.result.err.find(" later (epipolar distance to 4 cameras"), std::string::npos) << c.result.err;
  EXPECT_EQ(Count(codes, "detections_frame_shifted"), 0) << c.result.err;
}

TEST(EvalDiagnostics, WrongCameraRotation) {
  // cam2 turned by 0.2 rad (11 degrees) about its vertical image axis in every label.
  const Case c = EvalEdited("rotation", [](Json* labels) {
    const double a = 0.2, ca = std::cos(a), sa = std::sin(a);
    for (Json& label : *labels) {
      for (Json& camera : label["cameras"]) {
        if (camera["name"] != "cam2") continue;
        const Json R = camera["R"];
        for (int col = 0; col < 3; ++col) {
          const double r0 = R[0][col], r1 = R[1][col], r2 = R[2][col];
          camera["R"][0][col] = ca * r0 + sa * r2;
          camera["R"][1][col] = r1;
          camera["R"][2][col] = -sa * r0 + ca * r2;
        }
      }
    }
  }, nullptr);
  const std::vector<std::string> codes = Codes(c.summary);
  EXPECT_EQ(Count(codes, "gt_far_from_detections"), 1) << c.result.err;
  EXPECT_NE(c.result.err.find("warning: synthetic, camera cam2: projected GT is far from the detections"),
            std::string::npos)
      << c.result.err;
}

TEST(EvalDiagnostics, AllDetectionsFarAway) {
  const Case c = EvalEdited("far", nullptr, [](Json* d) {
    for (Json& frame : (*d)["frames"]) {
      for (Json& view : frame["views"]) {
        for (Json& pose : view["poses"]) {
          for (Json& joint : pose) {
            if (joint.is_array()) joint[0] = joint[0].get<double>() + 400.0;
          }
        }
      }
    }
  });
  const std::vector<std::string> codes = Codes(c.summary);
  EXPECT_EQ(Count(codes, "gt_far_from_detections"), 5) << c.result.err;
}

TEST(EvalDiagnostics, NoPredictionsNameTheStepWhereEverythingIsGone) {
  // Only cam0 keeps its detections: no pair of views, nothing to triangulate.
  const Case c = EvalEdited("one_camera", nullptr, [](Json* d) {
    for (Json& frame : (*d)["frames"]) {
      for (Json& view : frame["views"]) {
        if (view["camera"] != "cam0") view["poses"] = Json::array();
      }
    }
  });
  const std::vector<std::string> codes = Codes(c.summary);
  EXPECT_EQ(Count(codes, "camera_without_detections"), 4) << c.result.err;
  EXPECT_EQ(Count(codes, "no_predictions"), 1) << c.result.err;
  EXPECT_EQ(Count(codes, "low_recall"), 0) << "no_predictions says it all";
  EXPECT_NE(c.result.err.find("nothing is left after step 'make_pairs'"), std::string::npos) << c.result.err;
}

TEST(EvalDiagnostics, ManyFramesWithoutPredictionAndLowRecall) {
  // Detections only in every tenth frame (the others are missing from the file). Tracking
  // returns lost persons for 3 more frames, so 6 of 10 frames have no prediction.
  const Case c = EvalEdited("sparse", nullptr, [](Json* d) {
    Json kept = Json::array();
    const Json& frames = (*d)["frames"];
    for (size_t i = 0; i < frames.size(); ++i) {
      if (i % 10 == 0) kept.push_back(frames[i]);
    }
    (*d)["frames"] = kept;
  });
  const std::vector<std::string> codes = Codes(c.summary);
  EXPECT_EQ(Count(codes, "frames_without_detections"), 1) << c.result.err;
  EXPECT_EQ(Count(codes, "frames_without_predictions"), 1) << c.result.err;
  EXPECT_EQ(Count(codes, "low_recall"), 1) << c.result.err;
  // Plus the input warning that the detections file leaves frames out (counted, not dropped silently).
  EXPECT_NE(c.result.err.find("frames of the input absent from it"), std::string::npos) << c.result.err;
  EXPECT_EQ(WarningLines(c.result.err), static_cast<long>(codes.size()) + 1);
}

TEST(EvalDiagnostics, RealMvorFixtureWarnsOnlyAboutItsResults) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  RPT_REQUIRE_SHARED_DATA("mvor/openpose_kps.json");
  const fs::path out = test::TempDir("diag_mvor");
  const test::CommandResult r =
      test::RunRpt("eval --dataset mvor --root " + test::SharedData("mvor").string() + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json summary = ReadJson(out / "summary.json");
  // The shipped OpenPose detections agree with the GT geometry (no input warning), and with the
  // data-adaptive pair score the run finds about 63 % of the people (Recall@500), above the
  // low-recall warning; the fixed legacy score found 31 % and drew both result warnings.
  EXPECT_TRUE(Codes(summary).empty()) << r.err;
  const test::CommandResult legacy =
      test::RunRpt("eval --dataset mvor --root " + test::SharedData("mvor").string() + " --out " + out.string() +
                   " --set score.scale=fixed --set score.trim_fraction=0 --set filter.min_match_score=0.9"
                   " --set verify.enabled=false");
  ASSERT_EQ(legacy.exit_code, 0) << legacy.err;
  EXPECT_EQ(Codes(ReadJson(out / "summary.json")),
            (std::vector<std::string>{"frames_without_predictions", "low_recall"}))
      << legacy.err;
  ASSERT_EQ(summary.at("data_checks").size(), 4u);
  for (const Json& seq : summary["data_checks"]) {
    EXPECT_FALSE(seq["frame_shift"]["tested"].get<bool>()) << "MVOR frames are minutes apart";
    for (const Json& camera : seq["cameras"]) EXPECT_LT(camera["gt_to_detection_rel_median"].get<double>(), 0.25);
  }
  EXPECT_NE(r.out.find("frames are not continuous"), std::string::npos) << r.out;
  fs::remove_all(out);
}

}  // namespace
}  // namespace rpt
