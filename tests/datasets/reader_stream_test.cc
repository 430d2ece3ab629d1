// SPDX-License-Identifier: MIT
// The reader contract (datasets/frame_source.h, datasets/dataset_request.h) over every reader:
// streamed and materialised give the same numbers, also with frames pulled ahead and completed
// on several threads at once (ReaderStreamTest, instantiated here for the synthetic, generic and
// real-data readers, the simulated detections and the validation, and in each reader's own test
// file for its generated fixtures), a source of a format read whole does not hold the converted
// frames, and readers without their ground truth.
#include "tests/datasets/reader_stream_test.h"

#include <gmock/gmock.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>
#include <utility>

#if defined(__GLIBC__) && (__GLIBC__ > 2 || __GLIBC_MINOR__ >= 33)
#include <malloc.h>
#define RPT_HAVE_MALLINFO2 1
#endif

#include "core/errors.h"
#include "core/joints.h"
#include "datasets/readers/detections_file.h"
#include "datasets/readers/generic_labels.h"
#include "datasets/readers/hdf5_cache.h"
#include "datasets/synthetic/simulated_source.h"
#include "engine/checked_source.h"
#include "engine/dataset_registry.h"
#include "tests/datasets/io_test_util.h"
#include "tests/datasets/readers_generic_test_util.h"
#include "tests/error_message.h"
#include "tests/test_data.h"

namespace rpt::test {
using engine::OpenDataset;
using engine::ReadDataset;
namespace {

// Times compare equal when both are unknown (NaN).
void ExpectSameTime(double a, double b, const std::string& id) {
  if (std::isnan(a) || std::isnan(b)) {
    EXPECT_TRUE(std::isnan(a) && std::isnan(b)) << id << ": " << a << " vs " << b;
  } else {
    EXPECT_EQ(a, b) << id;
  }
}

void ExpectSameHeader(const SequenceHeader& a, const SequenceHeader& b) {
  EXPECT_EQ(a.name, b.name);
  ASSERT_EQ(a.cameras.size(), b.cameras.size()) << a.name;
  for (size_t c = 0; c < a.cameras.size(); ++c) {
    const Camera& x = a.cameras[c];
    const Camera& y = b.cameras[c];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.width, y.width);
    EXPECT_EQ(x.height, y.height);
    EXPECT_EQ(x.model, y.model);
    EXPECT_EQ(x.K, y.K) << x.name;
    EXPECT_EQ(x.R, y.R) << x.name;
    EXPECT_EQ(x.t, y.t) << x.name;
    EXPECT_EQ(x.dist, y.dist) << x.name;
  }
  EXPECT_EQ(a.gt_joints, b.gt_joints) << a.name;
  EXPECT_EQ(a.detection_joints, b.detection_joints) << a.name;
  EXPECT_EQ(a.evaluated_joints, b.evaluated_joints) << a.name;
  EXPECT_EQ(a.room.center_m, b.room.center_m) << a.name;
  EXPECT_EQ(a.room.size_m, b.room.size_m) << a.name;
  EXPECT_EQ(a.fps, b.fps) << a.name;
}

void ExpectSameFrame(const SequenceFrame& a, const SequenceFrame& b) {
  EXPECT_EQ(a.id, b.id);
  ExpectSameTime(a.timestamp_s, b.timestamp_s, a.id);
  EXPECT_EQ(a.gt.num_joints, b.gt.num_joints) << a.id;
  EXPECT_EQ(a.gt.data, b.gt.data) << a.id;
  EXPECT_EQ(a.gt.track_ids, b.gt.track_ids) << a.id;
  ASSERT_EQ(a.views.size(), b.views.size()) << a.id;
  for (size_t c = 0; c < a.views.size(); ++c) {
    EXPECT_EQ(a.views[c].num_joints, b.views[c].num_joints) << a.id << " camera " << c;
    EXPECT_EQ(a.views[c].data, b.views[c].data) << a.id << " camera " << c;
  }
  ASSERT_EQ(a.labels_2d.size(), b.labels_2d.size()) << a.id;
  for (size_t c = 0; c < a.labels_2d.size(); ++c) {
    ASSERT_EQ(a.labels_2d[c].size(), b.labels_2d[c].size()) << a.id;
    for (size_t p = 0; p < a.labels_2d[c].size(); ++p) {
      EXPECT_EQ(a.labels_2d[c][p].gt_person, b.labels_2d[c][p].gt_person) << a.id;
      EXPECT_EQ(a.labels_2d[c][p].box_px, b.labels_2d[c][p].box_px) << a.id;
      EXPECT_EQ(a.labels_2d[c][p].visibility, b.labels_2d[c][p].visibility) << a.id;
    }
  }
}

}  // namespace

