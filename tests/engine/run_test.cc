// SPDX-License-Identifier: MIT
// The run loop (engine/run.h): frames pulled from frame sources give the numbers of the same
// frames in memory, whatever the thread count, while one input frame is alive at a time; sinks
// see every frame in order; the input checks stream.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/errors.h"

#include "datasets/frame_source.h"
#include "datasets/synthetic/synthetic_dataset.h"
#include "datasets/synthetic/simulated_source.h"
#include "engine/detection_checks.h"
#include "engine/frame_sink.h"
#include "engine/outputs/loss_tables.h"
#include "engine/outputs/results_writer.h"
#include "engine/run.h"
#include "engine/thread_count.h"
#include "tests/counting_source.h"
#include "tests/error_message.h"
#include "datasets/synthetic/simulate_detections.h"

namespace rpt::engine {
namespace {

SyntheticParams Scene(int frames, uint64_t seed = 3) {
  SyntheticParams params;
  params.cameras = 4;
  params.people = 2;
  params.frames = frames;
  params.seed = seed;
  return params;
}

// Two sequences: the synthetic scene and another one renamed so that their frame ids differ.
std::vector<Sequence> TwoSequences() {
  std::vector<Sequence> whole = MakeSyntheticDataset(Scene(90));
  whole.push_back(MakeSyntheticDataset(Scene(60, 4))[0]);
  whole[1].name = "other";
  for (SequenceFrame& frame : whole[1].frames) frame.id = "other_" + frame.id;
  return whole;
}

void ExpectSamePredictions(const PredictionsCollector& a, const PredictionsCollector& b) {
  ASSERT_EQ(a.sequences().size(), b.sequences().size());
  for (size_t s = 0; s < a.sequences().size(); ++s) {
    const auto& x = a.sequences()[s];
    const auto& y = b.sequences()[s];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.output_joints, y.output_joints);
    EXPECT_EQ(x.frame_ids, y.frame_ids);
    ASSERT_EQ(x.persons.size(), y.persons.size());
    for (size_t f = 0; f < x.persons.size(); ++f) {
      EXPECT_EQ(x.persons[f].data, y.persons[f].data) << x.name << " frame " << f;
      EXPECT_EQ(x.persons[f].track_ids, y.persons[f].track_ids) << x.name << " frame " << f;
    }
  }
}

// Everything eval reports from a run, for comparisons.
void ExpectSameRun(const RunResult& a, const RunResult& b) {
  EXPECT_EQ(a.frames, b.frames);
  EXPECT_EQ(a.gt_persons, b.gt_persons);
  EXPECT_EQ(a.output_persons, b.output_persons);
  EXPECT_EQ(a.frames_with_gt, b.frames_with_gt);
  EXPECT_EQ(a.frames_with_gt_without_prediction, b.frames_with_gt_without_prediction);
  EXPECT_EQ(a.metrics.mpjpe_mm, b.metrics.mpjpe_mm);
  EXPECT_EQ(a.metrics.pcp, b.metrics.pcp);
  EXPECT_EQ(a.metrics.recall_500, b.metrics.recall_500);
  EXPECT_EQ(a.metrics.num_predictions, b.metrics.num_predictions);
  EXPECT_EQ(a.metrics.ap, b.metrics.ap);
  EXPECT_EQ(a.counts.count_per_frame, b.counts.count_per_frame);
  ASSERT_EQ(a.sequences.size(), b.sequences.size());
  for (size_t i = 0; i < a.sequences.size(); ++i) {
    EXPECT_EQ(a.sequences[i].name, b.sequences[i].name);
    EXPECT_EQ(a.sequences[i].frames, b.sequences[i].frames);
    EXPECT_EQ(a.sequences[i].metrics.mpjpe_mm, b.sequences[i].metrics.mpjpe_mm);
  }
}

// A sink that records the order of the calls it gets.
class OrderSink final : public FrameSink {
 public:
  void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& joints) override {
    calls.push_back("begin " + std::to_string(sequence) + " " + header.name + " " + std::to_string(joints.size()));
  }
  void Frame(const FrameOutput& frame) override {
    if (frame.input->id.size() > 0 && frames++ < 2) calls.push_back("frame " + frame.input->id);
    EXPECT_NE(frame.stats, nullptr);
  }
  void EndSequence(int sequence) override { calls.push_back("end " + std::to_string(sequence)); }
  std::vector<std::string> calls;
  int frames = 0;
};

