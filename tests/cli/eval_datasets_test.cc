// SPDX-License-Identifier: MIT
// rpt eval end to end on the real fixtures (skipped when ../shared/data is absent) and on
// generic interchange files written by the test.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "datasets/detections.h"
#include "datasets/readers/generic_detections.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/synthetic/synthetic_sequence.h"
#include "tests/cli/cli_test_util.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;


nlohmann::json EvalJson(const std::string& args, const fs::path& out) {
  const test::CommandResult r = test::RunRpt("eval " + args + " --json --quiet --out " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json();
}

TEST(EvalDatasets, ShelfFixtureWithItsOwnCacheAndSimulated) {
  RPT_REQUIRE_SHARED_DATA("shelf/actorsGT.mat");
  const fs::path out = test::TempDir("shelf");
  const std::string root = test::SharedData("shelf").string();
  // The mmpose cache subset is not frame-aligned with the GT subset (datasets.md 3.6): it must run
  // end to end and produce predictions, not good numbers.
  const nlohmann::json cache = EvalJson("--dataset shelf --root " + root + " --param frames=0-2 --param detections=voxelpose", out);
  EXPECT_EQ(cache["frames"], 3);
  EXPECT_EQ(cache["gt_persons"], 6);
  EXPECT_GT(cache["predictions"].get<int>(), 0);
  const nlohmann::json predictions = nlohmann::json::parse(test::ReadAll(out / "predictions.json"));
  EXPECT_EQ(predictions["frames"][0]["id"], "shelf_000000");
  // The clean detector profile: its small errors make a tight bound that catches convention errors.
  const nlohmann::json simulated =
      EvalJson("--dataset shelf --root " + root + " --param frames=0-2 --simulate --detector clean", out);
  EXPECT_EQ(simulated["recall500"], 100.0);
  EXPECT_LT(simulated["mpjpe_mm"].get<double>(), 40.0);
  fs::remove_all(out);
}

// What the metrics leave out is counted in summary.json (docs/metrics.md). On MVOR's shipped
// detections 90 GT-valid joints of matched persons are missing from the predictions, and with
// pelvis alignment 45 matched pairs lack a hip; no GT person is without a valid evaluated joint.
TEST(EvalDatasets, MvorSummaryCountsWhatTheMetricsLeaveOut) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  const fs::path out = test::TempDir("mvor_left_out");
  const std::string input = "--dataset mvor --root " + test::SharedData("mvor").string();
  const nlohmann::json aligned = EvalJson(input + " --set metrics.alignment=pelvis", out);
  EXPECT_EQ(aligned["matches"], 688);
  EXPECT_EQ(aligned["dropped_gt_persons"], 0);
  EXPECT_EQ(aligned["missing_pred_joints"], 90);
  EXPECT_EQ(aligned["unaligned_matches"], 45);
  const nlohmann::json summary = nlohmann::json::parse(test::ReadAll(out / "summary.json"));
  EXPECT_EQ(summary["missing_pred_joints"], 90) << "the file has what --json prints";
  const nlohmann::json absolute = EvalJson(input, out);
  EXPECT_EQ(absolute["missing_pred_joints"], 90);
  EXPECT_EQ(absolute["unaligned_matches"], 0) << "nothing is aligned without metrics.alignment";
  fs::remove_all(out);
}

TEST(EvalDatasets, CampusFixtureEmptyCacheGivesNoPredictions) {
  RPT_REQUIRE_SHARED_DATA("campus/actorsGT.mat");
  const fs::path out = test::TempDir("campus");
  const nlohmann::json j = EvalJson(
      "--dataset campus --root " + test::SharedData("campus").string() + " --param frames=0-2 --param detections=voxelpose", out);
  EXPECT_EQ(j["frames"], 3);
  EXPECT_EQ(j["predictions"], 0) << "the fixture cache has only empty lists";
  EXPECT_EQ(j["recall500"], 0.0);
  fs::remove_all(out);
}