void ReaderStreamTest::SetUp() {
  const ReaderFixture& fixture = GetParam();
  if (!fixture.shared_data.empty()) RPT_REQUIRE_SHARED_DATA(fixture.shared_data);
  materialised_ = MaterializeAll(fixture.open(dir_.path()));
  sources_ = fixture.open(dir_.path());
  ASSERT_EQ(sources_.size(), materialised_.size());
  ASSERT_FALSE(sources_.empty());
}

TEST_P(ReaderStreamTest, StreamedFramesEqualTheMaterialisedSequences) {
  const std::vector<Sequence>& materialised = materialised_;
  std::vector<std::unique_ptr<FrameSource>>& sources = sources_;

  // Round robin over the sources, every frame pulled into the same buffer (whose vectors keep
  // their capacity): what a consumer that keeps nothing does.
  std::vector<std::vector<SequenceFrame>> streamed(sources.size());
  std::vector<bool> done(sources.size(), false);
  SequenceFrame buffer;
  for (bool any = true; any;) {
    any = false;
    for (size_t s = 0; s < sources.size(); ++s) {
      if (done[s]) continue;
      if (sources[s]->Next(&buffer)) {
        streamed[s].push_back(buffer);
        any = true;
      } else {
        done[s] = true;
      }
    }
  }
  size_t frames = 0;
  for (size_t s = 0; s < sources.size(); ++s) {
    const Sequence& whole = materialised[s];
    ExpectSameHeader(sources[s]->header(), whole);
    if (sources[s]->num_frames() >= 0) {
      EXPECT_EQ(sources[s]->num_frames(), static_cast<long>(whole.frames.size()));
    }
    ASSERT_EQ(streamed[s].size(), whole.frames.size()) << whole.name;
    for (size_t f = 0; f < whole.frames.size(); ++f) ExpectSameFrame(streamed[s][f], whole.frames[f]);
    frames += whole.frames.size();
    const auto& a = sources[s]->warnings().items();
    const auto& b = whole.warnings.items();
    ASSERT_EQ(a.size(), b.size()) << whole.name;
    for (size_t w = 0; w < a.size(); ++w) {
      EXPECT_EQ(a[w].Line(), b[w].Line());
      EXPECT_EQ(a[w].kind, b[w].kind) << a[w].Line();
    }
    // After the last frame the source stays exhausted.
    EXPECT_FALSE(sources[s]->Next(&buffer));
  }
  EXPECT_GT(frames, 0u);
}

// The two parts of a frame (Pull in order, then Complete per frame; datasets/frame_source.h) as a
// consumer on several threads runs them: blocks of frames pulled into their own buffers, each
// with its id and time already, then completed all at once on a thread each, the last first. The
// frames are those of the materialised sequences: Complete reads nothing a later Pull changes and
// needs nothing of the frames around it.
TEST_P(ReaderStreamTest, FramesPulledAheadAndCompletedOnSeveralThreadsEqualTheMaterialisedSequences) {
  const std::vector<Sequence>& materialised = materialised_;
  std::vector<std::unique_ptr<FrameSource>>& sources = sources_;
  constexpr size_t kBlock = 6;
  for (size_t s = 0; s < sources.size(); ++s) {
    const Sequence& whole = materialised[s];
    std::vector<SequenceFrame> block(kBlock);
    size_t done = 0;
    for (bool more = true; more;) {
      size_t pulled = 0;
      while (pulled < kBlock && (more = sources[s]->Pull(&block[pulled]))) {
        ASSERT_LT(done + pulled, whole.frames.size()) << whole.name;
        EXPECT_EQ(block[pulled].id, whole.frames[done + pulled].id) << "Pull sets the id";
        ExpectSameTime(block[pulled].timestamp_s, whole.frames[done + pulled].timestamp_s, block[pulled].id);
        ++pulled;
      }
      std::vector<std::thread> threads;
      for (size_t i = pulled; i-- > 0;) {
        threads.emplace_back([&, i] { sources[s]->Complete(static_cast<long>(done + i), &block[i]); });
      }
      for (std::thread& t : threads) t.join();
      for (size_t i = 0; i < pulled; ++i) ExpectSameFrame(block[i], whole.frames[done + i]);
      done += pulled;
    }
    EXPECT_EQ(done, whole.frames.size()) << whole.name;
    EXPECT_EQ(sources[s]->warnings().items().size(), whole.warnings.items().size()) << whole.name;
  }
}

namespace {

// A registry dataset: its root under ../shared/data when `shared_data` names a real fixture, else
// under the test's folder.
ReaderFixture Dataset(std::string name, std::string shared_data, std::string dataset, std::string root,
                      std::map<std::string, std::string> params, bool ground_truth = true) {
  return {std::move(name), shared_data,
          [dataset, root, params, ground_truth, shared = !shared_data.empty()](const std::filesystem::path& dir) {
            DatasetRequest request;
            request.dataset = dataset;
            request.root = shared ? SharedData(root) : dir / root;
            request.params = params;
            request.ground_truth = ground_truth;
            return OpenDataset(request);
          }};
}

// A labels file of two scenes written by WriteLabels (times known), plus one without times.
std::vector<std::unique_ptr<FrameSource>> OpenWrittenLabels(const std::filesystem::path& dir, bool timed,
                                                            bool ground_truth) {
  const std::filesystem::path path = dir / (timed ? "timed.json" : "untimed.json");
  if (!std::filesystem::exists(path)) {
    std::vector<Sequence> sequences = {MakeLabelSequence("a", 7, "a_"), MakeLabelSequence("b", 4, "b_")};
    if (!timed) {
      for (Sequence& sequence : sequences) {
        sequence.fps = 0;
        for (SequenceFrame& frame : sequence.frames) frame.timestamp_s = kUnknownTime;
      }
    }
    WriteLabels(path, sequences);
  }
  return OpenLabels(path, {}, ground_truth);
}

// The sources of `fixture` with simulated detections (--simulate), then validated as a run does.
ReaderFixture SimulatedAndChecked(std::string name, ReaderFixture fixture) {
  return {std::move(name), fixture.shared_data, [open = fixture.open](const std::filesystem::path& dir) {
            std::vector<std::unique_ptr<FrameSource>> sources = open(dir);
            SimulationOptions simulation;
            simulation.seed = 3;
            for (auto& source : sources) {
              source = std::make_unique<engine::CheckedSource>(
                  std::make_unique<SimulatedDetectionsSource>(std::move(source), simulation));
            }
            return sources;
          }};
}

}  // namespace