TEST(RunTest, StreamedFramesGiveTheNumbersOfTheSequencesInMemory) {
  const std::vector<Sequence> whole = TwoSequences();
  RunOptions options;
  options.threads = 1;
  PredictionsCollector expected_predictions(2);
  const RunResult expected = engine::Run(std::span<const Sequence>(whole), options, &expected_predictions);

  options.threads = 2;
  std::vector<std::unique_ptr<FrameSource>> sources;
  sources.push_back(std::make_unique<CountingSource>(OpenSyntheticSequence(Scene(90))));
  sources.push_back(std::make_unique<SequenceSource>(whole[1]));
  PredictionsCollector streamed_predictions(2);
  const RunResult streamed = engine::Run(std::move(sources), options, &streamed_predictions);
  ExpectSameRun(streamed, expected);
  ExpectSamePredictions(streamed_predictions, expected_predictions);
  ASSERT_EQ(streamed.sequences.size(), 2u) << "one result per sequence";
  EXPECT_EQ(streamed.sequences[0].frames, 90);
  EXPECT_EQ(streamed.sequences[1].name, "other");
  EXPECT_NE(streamed.sequences[0].metrics.mpjpe_mm, streamed.sequences[1].metrics.mpjpe_mm);
  EXPECT_GT(streamed.metrics.recall_500, 90.0) << "a clean scene is recovered";
}

TEST(RunTest, TheTotalsDoNotDependOnTheThreadCount) {
  const std::vector<Sequence> whole = TwoSequences();
  RunOptions options;
  options.threads = 1;
  const RunResult one = engine::Run(std::span<const Sequence>(whole), options);
  options.threads = 2;
  const RunResult two = engine::Run(std::span<const Sequence>(whole), options);
  ExpectSameRun(one, two);
}

TEST(RunTest, InputChecksStreamWithTheFrames) {
  const std::vector<Sequence> whole = TwoSequences();
  RunOptions options;
  options.checks = DetectionCheckOptions{};
  const RunResult run = engine::Run(std::span<const Sequence>(whole), options);
  ASSERT_EQ(run.sequences.size(), 2u);
  for (size_t i = 0; i < 2; ++i) {
    const SequenceCheck expected = CheckDetections(whole[i], options.triangulator.track.max_gap_s);
    ASSERT_TRUE(run.sequences[i].check.has_value());
    const SequenceCheck& check = *run.sequences[i].check;
    EXPECT_EQ(check.frames, expected.frames);
    EXPECT_EQ(check.measured_frames, expected.measured_frames);
    EXPECT_TRUE(check.shift.tested) << check.shift.reason;
    EXPECT_EQ(check.shift.rel_median, expected.shift.rel_median);
    EXPECT_EQ(check.cameras[0].px_median, expected.cameras[0].px_median);
  }
}

// The checks' notion of consecutive frames is the tracker's: frames further apart than
// track.max_gap_s break continuity for both, so the shift test has no neighbours.
TEST(RunTest, InputChecksShareTheTrackersMaxGap) {
  const std::vector<Sequence> whole = TwoSequences();
  RunOptions options;
  options.checks = DetectionCheckOptions{};
  options.triangulator.track.max_gap_s = 1e-6;
  const RunResult run = engine::Run(std::span<const Sequence>(whole), options);
  for (const SequenceResult& sequence : run.sequences) {
    ASSERT_TRUE(sequence.check.has_value());
    EXPECT_FALSE(sequence.check->shift.tested);
  }
}

TEST(RunTest, HoldsOneInputFramePerSequenceWhateverTheLength) {
  for (const int threads : {1, 2}) {
    for (const int frames : {10, 3000}) {
      CountingSource::Counts counts;  // the run frees each source once exhausted
      std::vector<std::unique_ptr<FrameSource>> sources;
      sources.push_back(std::make_unique<CountingSource>(OpenSyntheticSequence(Scene(frames)), &counts));
      RunOptions options;
      options.checks = DetectionCheckOptions{};
      options.threads = threads;
      const RunResult run = engine::Run(std::move(sources), options);
      EXPECT_EQ(run.frames, frames);
      EXPECT_EQ(counts.delivered, frames);
      if (run.threads == 1) {
        EXPECT_EQ(counts.frames_alive_peak, 1u) << "one input frame alive, " << frames << " frames";
      } else {
        // One sequence on several threads: the pipeline's ring of 16 frames, however long.
        EXPECT_LE(counts.frames_alive_peak, 16u) << frames << " frames";
      }
      if (frames == 3000) {
        EXPECT_EQ(run.sequences[0].check->measured_frames, 200) << "bounded sample of the checks";
      }
    }
  }
}

// Everything a run reports but its times (and the time-derived numbers), as JSON.
nlohmann::ordered_json Untimed(const RunResult& run) {
  nlohmann::ordered_json j = SummaryJson(run);
  j.update(RunLossTablesJson(run));
  for (const char* timed : {"fps", "frame_time_us_median", "step_time_us_median", "step_time_us_mean",
                            "eval_frames_per_s", "wall_seconds", "threads"}) {
    j.erase(timed);
  }
  return j;
}

void ExpectSameFrames(const PredictionsCollector& a, const PredictionsCollector& b) {
  ExpectSamePredictions(a, b);
  for (size_t s = 0; s < a.sequences().size(); ++s) {
    EXPECT_EQ(a.sequences()[s].timestamps_s, b.sequences()[s].timestamps_s);
    for (size_t f = 0; f < a.sequences()[s].persons.size(); ++f) {
      ASSERT_EQ(a.sequences()[s].persons[f].provenance, b.sequences()[s].persons[f].provenance) << "frame " << f;
    }
  }
}

// One sequence on 2 or 3 threads (engine/frame_pipeline.h): reading, completing (the simulated
// detector, the validation, several frames at once), triangulating and measuring + writing
// overlap, and every number is that of one thread: the predictions with their track ids,
// the metrics, the input checks, the loss table, the step counts. A long tracked scene (more
// frames than the pipeline holds, persons coming and going) with each temporal step in turn.
TEST(RunTest, OneSequenceOnSeveralThreadsGivesTheResultsOfOneThread) {
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (const char* temporal : {"track", "causal", "offline"}) {
    SyntheticParams scene = Scene(900, 7);
    scene.people = 3;
    RunOptions options;
    options.checks = DetectionCheckOptions{};
    options.loss_table = true;
    if (std::string(temporal) == "causal") {
      options.triangulator.smooth.mode = SmoothMode::kCausal;
      options.triangulator.bone_lengths.enabled = true;
    } else if (std::string(temporal) == "offline") {
      options.triangulator.smooth.mode = SmoothMode::kOffline;
    }
    const auto run = [&](int threads, PredictionsCollector* predictions) {
      std::vector<std::unique_ptr<FrameSource>> sources;
      sources.push_back(OpenSyntheticSequence(scene));
      options.threads = threads;
      return engine::Run(std::move(sources), options, predictions);
    };
    PredictionsCollector one_predictions(1);
    const RunResult one = run(1, &one_predictions);
    ASSERT_EQ(one.frames, 900);
    EXPECT_EQ(one.threads, 1);
    ASSERT_GT(one.output_persons, 900 * 2) << temporal;
    for (const int threads : {2, 3}) {
      PredictionsCollector predictions(1);
      const RunResult several = run(threads, &predictions);
      EXPECT_EQ(several.threads, std::min(threads, hardware)) << "the stages' threads";
      ExpectSameRun(several, one);
      ExpectSameFrames(predictions, one_predictions);
      EXPECT_EQ(Untimed(several).dump(), Untimed(one).dump()) << temporal << ", " << threads << " threads";
      ASSERT_TRUE(several.sequences[0].check.has_value());
      EXPECT_EQ(several.sequences[0].check->cameras[0].px_median, one.sequences[0].check->cameras[0].px_median);
    }
  }
}

// A source whose frame `bad` has a score out of range: the validation (engine/checked_source.h)
// stops the run there.
std::unique_ptr<FrameSource> WithBadFrame(int frames, int bad) {
  Sequence sequence = MakeSyntheticDataset(Scene(frames))[0];
  Poses2D& view = sequence.frames[static_cast<size_t>(bad)].views[1];
  view.data[2] = 7.5;  // the first joint's score
  return std::make_unique<SequenceSource>(std::move(sequence));
}

// Runs the source `make` opens on 1, 2 and 3 threads: each run stops with the error one thread
// meets (containing `names`), after handing on exactly the `frames_before` frames before it, and
// nothing hangs.
void ExpectTheSameStopOnEveryThreadCount(const std::function<std::unique_ptr<FrameSource>()>& make, RunOptions options,
                                         const std::string& names, int frames_before) {
  std::string expected;
  for (const int threads : {1, 2, 3}) {
    std::vector<std::unique_ptr<FrameSource>> sources;
    sources.push_back(make());
    options.threads = threads;
    OrderSink sink;
    try {
      engine::Run(std::move(sources), options, &sink);
      ADD_FAILURE() << "no error with " << threads << " threads";
    } catch (const InputError& e) {
      if (threads == 1) expected = e.what();
      EXPECT_EQ(std::string(e.what()), expected) << threads << " threads";
      EXPECT_NE(expected.find(names), std::string::npos) << expected;
      EXPECT_EQ(sink.frames, frames_before) << "the frames before the bad one, " << threads << " threads";
    }
  }
}

// A bad frame in the middle of one sequence on several threads: the error of one thread (naming
// the sequence, the frame and the view), the frames before it handed on, nothing after, no hang.
TEST(RunTest, ABadFrameMidSequenceStopsEveryThreadCountTheSameWay) {
  ExpectTheSameStopOnEveryThreadCount([] { return WithBadFrame(400, 200); }, RunOptions{}, "synthetic_000200", 200);
}

// A frame the triangulator refuses (above triangulate.max_persons_per_view) in the middle.
TEST(RunTest, AFrameTheTriangulatorRefusesStopsEveryThreadCountTheSameWay) {
  const auto make = [] {
    Sequence sequence = MakeSyntheticDataset(Scene(300))[0];
    Poses2D& view = sequence.frames[150].views[0];
    const Eigen::Matrix3Xd copy = view.Person(0);
    for (int extra = 0; extra < 4; ++extra) view.AddPerson() = copy;
    return std::unique_ptr<FrameSource>(std::make_unique<SequenceSource>(std::move(sequence)));
  };
  RunOptions options;
  options.triangulator.triangulate.max_persons_per_view = 4;
  ExpectTheSameStopOnEveryThreadCount(make, options, "frame 'synthetic_000150'", 150);
}

TEST(RunTest, WithoutMetricsNoGroundTruthIsNeeded) {
  std::vector<Sequence> whole = MakeSyntheticDataset(Scene(30));
  for (SequenceFrame& frame : whole[0].frames) frame.gt.Clear(frame.gt.num_joints);
  RunOptions options;
  options.eval.reset();
  PredictionsCollector predictions(1);
  const RunResult run = engine::Run(std::span<const Sequence>(whole), options, &predictions);
  EXPECT_FALSE(run.evaluated);
  EXPECT_EQ(run.frames, 30);
  EXPECT_EQ(run.gt_persons, 0);
  EXPECT_GT(run.output_persons, 30) << "two people, triangulated without GT";
  EXPECT_EQ(predictions.sequences()[0].persons.size(), 30u);
}

// A run of no frame at all measured nothing: with require_frames (eval, triangulate, check, sweep)
// it is an InputError saying what can leave none (it was exit 0 with every metric '-'); the
// library runs it.
TEST(RunTest, AnInputWithoutFramesIsAnErrorWhenFramesAreRequired) {
  std::vector<Sequence> empty = MakeSyntheticDataset(Scene(5));
  empty[0].frames.clear();
  RunOptions options;
  EXPECT_EQ(engine::Run(std::span<const Sequence>(empty), options).frames, 0);
  options.require_frames = true;
  EXPECT_THAT(test::InputErrorOf([&] { engine::Run(std::span<const Sequence>(empty), options); }),
              ::testing::HasSubstr("the input: no frame to triangulate in 1 sequence (a selection such as"));
  std::vector<Sequence> one = MakeSyntheticDataset(Scene(1));
  EXPECT_EQ(engine::Run(std::span<const Sequence>(one), options).frames, 1);
}

// A time that goes back (or repeats) ends the tracks: counted in one warning with the largest
// step back; a frame without a time gets no track ids and does not count.
TEST(RunTest, TimesThatGoBackAreCountedAndStartTracksAnew) {
  std::vector<Sequence> whole = MakeSyntheticDataset(Scene(8));
  const double times[] = {0, 0.04, 0.08, 0.02, 0.02, 0.12, kUnknownTime, 0.10};
  for (size_t f = 0; f < 8; ++f) whole[0].frames[f].timestamp_s = times[f];
  RunOptions options;
  options.eval.reset();
  PredictionsCollector predictions(1);
  const RunResult run = engine::Run(std::span<const Sequence>(whole), options, &predictions);
  const std::string what = "frames whose time is not after the previous frame's (tracks end there, and start anew)";
  const auto it = std::find_if(run.warnings.items().begin(), run.warnings.items().end(),
                               [&](const InputWarning& w) { return w.what == what; });
  ASSERT_NE(it, run.warnings.items().end());
  EXPECT_EQ(it->source, whole[0].name);
  EXPECT_EQ(it->count, 3) << "0.02 after 0.08, 0.02 after 0.02, 0.10 after 0.12";
  EXPECT_NEAR(it->worst, 0.06, 1e-12);
  const auto& tracks = predictions.sequences()[0].persons;
  ASSERT_EQ(tracks.size(), 8u);
  auto ids = [&](size_t f) { return std::vector<int>(tracks[f].track_ids.begin(), tracks[f].track_ids.end()); };
  const std::vector<int> before = ids(2);
  for (int id : ids(3)) {
    EXPECT_GE(id, 0);
    EXPECT_EQ(std::count(before.begin(), before.end(), id), 0) << "frame 3 continues no track of frame 2";
  }
  for (int id : ids(6)) EXPECT_EQ(id, -1) << "no time: not tracked";
  EXPECT_EQ(ids(1), ids(0)) << "increasing times keep the tracks";
  // In order: no such warning.
  for (size_t f = 0; f < 8; ++f) whole[0].frames[f].timestamp_s = 0.04 * static_cast<double>(f);
  PredictionsCollector unused(1);
  const RunResult ordered = engine::Run(std::span<const Sequence>(whole), options, &unused);
  for (const InputWarning& w : ordered.warnings.items()) EXPECT_NE(w.what, what);
}

// Without ground truth the persons are compared with each camera's detections: two cameras whose
// calibrations are swapped are named, the others and a right rig are not.
// A run without metrics, with the camera-agreement check (what rpt triangulate runs).
RunOptions AgreementRun() {
  RunOptions options;
  options.eval.reset();
  options.camera_agreement = true;
  return options;
}

TEST(RunTest, CamerasWhoseDetectionsDisagreeWithThePersonsAreNamed) {
  SyntheticParams params = Scene(60);
  params.cameras = 5;
  std::vector<Sequence> whole = MakeSyntheticDataset(params);
  const RunOptions options = AgreementRun();
  const auto warnings = [&](const std::vector<Sequence>& input) {
    const RunResult run = engine::Run(std::span<const Sequence>(input), options, nullptr);
    return CameraAgreementWarnings(run.sequences[0].name, run.sequences[0].camera_agreement);
  };
  EXPECT_TRUE(warnings(whole).empty());
  const RunResult right = engine::Run(std::span<const Sequence>(whole), options, nullptr);
  for (const CameraAgreement& camera : right.sequences[0].camera_agreement) {
    EXPECT_GE(camera.in_view, kMinAgreementPersons) << camera.camera;
    EXPECT_GE(static_cast<double>(camera.agreeing) / camera.in_view, 0.8) << camera.camera;
  }
  std::swap(whole[0].cameras[0], whole[0].cameras[1]);  // each camera's calibration under the other's detections
  std::swap(whole[0].cameras[0].name, whole[0].cameras[1].name);
  const std::vector<std::string> swapped = warnings(whole);
  ASSERT_EQ(swapped.size(), 2u);
  EXPECT_NE(swapped[0].find(", camera 'cam0': only "), std::string::npos) << swapped[0];
  EXPECT_NE(swapped[1].find(", camera 'cam1': only "), std::string::npos) << swapped[1];
  EXPECT_NE(swapped[0].find("is its calibration right, its pixel scale (detections from a resized image?), or is its name another camera's?"), std::string::npos);
  // A camera without any detection has nothing to match: its output is missing, not misplaced.
  std::swap(whole[0].cameras[0], whole[0].cameras[1]);
  std::swap(whole[0].cameras[0].name, whole[0].cameras[1].name);
  for (SequenceFrame& frame : whole[0].frames) frame.views[2].Clear(frame.views[2].num_joints);
  const std::vector<std::string> silent = warnings(whole);
  ASSERT_EQ(silent.size(), 1u);
  EXPECT_NE(silent[0].find(", camera 'cam2': no detections in any of the 60 frames compared, while "), std::string::npos)
      << silent[0];
  EXPECT_EQ(silent[0].find("calibration"), std::string::npos) << silent[0];
  // A camera with detections in every other frame only (the others without data, or seeing nobody)
  // is judged on the frames where it detected someone: they all match, nothing is named.
  for (const bool unavailable : {true, false}) {
    std::vector<Sequence> intermittent = MakeSyntheticDataset(params);
    for (size_t f = 1; f < intermittent[0].frames.size(); f += 2) {
      Poses2D& view = intermittent[0].frames[f].views[3];
      view.Clear(view.num_joints);
      view.unavailable = unavailable;
    }
    EXPECT_TRUE(warnings(intermittent).empty()) << unavailable << ": " << warnings(intermittent)[0];
    const RunResult run = engine::Run(std::span<const Sequence>(intermittent), options, nullptr);
    const CameraAgreement& camera = run.sequences[0].camera_agreement[3];
    EXPECT_GE(static_cast<double>(camera.agreeing) / camera.in_view, 0.8);
    EXPECT_EQ(camera.frames, unavailable ? 30 : 60);
    EXPECT_EQ(camera.in_view_without_detections > 0, !unavailable);
  }
}

// The camera centre given where the world-to-camera t belongs (a calibration user's finding: two
// of four cameras turned round, the 3D persons 4 m off, no warning): those cameras detect people in
// every frame, yet none of the persons triangulated falls in their images. They are named; the
// others, and every camera of the right rig, are not.
TEST(RunTest, CamerasInWhoseImagesNoPersonFallsAreNamed) {
  SyntheticParams params = Scene(60);
  params.cameras = 4;
  std::vector<Sequence> whole = MakeSyntheticDataset(params);
  const RunOptions options = AgreementRun();
  const auto run = [&](const std::vector<Sequence>& input) {
    return engine::Run(std::span<const Sequence>(input), options, nullptr).sequences[0];
  };
  const SequenceResult right = run(whole);
  EXPECT_TRUE(CameraAgreementWarnings(right.name, right.camera_agreement).empty());
  for (const CameraAgreement& camera : right.camera_agreement) {
    EXPECT_GT(camera.in_view, 0.9 * static_cast<double>(camera.while_detecting)) << camera.camera;
  }
  for (const int c : {2, 3}) {
    Camera& camera = whole[0].cameras[static_cast<size_t>(c)];
    camera.t = camera.Center();
  }
  const SequenceResult wrong = run(whole);
  const std::vector<std::string> lines = CameraAgreementWarnings(wrong.name, wrong.camera_agreement);
  ASSERT_EQ(lines.size(), 2u) << (lines.empty() ? "" : lines[0]);
  for (size_t i = 0; i < 2; ++i) {
    const CameraAgreement& camera = wrong.camera_agreement[i + 2];
    EXPECT_EQ(camera.in_view, 0) << camera.camera;
    EXPECT_EQ(camera.frames_with_detections, 60) << camera.camera;
    EXPECT_EQ(lines[i].find(", camera '" + camera.camera +
                            "': it detected persons in 60 of the 60 frames compared, but "
                            "none of the " +
                            std::to_string(camera.while_detecting) +
                            " 3D persons of those frames fall in its image: is its calibration right?"),
              wrong.name.size())
        << lines[i];
  }
  EXPECT_GE(wrong.camera_agreement[2].while_detecting, kMinAgreementPersons);
}

// Half the persons in view matching is named (a COLMAP quaternion read x, y, z, w gave every camera
// exactly 22 of 44: said nothing when it took fewer than half); more than half is not.
TEST(RunTest, ACameraMatchingHalfItsPersonsIsNamed) {
  CameraAgreement half;
  half.camera = "cam0";
  half.frames = half.frames_with_detections = 30;
  half.in_view = half.while_detecting = 44;
  half.agreeing = 22;
  ASSERT_EQ(CameraAgreementWarnings("s", {half}).size(), 1u);
  EXPECT_NE(CameraAgreementWarnings("s", {half})[0].find("s, camera 'cam0': only 50 % of the 44 3D persons"),
            std::string::npos);
  half.agreeing = 23;
  EXPECT_TRUE(CameraAgreementWarnings("s", {half}).empty());
}

TEST(RunTest, ASinkSeesTheSequenceBeginItsFramesInOrderThenTheEnd) {
  const std::vector<Sequence> whole = MakeSyntheticDataset(Scene(5));
  OrderSink sink;
  RunOptions options;
  engine::Run(std::span<const Sequence>(whole), options, &sink);
  ASSERT_EQ(sink.calls.size(), 4u);
  EXPECT_EQ(sink.calls[0], "begin 0 " + whole[0].name + " 20") << "17 COCO joints and 3 derived ones";
  EXPECT_EQ(sink.calls[1], "frame " + whole[0].frames[0].id);
  EXPECT_EQ(sink.calls[2], "frame " + whole[0].frames[1].id);
  EXPECT_EQ(sink.calls[3], "end 0");
  EXPECT_EQ(sink.frames, 5);
}

TEST(RunTest, TheSequencesRoomBecomesTheRoomCheckUnlessOneIsSet) {
  SequenceHeader header;
  header.room.center_m = Eigen::Vector3d(1, 2, 1);
  header.room.size_m = Eigen::Vector3d(8, 6, 2);
  TriangulatorOptions options;
  const TriangulatorOptions from_dataset = TriangulatorOptionsFor(options, header);
  EXPECT_EQ(from_dataset.room_check.center_m, header.room.center_m);
  EXPECT_EQ(from_dataset.room_check.size_m, header.room.size_m);
  options.room_check.size_m = Eigen::Vector3d(3, 3, 3);
  const TriangulatorOptions set = TriangulatorOptionsFor(options, header);
  EXPECT_EQ(set.room_check.size_m, Eigen::Vector3d(3, 3, 3));
  EXPECT_EQ(set.room_check.center_m, Eigen::Vector3d::Zero());
}

TEST(SimulatedDetectionsSourceTest, SameDetectionsAsSimulatingTheWholeSequence) {
  SyntheticParams params = Scene(40);
  params.noise = "perfect";
  std::vector<Sequence> whole = MakeSyntheticDataset(params);
  SimulationOptions simulation;
  simulation.seed = 11;
  simulation.detector = "hard";
  SimulateDetections(simulation, &whole[0]);
  SimulatedDetectionsSource source(OpenSyntheticSequence(params), simulation);
  EXPECT_EQ(source.header().detection_joints, whole[0].detection_joints);
  const Sequence streamed = Materialize(source);
  ASSERT_EQ(streamed.frames.size(), whole[0].frames.size());
  for (size_t f = 0; f < streamed.frames.size(); ++f) {
    ASSERT_EQ(streamed.frames[f].views.size(), whole[0].frames[f].views.size());
    for (size_t c = 0; c < streamed.frames[f].views.size(); ++c) {
      EXPECT_EQ(streamed.frames[f].views[c].data, whole[0].frames[f].views[c].data) << "frame " << f;
    }
    EXPECT_EQ(streamed.frames[f].labels_2d.size(), whole[0].frames[f].labels_2d.size());
  }
}

}  // namespace
}  // namespace rpt::engine