TEST(EvalDatasets, Shelf4daFixtureWithItsOpenPoseDetections) {
  RPT_REQUIRE_SHARED_DATA("shelf/4d_association/gt.txt");
  const fs::path out = test::TempDir("shelf4da");
  const std::string input = "--dataset shelf-4da --root " + test::SharedData("shelf/4d_association").string();
  // Real OpenPose detections assembled by the reader (default params): observed PCP 95.5 %,
  // MPJPE 67 mm, Recall@500 100 %; Invalid is high because the GT annotates only some people.
  const nlohmann::json j = EvalJson(input, out);
  EXPECT_EQ(j["frames"], 301);
  EXPECT_EQ(j["gt_persons"], 510);
  EXPECT_GE(j["recall500"].get<double>(), 99.0);
  EXPECT_GT(j["pcp"].get<double>(), 90.0);
  EXPECT_LT(j["mpjpe_mm"].get<double>(), 80.0);
  const nlohmann::json predictions = nlohmann::json::parse(test::ReadAll(out / "predictions.json"));
  EXPECT_EQ(predictions["frames"][0]["id"], "shelf4da_000000");
  const test::CommandResult text = test::RunRpt("eval " + input + " --quiet --out " + (out / "text").string());
  EXPECT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("1 sequence(s), 301 frames, 5 cameras, 510 GT persons"), std::string::npos) << text.out;
  fs::remove_all(out);
}

TEST(EvalDatasets, PanopticFixtureWithSimulatedDetections) {
  RPT_REQUIRE_SHARED_DATA("panoptic/160906_band1");
  const fs::path out = test::TempDir("panoptic");
  const nlohmann::json j = EvalJson("--dataset panoptic --root " + test::SharedData("panoptic").string() +
                                        " --param sequences=160906_band1 --param every=1 --simulate --detector clean",
                                    out);
  EXPECT_EQ(j["frames"], 20);
  EXPECT_GT(j["recall500"].get<double>(), 99.0);
  EXPECT_LT(j["mpjpe_mm"].get<double>(), 25.0);
  fs::remove_all(out);
}

// A streamed dataset without detections of its own (Panoptic) is refused before anything runs,
// as when it is loaded whole.
TEST(EvalDatasets, StreamedDatasetWithoutDetectionsIsRefused) {
  RPT_REQUIRE_SHARED_DATA("panoptic/160906_band1");
  const fs::path out = test::TempDir("no-detections");
  const test::CommandResult r = test::RunRpt("eval --dataset panoptic --root " + test::SharedData("panoptic").string() +
                                             " --param sequences=160906_band1 --quiet --out " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("sequence 'panoptic/160906_band1' has no 2D detections: pass --detections FILE or --simulate\n"),
            std::string::npos)
      << "Panoptic has no detections of its own to suggest: " << r.err;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  // A reader with its own detections names them (it suggested detections=voxelpose, which MVOR refuses).
  RPT_REQUIRE_SHARED_DATA("mvor");
  const test::CommandResult mvor = test::RunRpt("eval --dataset mvor --root " + test::SharedData("mvor").string() +
                                                " --param detections=none --quiet --out " + out.string());
  EXPECT_EQ(mvor.exit_code, 2);
  EXPECT_NE(mvor.err.find("has no 2D detections: pass --detections FILE or --simulate, or the dataset's own "
                          "(--param detections=openpose)"),
            std::string::npos)
      << mvor.err;
  fs::remove_all(out);
}

TEST(EvalDatasets, ParallelSequencesGiveTheSameMetricsAsOneThread) {
  RPT_REQUIRE_SHARED_DATA("panoptic/160906_band2");
  const fs::path out = test::TempDir("threads");
  const std::string input = "--dataset panoptic --root " + test::SharedData("panoptic").string() +
                            " --param sequences=160906_band1,160906_band2 --param every=1 --simulate";
  nlohmann::json one = EvalJson(input + " --threads 1", out / "one");
  nlohmann::json two = EvalJson(input + " --threads 2", out / "two");
  for (const char* differs :
       {"fps", "frame_time_us_median", "step_time_us_median", "eval_frames_per_s", "run_id", "output"}) {
    one.erase(differs);
    two.erase(differs);
    for (nlohmann::json* j : {&one, &two}) {
      for (nlohmann::json& sequence : (*j)["per_sequence"]) sequence.erase(differs);
    }
  }
  ASSERT_EQ(one["per_sequence"].size(), 2u) << "one row per sequence";
  EXPECT_EQ(one, two);
  nlohmann::json predictions_one = nlohmann::json::parse(test::ReadAll(out / "one" / "predictions.json"));
  nlohmann::json predictions_two = nlohmann::json::parse(test::ReadAll(out / "two" / "predictions.json"));
  predictions_one.erase("run_id");  // each run has its own
  predictions_two.erase("run_id");
  EXPECT_EQ(predictions_one, predictions_two);
  fs::remove_all(out);
}