INSTANTIATE_TEST_SUITE_P(
    Generated, ReaderStreamTest,
    ::testing::Values(
        Dataset("Synthetic", "", "synthetic", "", {{"frames", "40"}, {"people", "3"}, {"cameras", "3"}}),
        Dataset("SyntheticWholeBodyFisheye", "", "synthetic", "",
                {{"frames", "6"}, {"joints", "wholebody"}, {"distortion", "fisheye"}}),
        Dataset("SyntheticWithoutGroundTruth", "", "synthetic", "", {{"frames", "10"}}, false),
        SimulatedAndChecked("SyntheticSimulatedAgain",
                            Dataset("", "", "synthetic", "", {{"frames", "15"}, {"people", "2"}, {"cameras", "3"}})),
        SimulatedAndChecked("LabelsSimulated",
                            ReaderFixture{"", "", [](const auto& dir) { return OpenWrittenLabels(dir, true, true); }}),
        ReaderFixture{"LabelsWithTimes", "", [](const auto& dir) { return OpenWrittenLabels(dir, true, true); }},
        ReaderFixture{"LabelsWithoutTimes", "", [](const auto& dir) { return OpenWrittenLabels(dir, false, true); }},
        ReaderFixture{"LabelsWithoutGroundTruth", "",
                      [](const auto& dir) { return OpenWrittenLabels(dir, true, false); }},
        ReaderFixture{
            "LabelsHdf5", "",
            [](const std::filesystem::path& dir) {
              const std::filesystem::path path = dir / "labels.h5";
              if (!std::filesystem::exists(path)) {
                std::vector<Sequence> sequences = {MakeLabelSequence("a", 5, "a_"), MakeLabelSequence("b", 3, "b_")};
                sequences[1].frames[1].timestamp_s = kUnknownTime;
                WriteSequencesHdf5(path, sequences);
              }
              return OpenLabelsFile(path);
            }}),
    ReaderFixtureName);

INSTANTIATE_TEST_SUITE_P(
    RealData, ReaderStreamTest,
    ::testing::Values(Dataset("Shelf", "shelf/actorsGT.mat", "shelf", "shelf", {{"frames", "0-2"}}),
                      Dataset("ShelfVoxelPose", "shelf/actorsGT.mat", "shelf", "shelf",
                              {{"frames", "0-2"}, {"detections", "voxelpose"}, {"actors", "0,2"}}),
                      Dataset("ShelfVoxelPoseWithoutGroundTruth", "shelf/pred_shelf_maskrcnn_hrnet_coco.pkl", "shelf",
                              "shelf", {{"frames", "0-2"}, {"detections", "voxelpose"}}, false),
                      Dataset("CampusVoxelPose", "campus/actorsGT.mat", "campus", "campus",
                              {{"frames", "0-2"}, {"detections", "voxelpose"}}),
                      Dataset("Shelf4da", "shelf/4d_association/gt.txt", "shelf-4da", "shelf/4d_association",
                              {{"frames", "0-300:4"}}),
                      Dataset("Shelf4daWithoutGroundTruth", "shelf/4d_association/detection", "shelf-4da",
                              "shelf/4d_association", {{"frames", "0-300:9"}}, false),
                      SimulatedAndChecked("ShelfSimulated",
                                          Dataset("", "shelf/actorsGT.mat", "shelf", "shelf", {{"frames", "0-2"}})),
                      Dataset("Panoptic", "panoptic/160906_band1", "panoptic", "panoptic",
                              {{"sequences", "160906_band1,160906_band2"}, {"every", "1"}}),
                      Dataset("Mvor", "mvor/camma_mvor_2018.json", "mvor", "mvor", {}),
                      Dataset("MvorDays1And3Distorted", "mvor/camma_mvor_2018.json", "mvor", "mvor",
                              {{"days", "1,3"}, {"detections", "none"}, {"distortion", "file"}}),
                      Dataset("MvorWithoutGroundTruth", "mvor/openpose_kps.json", "mvor", "mvor", {{"days", "2"}},
                              false)),
    ReaderFixtureName);

namespace {

using ::testing::HasSubstr;

// Bytes allocated on the heap now (glibc; 0 elsewhere and under sanitizers, which replace malloc).
size_t HeapInUse() {
#if defined(RPT_HAVE_MALLINFO2)
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;
#else
  return 0;
#endif
}

// A long labels file: `labels` labels of 8 persons x 133 COCO-WholeBody joints written as small
// integers, so that its text is about a third of the frames it converts to.
std::filesystem::path WriteLongLabels(const TempDir& dir, int labels) {
  const std::filesystem::path path = dir.path() / "long.json";
  std::ofstream out(path);
  std::string joints;
  for (const std::string& name : CocoWholeBodyJoints()) joints += (joints.empty() ? "\"" : ", \"") + name + "\"";
  std::string person;
  for (size_t j = 0; j < CocoWholeBodyJoints().size(); ++j)
    person += (j == 0 ? "[" : ",[") + std::to_string(j % 7) + ",1,2]";
  out << "[\n";
  for (int i = 0; i < labels; ++i) {
    out << (i == 0 ? "" : ",\n") << R"({"id": "f)" << i << R"(", "timestamp": )" << i << R"(, "joints": [)" << joints
        << R"(], "cameras": [{"name": "c", "K": [[900, 0, 500], [0, 900, 400], [0, 0, 1]], "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]], "T": [0, 0, -3], "width": 1000, "height": 800}], "bodies3D": [)"
        << "[" << person << "],[" << person << "],[" << person << "],[" << person << "],[" << person << "],[" << person
        << "],[" << person << "],[" << person << "]]}";
  }
  out << "\n]\n";
  return path;
}

}  // namespace

// A source of a format read whole (one JSON list) keeps the file, not its converted frames: what
// it holds once open is well under what its frames take once converted, and pulling every frame
// through one buffer does not add to it.
// A frame's simulated detections depend on the number its id ends in, not on its position: the
// frames 3-6 of a sequence, selected alone (as --param frames=3-6 or every= select), get the
// detections the whole sequence's run gives them (they were the whole run's frames 0-3).
TEST(SimulatedDetections, AFramesDetectionsDoNotDependOnTheOtherFramesSelected) {
  TempDir dir;
  Sequence whole = MakeLabelSequence("a", 7, "a_");
  Sequence part = whole;
  part.frames.erase(part.frames.begin(), part.frames.begin() + 3);
  WriteLabels(dir.path() / "whole.json", {whole});
  WriteLabels(dir.path() / "part.json", {part});
  SimulationOptions simulation;
  simulation.seed = 5;
  const auto simulated = [&](const std::string& file) {
    std::vector<std::unique_ptr<FrameSource>> sources = OpenLabels(dir.path() / file, {}, true);
    sources[0] = std::make_unique<SimulatedDetectionsSource>(std::move(sources[0]), simulation);
    return MaterializeAll(std::move(sources)).at(0);
  };
  const Sequence a = simulated("whole.json"), b = simulated("part.json");
  ASSERT_EQ(b.frames.size(), 4u);
  for (size_t f = 0; f < b.frames.size(); ++f) ExpectSameFrame(a.frames[f + 3], b.frames[f]);
  // The whole sequence at once (detector-stats --compare, Python) gives the same numbers.
  Sequence at_once = part;
  SimulateDetections(simulation, &at_once);
  for (size_t f = 0; f < b.frames.size(); ++f) ExpectSameFrame(at_once.frames[f], b.frames[f]);
  // Ids without a number: their position.
  EXPECT_EQ(SimulatedFrameIndex("take_000300", 2), 300u);
  EXPECT_EQ(SimulatedFrameIndex("frame7", 2), 7u);
  EXPECT_EQ(SimulatedFrameIndex("take", 2), 2u);
  EXPECT_EQ(SimulatedFrameIndex("9999999999999999999999", 2), 999999999999999999u) << "the last 18 digits";
}

TEST(ReaderMemory, LabelsSourceHoldsTheFileNotTheConvertedFrames) {
  if (HeapInUse() == 0) GTEST_SKIP() << "heap statistics not available (not glibc, or a sanitizer's allocator)";
  TempDir dir;
  const int kLabels = 600;
  const std::filesystem::path path = WriteLongLabels(dir, kLabels);
  const size_t file_bytes = std::filesystem::file_size(path);

  const size_t before = HeapInUse();
  std::vector<std::unique_ptr<FrameSource>> sources = OpenLabels(path);
  ASSERT_EQ(sources.size(), 1u);
  const size_t opened = HeapInUse();
  SequenceFrame buffer;
  size_t pulled = 0, peak = opened;
  while (sources[0]->Next(&buffer)) {
    ++pulled;
    peak = std::max(peak, HeapInUse());
  }
  ASSERT_EQ(pulled, static_cast<size_t>(kLabels));
  EXPECT_EQ(buffer.gt.num_persons(), 8);
  const size_t frame_bytes = buffer.gt.data.size() * sizeof(double);  // one converted frame's persons
  const size_t held = opened - before;
  EXPECT_LT(held, file_bytes + file_bytes / 4) << "the source holds its file and a small index";
  EXPECT_LT(held, kLabels * frame_bytes / 2) << "the converted frames would take " << kLabels * frame_bytes;
  // Pulling converts one frame at a time: the heap grows by about one frame (and one parsed label).
  EXPECT_LT(peak - opened, 40 * frame_bytes) << "peak while pulling";
}

// Opening converts no frame: a label whose persons are malformed is only seen when it is pulled.
TEST(ReaderMemory, LabelsAreConvertedWhenPulled) {
  TempDir dir;
  const std::string good = R"({"id": "f0", "joints": ["nose"], "bodies3D": [[[0, 0, 1, 1]]],
    "cameras": [{"name": "c", "K": [[900, 0, 500], [0, 900, 400], [0, 0, 1]], "R": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],
                 "T": [0, 0, -3], "width": 1000, "height": 800}], "fps": 10})";
  std::string bad = good;
  bad.replace(bad.find("\"f0\""), 4, "\"f1\"");
  bad.replace(bad.find("[[[0, 0, 1, 1]]]"), 16, "[[[0, 0, 1, 1, 9]]]");
  const auto path = WriteText(dir, "l.json", "[" + good + ",\n" + bad + "]");
  std::vector<std::unique_ptr<FrameSource>> sources = OpenLabels(path);
  ASSERT_EQ(sources.size(), 1u);
  EXPECT_EQ(sources[0]->num_frames(), 2);
  SequenceFrame frame;
  ASSERT_TRUE(sources[0]->Next(&frame));
  EXPECT_EQ(frame.id, "f0");
  EXPECT_DOUBLE_EQ(frame.gt.Person(0)(2, 0), 1.0);
  EXPECT_THAT(InputErrorOf([&] { sources[0]->Next(&frame); }),
              HasSubstr(path.string() + ": /1/bodies3D/0/0: expected [x, y, z, visibility]"));
}

// Without the ground truth, readers that can give frames without their GT files do (frames with
// no persons and no GT joints); the others say why they cannot.
TEST(ReaderWithoutGroundTruth, Shelf4daRunsFromItsDetectionsWithoutGtTxt) {
  RPT_REQUIRE_SHARED_DATA("shelf/4d_association/detection");
  TempDir dir;
  const std::filesystem::path bundle = SharedData("shelf/4d_association");
  std::filesystem::copy_file(bundle / "calibration.json", dir.path() / "calibration.json");
  std::filesystem::create_directories(dir.path() / "detection");
  for (int c = 0; c < 5; ++c) {
    const std::string name = std::to_string(c) + ".txt";
    std::filesystem::create_symlink(bundle / "detection" / name, dir.path() / "detection" / name);
  }
  DatasetRequest request;
  request.dataset = "shelf-4da";
  request.root = dir.path();
  EXPECT_THAT(InputErrorOf([&] { OpenDataset(request); }), HasSubstr("gt.txt"));  // the GT is asked for by default
  request.ground_truth = false;
  const Sequence without = ReadDataset(request)[0];
  request.root = bundle;
  request.ground_truth = true;
  const Sequence with = ReadDataset(request)[0];
  EXPECT_TRUE(without.gt_joints.empty());
  EXPECT_EQ(without.detection_joints, with.detection_joints);
  ASSERT_EQ(without.frames.size(), 301u);
  ASSERT_EQ(without.frames.size(), with.frames.size());
  for (size_t f = 0; f < with.frames.size(); ++f) {
    EXPECT_EQ(without.frames[f].id, with.frames[f].id);
    EXPECT_EQ(without.frames[f].timestamp_s, with.frames[f].timestamp_s);
    EXPECT_EQ(without.frames[f].gt.num_persons(), 0);
    ASSERT_EQ(without.frames[f].views.size(), 5u);
    for (size_t c = 0; c < 5; ++c) EXPECT_EQ(without.frames[f].views[c].data, with.frames[f].views[c].data);
  }
  EXPECT_EQ(without.warnings.items().size(), with.warnings.items().size());
  ValidateSequence(without, "shelf-4da");  // what a run checks
  request.params = {{"detections", "none"}};
  request.ground_truth = false;
  EXPECT_THAT(ErrorMessage<ConfigError>([&] { OpenDataset(request); }),
              HasSubstr("shelf-4da: without the ground truth (gt.txt) the frames come from the detections: pass "
                        "--param detections=openpose"));
}

TEST(ReaderWithoutGroundTruth, ShelfRunsFromTheVoxelPoseCacheWithoutActorsGt) {
  RPT_REQUIRE_SHARED_DATA("shelf/pred_shelf_maskrcnn_hrnet_coco.pkl");
  TempDir dir;
  const std::filesystem::path shelf = SharedData("shelf");
  for (const char* name : {"calibration_shelf.json", "pred_shelf_maskrcnn_hrnet_coco.pkl"}) {
    std::filesystem::copy_file(shelf / name, dir.path() / name);
  }
  DatasetRequest request;
  request.dataset = "shelf";
  request.root = dir.path();
  request.params = {{"frames", "0-3"}, {"detections", "voxelpose"}};
  EXPECT_THAT(InputErrorOf([&] { OpenDataset(request); }), HasSubstr("actorsGT.mat"));
  request.ground_truth = false;
  const Sequence without = ReadDataset(request)[0];
  EXPECT_TRUE(without.gt_joints.empty());
  ASSERT_EQ(without.frames.size(), 4u);
  EXPECT_EQ(without.frames[3].id, "shelf_000003");
  for (const SequenceFrame& frame : without.frames) EXPECT_EQ(frame.gt.num_persons(), 0);
  EXPECT_GE(without.frames[0].views[2].num_persons(), 3);  // the cache has frames 0-2
  EXPECT_EQ(without.frames[3].views[2].num_persons(), 0);
  // Frame 3 is not in the cache: counted as AttachDetections counts it.
  ASSERT_FALSE(without.warnings.items().empty());
  EXPECT_THAT(without.warnings.items().back().Line(),
              HasSubstr("1 frames of the input absent from it, triangulated without detections (first 'shelf_000003')"));
  request.params = {{"frames", "0-3"}};
  EXPECT_THAT(ErrorMessage<ConfigError>([&] { OpenDataset(request); }), HasSubstr("detections=voxelpose"));
}

TEST(ReaderWithoutGroundTruth, ReadersWhoseFramesAreTheGroundTruthSayWhy) {
  for (const char* dataset : {"panoptic", "human36m", "h3wb", "egohumans"}) {
    DatasetRequest request;
    request.dataset = dataset;
    request.root = "/nonexistent";
    request.ground_truth = false;
    EXPECT_THAT(ErrorMessage<ConfigError>([&] { OpenDataset(request); }),
                HasSubstr("cannot run without its ground truth"))
        << dataset;
  }
}

}  // namespace rpt::test