// Two sequences of 5 cameras: the data check's line says 10 cameras over 2 sequences (it said 10
// cameras, as if of one rig), and which sequences the frame-shift check could not test.
TEST(EvalDatasets, ChecksOverSequencesSayHowManySequences) {
  RPT_REQUIRE_SHARED_DATA("panoptic/160906_band2");
  const fs::path out = test::TempDir("two_sequences");
  const test::CommandResult r = test::RunRpt("eval --dataset panoptic --root " + test::SharedData("panoptic").string() +
                                             " --param sequences=160906_band1,160906_band2 --simulate --out " +
                                             out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("(10 camera(s) over 2 sequences; warning from 0.30)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("frame shift (detections of frame f vs GT of frame f+k): not tested, no frame"),
            std::string::npos)
      << r.out;
  fs::remove_all(out);
}

// The legacy PCP line names the actors its average is over: the Campus fixture's 3 frames label
// actor 1 only (it said "actors 1-3", to be read beside papers' averages of all three).
TEST(EvalDatasets, LegacyPcpNamesTheActorsAveraged) {
  RPT_REQUIRE_SHARED_DATA("campus/actorsGT.mat");
  const fs::path out = test::TempDir("legacy_actors");
  const test::CommandResult r =
      test::RunRpt("eval --dataset campus --root " + test::SharedData("campus").string() +
                   " --param frames=0-2 --simulate --set metrics.legacy_pcp=campus --quiet --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("  legacy PCP (actor 1 of 1-3: the others have no GT here) "), std::string::npos) << r.out;
  fs::remove_all(out);
}

TEST(EvalDatasets, GenericInterchangeFilesWrittenByTheTest) {
  const fs::path dir = test::TempDir("generic");
  synthetic::SceneOptions options;
  options.num_frames = 30;
  options.num_people = 3;
  const synthetic::Scene scene = synthetic::GenerateScene(options);
  const Sequence sequence = synthetic::MakeSyntheticSequence(scene, synthetic::DetectorOptions::Realistic(), 5, "mine");
  WriteLabels(dir / "labels.json", {sequence});
  Detections detections;
  detections.joints = sequence.detection_joints;
  for (const SequenceFrame& f : sequence.frames) {
    FrameDetections frame{f.id, {}, f.views};
    for (const Camera& c : sequence.cameras) frame.cameras.push_back(c.name);
    detections.frames.push_back(frame);
  }
  WriteGenericDetections(dir / "detections.json", detections);
  const nlohmann::json json_run =
      EvalJson("--labels " + (dir / "labels.json").string() + " --detections " + (dir / "detections.json").string(), dir / "out1");
  EXPECT_EQ(json_run["frames"], 30);
  EXPECT_GT(json_run["recall500"].get<double>(), 99.0);
  // The same through an HDF5 cache written by rpt convert.
  const test::CommandResult convert = test::RunRpt("convert --labels " + (dir / "labels.json").string() + " --detections " +
                                                   (dir / "detections.json").string() + " --out " + (dir / "cache.h5").string());
  ASSERT_EQ(convert.exit_code, 0) << convert.err;
  const nlohmann::json h5_run =
      EvalJson("--labels " + (dir / "cache.h5").string() + " --detections " + (dir / "cache.h5").string(), dir / "out2");
  EXPECT_EQ(h5_run["matches"], json_run["matches"]);
  EXPECT_NEAR(h5_run["mpjpe_mm"].get<double>(), json_run["mpjpe_mm"].get<double>(), 1e-3) << "float32 cache";
  // Detections whose ids match nothing are an error naming the file.
  Detections stray = detections;
  for (auto& f : stray.frames) f.frame_id = "other_" + f.frame_id;
  WriteGenericDetections(dir / "stray.json", stray);
  const test::CommandResult mismatch =
      test::RunRpt("eval --quiet --labels " + (dir / "labels.json").string() + " --detections " + (dir / "stray.json").string());
  EXPECT_EQ(mismatch.exit_code, 2);
  EXPECT_NE(mismatch.err.find("stray.json"), std::string::npos) << mismatch.err;
  fs::remove_all(dir);
}

// Honest time end to end: labels without "timestamp" and "fps" run with their times unknown
// (one warning saying how to give them; nothing carried across frames, so no track lasts), and
// --param fps=N gives them times again (no warning; tracks last).
TEST(EvalDatasets, LabelsWithoutTimesRunWithTimesUnknownAndSaySo) {
  const fs::path dir = test::TempDir("no_times");
  synthetic::SceneOptions options;
  options.num_frames = 20;
  options.num_people = 3;
  const synthetic::Scene scene = synthetic::GenerateScene(options);
  Sequence sequence = synthetic::MakeSyntheticSequence(scene, synthetic::DetectorOptions::Realistic(), 5, "mine");
  sequence.fps = 0;
  for (SequenceFrame& f : sequence.frames) f.timestamp_s = kUnknownTime;
  WriteLabels(dir / "labels.json", {sequence});
  Detections detections;
  detections.joints = sequence.detection_joints;
  for (const SequenceFrame& f : sequence.frames) {
    FrameDetections frame{f.id, {}, f.views};
    for (const Camera& c : sequence.cameras) frame.cameras.push_back(c.name);
    detections.frames.push_back(frame);
  }
  WriteGenericDetections(dir / "detections.json", detections);
  const std::string input = "eval --quiet --labels " + (dir / "labels.json").string() + " --detections " +
                            (dir / "detections.json").string();
  // Distinct track ids over the run's predictions.
  auto track_ids = [](const fs::path& out) {
    std::set<int> ids;
    const nlohmann::json predictions = nlohmann::json::parse(test::ReadAll(out / "predictions.json"));
    for (const auto& frame : predictions["frames"]) {
      for (const auto& id : frame["track_ids"]) ids.insert(id.get<int>());
    }
    return ids;
  };
  const test::CommandResult unknown = test::RunRpt(input + " --out " + (dir / "unknown").string());
  ASSERT_EQ(unknown.exit_code, 0) << unknown.err;
  const std::string warning = "their times are unknown";
  ASSERT_NE(unknown.err.find(warning), std::string::npos) << unknown.err;
  EXPECT_EQ(unknown.err.find(warning), unknown.err.rfind(warning)) << "one warning: " << unknown.err;
  EXPECT_NE(unknown.err.find("--param fps=N"), std::string::npos) << "says how to give them";
  EXPECT_EQ(track_ids(dir / "unknown"), std::set<int>{-1}) << "nothing carried from one frame to the next: no tracks";

  const test::CommandResult known = test::RunRpt(input + " --param fps=5 --out " + (dir / "known").string());
  ASSERT_EQ(known.exit_code, 0) << known.err;
  EXPECT_EQ(known.err.find(warning), std::string::npos) << known.err;
  EXPECT_LE(track_ids(dir / "known").size(), 6u) << "tracks last across frames 0.2 s apart";

  const test::CommandResult bogus = test::RunRpt(input + " --param bogus=1 --out " + (dir / "bogus").string());
  EXPECT_EQ(bogus.exit_code, 2) << "an unknown parameter of the labels reader is refused";
  EXPECT_NE(bogus.err.find("bogus"), std::string::npos) << bogus.err;
  fs::remove_all(dir);
}

TEST(InspectCommand, ReportsSmallDistancesForConsistentInput) {
  const test::CommandResult r = test::RunRpt("inspect --dataset synthetic --param frames=10 --param noise=clean --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j[0]["cameras"].size(), 5u);
  for (const auto& camera : j[0]["cameras"]) EXPECT_LT(camera["gt_to_detection_px_median"].get<double>(), 15.0);
  EXPECT_TRUE(j[0]["warnings"].empty()) << j[0]["warnings"];
  EXPECT_EQ(test::RunRpt("datasets").exit_code, 0);
}

// Without detections inspect shows cameras and ground truth; it said the frame ids and joint names
// of the (absent) detections were wrong.
TEST(InspectCommand, WithoutDetectionsSaysSoAndNothingElse) {
  const fs::path dir = test::TempDir("inspect_no_detections");
  ASSERT_EQ(test::RunRpt("convert --dataset synthetic --param frames=3 --labels-out " + (dir / "l.json").string())
                .exit_code,
            0);
  const test::CommandResult r = test::RunRpt("inspect --labels " + (dir / "l.json").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json warnings = nlohmann::json::parse(r.out)[0]["warnings"];
  ASSERT_EQ(warnings.size(), 1u) << warnings;
  EXPECT_EQ(warnings[0]["code"], "no_detections");
  EXPECT_NE(r.err.find("warning: synthetic: no 2D detections (pass --detections FILE or --simulate"), std::string::npos)
      << r.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt
