// SPDX-License-Identifier: MIT
// The detection mapping flags (engine/detection_mapping.h) end to end: OpenPose folders of
// another layout (--map-*), the OpenPose joint set, COCO result lists placed by an annotation
// file's images (--coco-images, by file name), --coco-min-score and --coco-keypoints, VoxelPose
// caches with another prefix and camera ids (--voxelpose-prefix, --rename-camera), each
// triangulated and compared with `rpt eval` on the same input; a flag that does not apply exits 2
// naming it; `rpt report` and `rpt render --run` re-load the mapped input from run.json; the real
// MVOR fixture read through the flags gives the dataset reader's predictions.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "datasets/readers/generic_detections.h"
#include "tests/cli/cli_test_util.h"
#include "tests/cli/triangulate_test_util.h"
#include "tests/test_data.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;
using test::Coco17;
using test::ExpectSameFrames;
using test::Ids;
using test::ReadJson;
using DetectionMapping = test::SceneFilesTest;

// Moves an OpenPose folder <camera>/video_<12 digits>_keypoints.json to the flat layout
// <camera>-<frame, 4 digits>.json (which the default pattern does not match).
void FlattenOpenPoseFolder(const fs::path& dir) {
  for (const auto& camera : std::vector<fs::path>(fs::directory_iterator(dir), fs::directory_iterator())) {
    for (const auto& file : std::vector<fs::path>(fs::directory_iterator(camera), fs::directory_iterator())) {
      const std::string name = file.filename().string();  // video_000000000012_keypoints.json
      const int frame = std::stoi(name.substr(6, 12));
      char flat[64];
      std::snprintf(flat, sizeof(flat), "%s-%04d.json", camera.filename().string().c_str(), frame);
      fs::rename(file, dir / flat);
    }
    fs::remove(camera);
  }
}

// The flags that read the flat layout, frame f -> frame id "take_<f + 100, 6 digits>".
const std::string kFlatMapping =
    R"( --map-pattern '([a-z0-9]+)-(\d+)\.json' --map-frame-id 'take_{2:6+100}' --map-camera '{1}')";

std::vector<std::string> Offset(int frames, int first) {
  std::vector<std::string> ids;
  for (int f = 0; f < frames; ++f) ids.push_back(Ids("take_", first + frames)[first + f]);
  return ids;
}

TEST_F(DetectionMapping, OpenPoseFolderOfAnotherLayoutEqualsEval) {
  const fs::path folder = dir_ / "openpose";
  test::WriteOpenPoseFolder(folder, Coco17(scene_, Ids("", kFrames)));
  FlattenOpenPoseFolder(folder);
  const std::string input = " --cameras " + (dir_ / "cameras.json").string() + " --detections " + folder.string();
  const test::CommandResult unmapped = test::RunRpt("triangulate" + input);
  EXPECT_EQ(unmapped.exit_code, 2);
  EXPECT_NE(unmapped.err.find("no file matches the pattern"), std::string::npos) << unmapped.err;
  EXPECT_NE(unmapped.err.find("need --map-pattern '([a-z0-9]+)_(\\d+)_keypoints\\.json'"), std::string::npos)
      << unmapped.err;
  CompareWithEval("openpose_flat", folder, Offset(kFrames, 100), kFlatMapping);
}

TEST_F(DetectionMapping, OpenPoseJointSetIsTheOneAsked) {
  const fs::path folder = dir_ / "openpose";
  test::WriteOpenPoseFolder(folder, Coco17(scene_, Ids("", kFrames)));
  const std::string input = "triangulate --quiet --cameras " + (dir_ / "cameras.json").string() + " --detections " +
                            folder.string() + " --out ";
  const auto joints = [&](const std::string& out, const std::string& flags) {
    const test::CommandResult r = test::RunRpt(input + (dir_ / out).string() + flags);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return r.exit_code == 0 ? ReadJson(dir_ / out / "predictions.json")["joints"] : Json::array();
  };
  const Json body = joints("auto", "");  // COCO-18 files: auto = body
  EXPECT_EQ(body.size(), 17u + 3u) << "COCO-17 and the derived joints";
  EXPECT_EQ(joints("body", " --openpose-joints body"), body);
  const Json feet = joints("feet", " --openpose-joints body-feet");
  EXPECT_EQ(feet.size(), 23u + 3u);
  EXPECT_NE(std::find(feet.begin(), feet.end(), "foot_heel_left"), feet.end());
  const test::CommandResult bad = test::RunRpt(input + (dir_ / "x").string() + " --openpose-joints feet");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--openpose-joints"), std::string::npos) << bad.err;
}

// COCO results with image ids 1, 2, ... and their annotation file: images "<camera>/<frame>.png".
// Person p of a view has score 0.9 - 0.5 p; the keypoints are in `key`; at most `max_persons` per view.
void WriteCocoWithImages(const fs::path& results, const fs::path& annotations, const Detections& detections,
                         const std::string& key = "keypoints", int max_persons = 100) {
  Json list = Json::array(), images = Json::array();
  int image_id = 0;
  for (size_t f = 0; f < detections.frames.size(); ++f) {
    const FrameDetections& frame = detections.frames[f];
    for (size_t c = 0; c < frame.cameras.size(); ++c) {
      ++image_id;
      char file_name[64];
      std::snprintf(file_name, sizeof(file_name), "%s/%06zu.png", frame.cameras[c].c_str(), f);
      images.push_back({{"id", image_id}, {"file_name", file_name}});
      for (int p = 0; p < std::min(max_persons, frame.views[c].num_persons()); ++p) {
        std::vector<double> flat;
        for (int j = 0; j < 17; ++j) {
          for (int r = 0; r < 3; ++r) flat.push_back(frame.views[c].Person(p)(r, j));
        }
        list.push_back({{"image_id", image_id}, {"category_id", 1}, {"score", 0.9 - 0.5 * p}, {key, flat}});
      }
    }
  }
  std::ofstream(results) << list.dump();
  std::ofstream(annotations) << Json{{"images", images}}.dump();
}

TEST_F(DetectionMapping, CocoResultsPlacedByTheAnnotationImagesEqualEval) {
  const fs::path results = dir_ / "results.json", images = dir_ / "images.json";
  WriteCocoWithImages(results, images, Coco17(scene_, Ids("", kFrames)));
  // The default file-name mapping: the folder is the camera, the digits the frame.
  CompareWithEval("coco_images", results, Ids("", kFrames), " --coco-images " + images.string());
  // The same files with frame ids of another form.
  CompareWithEval("coco_mapped", results, Offset(kFrames, 100),
                  " --coco-images " + images.string() +
                      R"( --map-pattern '(cam\d)/(\d+)\.png' --map-frame-id 'take_{2:6+100}' --map-camera '{1}')");
  // Without the annotation file the ids are read as MVOR's, which these are not.
  const std::string input = "triangulate --cameras " + (dir_ / "cameras.json").string() + " --detections " +
                            results.string() + " --out " + (dir_ / "x").string();
  const test::CommandResult mvor = test::RunRpt(input);
  EXPECT_EQ(mvor.exit_code, 2);
  EXPECT_NE(mvor.err.find("is not an MVOR multi-view id"), std::string::npos) << mvor.err;
}

TEST_F(DetectionMapping, CocoMinScoreAndKeypointsKeyAreApplied) {
  const Detections detections = Coco17(scene_, Ids("", kFrames));
  const fs::path images = dir_ / "images.json";
  WriteCocoWithImages(dir_ / "results.json", images, detections, "kps");
  WriteCocoWithImages(dir_ / "first.json", images, detections, "kps", /*max_persons=*/1);
  const std::string input = "triangulate --quiet --cameras " + (dir_ / "cameras.json").string() + " --coco-images " +
                            images.string() + " --coco-keypoints kps --detections ";
  // Scores 0.9, 0.4, ...: a minimum of 0.5 keeps the first person of each view, as if the file
  // held no other.
  const test::CommandResult kept = test::RunRpt(input + (dir_ / "results.json").string() +
                                                " --coco-min-score 0.5 --out " + (dir_ / "kept").string());
  ASSERT_EQ(kept.exit_code, 0) << kept.err;
  const test::CommandResult first =
      test::RunRpt(input + (dir_ / "first.json").string() + " --out " + (dir_ / "first").string());
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const test::CommandResult all =
      test::RunRpt(input + (dir_ / "results.json").string() + " --out " + (dir_ / "all").string());
  ASSERT_EQ(all.exit_code, 0) << all.err;
  const Json k = ReadJson(dir_ / "kept" / "predictions.json");
  EXPECT_EQ(k["frames"], ReadJson(dir_ / "first" / "predictions.json")["frames"]);
  EXPECT_NE(k["frames"], ReadJson(dir_ / "all" / "predictions.json")["frames"]);
  // Without the key the results have no "keypoints": refused, naming the JSON pointer.
  const test::CommandResult no_key = test::RunRpt(
      "triangulate --quiet --cameras " + (dir_ / "cameras.json").string() + " --detections " +
      (dir_ / "results.json").string() + " --coco-images " + images.string() + " --out " + (dir_ / "nokey").string());
  EXPECT_EQ(no_key.exit_code, 2);
  EXPECT_NE(no_key.err.find((dir_ / "results.json").string() + ": /0/keypoints: missing"), std::string::npos)
      << no_key.err;
}

TEST_F(DetectionMapping, RenamedCamerasEqualEval) {
  // Detections naming the cameras "view0".."view3", the calibration "cam0".."cam3".
  Detections detections = Coco17(scene_, Ids("take_", kFrames));
  for (FrameDetections& frame : detections.frames) {
    for (std::string& camera : frame.cameras) camera = "view" + camera.substr(3);
  }
  WriteGenericDetections(dir_ / "views.json", detections);
  std::string renames;
  for (int c = 0; c < 4; ++c) renames += " --rename-camera view" + std::to_string(c) + "=cam" + std::to_string(c);
  CompareWithEval("renamed", dir_ / "views.json", Ids("take_", kFrames), renames);

  const std::string input =
      "triangulate --cameras " + (dir_ / "cameras.json").string() + " --detections " + (dir_ / "views.json").string();
  const test::CommandResult plain = test::RunRpt(input);
  EXPECT_EQ(plain.exit_code, 2);
  EXPECT_NE(plain.err.find("camera 'view0' is not in the calibration"), std::string::npos) << plain.err;
  EXPECT_NE(plain.err.find("; when it is one of those under another name, --rename-camera view0=NAME maps it"),
            std::string::npos)
      << plain.err;
  std::string three_renames;
  for (int c = 0; c < 3; ++c) three_renames += " --rename-camera view" + std::to_string(c) + "=cam" + std::to_string(c);
  const test::CommandResult unused = test::RunRpt(input + three_renames + " --rename-camera view7=cam3");
  EXPECT_EQ(unused.exit_code, 2);
  EXPECT_NE(
      unused.err.find("--rename-camera view7=cam3: " + (dir_ / "views.json").string() + " names no camera 'view7'"),
      std::string::npos)
      << unused.err;
  // A rename to a camera the calibration lacks is that rename's error (the hint was to add one
  // more rename, of the name the user had just made up), with a "did you mean" for a slip.
  for (const auto& [rename, hint] : {std::pair<std::string, std::string>{"view0=cam9", ""},
                                     std::pair<std::string, std::string>{"view0=Cam0", " (did you mean 'cam0'?)"}}) {
    const test::CommandResult wrong = test::RunRpt(input + " --rename-camera " + rename);
    EXPECT_EQ(wrong.exit_code, 2) << rename;
    EXPECT_NE(wrong.err.find("--rename-camera " + rename + ": the calibration " + (dir_ / "cameras.json").string() +
                             " has no camera '" + rename.substr(6) + "' (cameras: cam0, cam1, cam2, cam3)" + hint),
              std::string::npos)
        << wrong.err;
  }
  // A detections camera named as a calibration camera but for case gets the same hint.
  Detections cased = detections;
  for (FrameDetections& frame : cased.frames) {
    for (std::string& camera : frame.cameras) camera = "Cam" + camera.substr(4);
  }
  WriteGenericDetections(dir_ / "cased.json", cased);
  const test::CommandResult case_only = test::RunRpt("triangulate --cameras " + (dir_ / "cameras.json").string() +
                                                     " --detections " + (dir_ / "cased.json").string());
  EXPECT_EQ(case_only.exit_code, 2);
  EXPECT_NE(case_only.err.find("camera 'Cam0' (did you mean 'cam0'?) is not in the calibration"), std::string::npos)
      << case_only.err;
  const test::CommandResult twice = test::RunRpt(input + " --rename-camera view0=cam0 --rename-camera view1=cam0");
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_NE(twice.err.find("two cameras renamed to 'cam0'"), std::string::npos) << twice.err;
  const test::CommandResult syntax = test::RunRpt(input + " --rename-camera view0");
  EXPECT_EQ(syntax.exit_code, 2);
  EXPECT_NE(syntax.err.find("--rename-camera view0: expected FROM=TO"), std::string::npos) << syntax.err;
}

TEST_F(DetectionMapping, VoxelPoseCacheWithPrefixAndCameraIdsEqualsEval) {
  // A cache named otherwise than the frames, keyed by camera ids 0..3 like VoxelPose's.
  scene_.name = "take";
  std::map<std::string, std::string> ids_of;
  std::string renames;
  for (int c = 0; c < 4; ++c) {
    ids_of["cam" + std::to_string(c)] = std::to_string(c);
    renames += " --rename-camera " + std::to_string(c) + "=cam" + std::to_string(c);
  }
  test::WriteVoxelPoseCache(dir_ / "cache.pkl", Coco17(scene_, Ids("take_", kFrames)), ids_of);
  CompareWithEval("pkl_mapped", dir_ / "cache.pkl", Ids("take_", kFrames), " --voxelpose-prefix take" + renames);
  // Without the renames no key names a camera of the calibration: nothing to triangulate.
  const test::CommandResult unnamed =
      test::RunRpt("triangulate --quiet --cameras " + (dir_ / "cameras.json").string() + " --detections " +
                   (dir_ / "cache.pkl").string() + " --out " + (dir_ / "x").string());
  EXPECT_NE(unnamed.err.find("keys of cameras not in the calibration ignored"), std::string::npos) << unnamed.err;
  // rpt convert reads it alone only when told the frame ids; the renames apply too.
  const std::string convert = "convert --detections " + (dir_ / "cache.pkl").string() + " --detections-out " +
                              (dir_ / "converted.json").string();
  const test::CommandResult no_prefix = test::RunRpt(convert);
  EXPECT_EQ(no_prefix.exit_code, 2);
  EXPECT_NE(no_prefix.err.find("--voxelpose-prefix NAME"), std::string::npos) << no_prefix.err;
  const test::CommandResult converted = test::RunRpt(convert + " --voxelpose-prefix take" + renames);
  ASSERT_EQ(converted.exit_code, 0) << converted.err;
  const Json written = ReadJson(dir_ / "converted.json");
  ASSERT_EQ(written["frames"].size(), static_cast<size_t>(kFrames));
  EXPECT_EQ(written["frames"][3]["id"], "take_000003");
  EXPECT_EQ(written["frames"][3]["views"][2]["camera"], "cam2");
}

TEST_F(DetectionMapping, AFlagThatDoesNotApplyExitsWith2NamingIt) {
  const std::vector<std::string> ids = Ids("take_", kFrames);
  WriteGenericDetections(dir_ / "detections.json", Coco17(scene_, ids));
  test::WriteOpenPoseFolder(dir_ / "openpose", Coco17(scene_, Ids("", kFrames)));
  const std::string cameras = "triangulate --cameras " + (dir_ / "cameras.json").string();
  const std::string json = cameras + " --detections " + (dir_ / "detections.json").string();
  const std::string openpose = cameras + " --detections " + (dir_ / "openpose").string();
  const auto expect_refused = [](const std::string& command, const std::string& message) {
    const test::CommandResult r = test::RunRpt(command + " --out /nonexistent/never");
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_NE(r.err.find(message), std::string::npos) << command << "\n" << r.err;
  };
  expect_refused(json + " --openpose-joints body",
                 "--openpose-joints applies to an OpenPose folder, but --detections " +
                     (dir_ / "detections.json").string() + " is generic detections JSON");
  expect_refused(json + " --map-pattern x",
                 "--map-pattern applies to an OpenPose folder or the images of --coco-images");
  expect_refused(openpose + " --coco-min-score 0.5",
                 "--coco-min-score applies to a COCO result list, but --detections " + (dir_ / "openpose").string() +
                     " is an OpenPose folder");
  expect_refused(openpose + " --coco-keypoints kps", "--coco-keypoints applies to a COCO result list");
  expect_refused(openpose + " --coco-images x.json", "--coco-images applies to a COCO result list");
  expect_refused(openpose + " --voxelpose-prefix take", "--voxelpose-prefix applies to a VoxelPose .pkl cache");
  expect_refused(openpose + " --map-pattern '('", "--map-pattern/--map-frame-id/--map-camera: pattern '('");
  expect_refused(openpose + " --map-frame-id '{3:6}'", "a template uses {3}");
  // Without --detections (an input with its own detections): refused too, eval as triangulate.
  expect_refused("eval --dataset synthetic --param frames=2 --simulate --coco-min-score 0.5",
                 "--coco-min-score maps the entries of a detections file: it needs --detections FILE");
  // COCO: the file-name mapping needs the annotation images.
  WriteCocoWithImages(dir_ / "results.json", dir_ / "images.json", Coco17(scene_, Ids("", kFrames)));
  const std::string coco = cameras + " --detections " + (dir_ / "results.json").string();
  expect_refused(coco + " --map-camera '{1}'", "--map-camera maps the file names of the images of --coco-images");
  expect_refused(coco + " --coco-image-ids images", "--coco-image-ids images needs --coco-images FILE");
  expect_refused(coco + " --coco-min-score -1", "--coco-min-score");
}

TEST_F(DetectionMapping, ReportAndRenderReloadTheMappedInput) {
  const fs::path folder = dir_ / "openpose";
  test::WriteOpenPoseFolder(folder, Coco17(scene_, Ids("", kFrames)));
  FlattenOpenPoseFolder(folder);
  const fs::path run = dir_ / "run";
  const test::CommandResult t =
      test::RunRpt("triangulate --quiet --cameras " + (dir_ / "cameras.json").string() + " --detections " +
                   folder.string() + " --fps 25 --out " + run.string() + kFlatMapping);
  ASSERT_EQ(t.exit_code, 0) << t.err;
  // run.json records the command with its mapping flags: the report re-loads the same frames.
  const Json argv = ReadJson(run / "run.json")["argv"];
  EXPECT_NE(std::find(argv.begin(), argv.end(), "take_{2:6+100}"), argv.end()) << argv;
  const test::CommandResult report = test::RunRpt("report " + run.string());
  ASSERT_EQ(report.exit_code, 0) << report.err;
  EXPECT_EQ(report.err.find("warning"), std::string::npos) << report.err;
  EXPECT_NE(report.out.find("frame(s) with 3D scene and camera views"), std::string::npos) << report.out;
  EXPECT_EQ(report.out.find(" 0 frame(s)"), std::string::npos) << "the input was re-loaded: " << report.out;
  // rpt render --run draws the run over the same input: 2 frames x 4 cameras.
  const test::CommandResult render =
      test::RunRpt("render --run " + run.string() + " --frames 0:2 --out " + (dir_ / "render").string());
  ASSERT_EQ(render.exit_code, 0) << render.err;
  EXPECT_NE(render.out.find("8 PNG file(s)"), std::string::npos) << render.out;
  EXPECT_TRUE(fs::exists(dir_ / "render" / "openpose" / "cam0" / "take_000101.png"));
}

// The real Shelf fixture: VoxelPose's cache on the calibration file, its frame ids named with
// --voxelpose-prefix, gives the Shelf reader's predictions (with the reader's frame rate and room).
TEST(DetectionMappingShelf, VoxelPoseCacheOnTheCalibrationGivesTheReadersPredictions) {
  RPT_REQUIRE_SHARED_DATA("shelf/actorsGT.mat");
  RPT_REQUIRE_SHARED_DATA("shelf/pred_shelf_maskrcnn_hrnet_coco.pkl");
  const fs::path dir = test::TempDir("mapping_shelf");
  const std::string cache = test::SharedData("shelf/pred_shelf_maskrcnn_hrnet_coco.pkl").string();
  const test::CommandResult own = test::RunRpt(
      "eval --quiet --dataset shelf --root " + test::SharedData("shelf").string() +
      " --param frames=0-2 --param detections=none --detections " + cache + " --out " + (dir / "own").string());
  ASSERT_EQ(own.exit_code, 0) << own.err;
  const std::string cameras =
      "triangulate --quiet --cameras " + test::SharedData("shelf/calibration_shelf.json").string() + " --detections " +
      cache + " --fps 25" + " --set room_check.size_m=[8,8,2] --set room_check.center_m=[0.45,-0.32,0.8]";
  const test::CommandResult tri = test::RunRpt(cameras + " --voxelpose-prefix shelf --out " + (dir / "tri").string());
  ASSERT_EQ(tri.exit_code, 0) << tri.err;
  const Json a = ReadJson(dir / "own" / "predictions.json"), b = ReadJson(dir / "tri" / "predictions.json");
  ASSERT_EQ(b["frames"].size(), 3u);
  EXPECT_EQ(b["frames"][0]["id"], "shelf_000000");
  ExpectSameFrames(a, b, "shelf");
  // Without the prefix the frame ids are the file's name: the same persons under other ids.
  const test::CommandResult named = test::RunRpt(cameras + " --out " + (dir / "named").string());
  ASSERT_EQ(named.exit_code, 0) << named.err;
  const Json c = ReadJson(dir / "named" / "predictions.json");
  EXPECT_EQ(c["frames"][0]["id"], "pred_shelf_maskrcnn_hrnet_coco_000000");
  EXPECT_EQ(c["frames"][2]["persons"], a["frames"][2]["persons"]);
  fs::remove_all(dir);
}

// The real MVOR fixture: its OpenPose results read with --detections and the flags (placed by the
// annotation file's image file names) give the predictions of the dataset reader's own detections.
TEST(DetectionMappingMvor, AnnotationFileNamesGiveTheReadersPredictions) {
  RPT_REQUIRE_SHARED_DATA("mvor/camma_mvor_2018.json");
  RPT_REQUIRE_SHARED_DATA("mvor/openpose_kps.json");
  const fs::path dir = test::TempDir("mapping_mvor");
  const std::string root = test::SharedData("mvor").string();
  const std::string dataset = "eval --quiet --dataset mvor --root " + root + " --param days=1";
  const test::CommandResult own = test::RunRpt(dataset + " --out " + (dir / "own").string());
  ASSERT_EQ(own.exit_code, 0) << own.err;
  const std::string file = dataset + " --param detections=none --detections " +
                           test::SharedData("mvor/openpose_kps.json").string() + " --coco-images " +
                           test::SharedData("mvor/camma_mvor_2018.json").string();
  const test::CommandResult mapped =
      test::RunRpt(file + R"( --map-pattern 'day(\d+)/cam(\d+)/color/(\d+)\.png' --map-frame-id 'mvor_day{1}_{3:6}')" +
                   R"( --map-camera 'cam{2}' --out )" + (dir / "mapped").string());
  ASSERT_EQ(mapped.exit_code, 0) << mapped.err;
  const Json a = ReadJson(dir / "own" / "predictions.json"), b = ReadJson(dir / "mapped" / "predictions.json");
  ExpectSameFrames(a, b, "mvor");
  // By MVOR's ids, with the annotation file listing the images: the same again.
  const test::CommandResult by_ids = test::RunRpt(file + " --coco-image-ids mvor --out " + (dir / "ids").string());
  ASSERT_EQ(by_ids.exit_code, 0) << by_ids.err;
  ExpectSameFrames(a, ReadJson(dir / "ids" / "predictions.json"), "mvor ids");
  // MVOR's "keypoints" hold its 10 joints, not COCO's: refused, naming the JSON pointer.
  const test::CommandResult ten =
      test::RunRpt(file + " --coco-image-ids mvor --coco-keypoints keypoints --out " + (dir / "ten").string());
  EXPECT_EQ(ten.exit_code, 2);
  EXPECT_NE(ten.err.find("/0/keypoints"), std::string::npos) << ten.err;
  // A minimum person score drops persons.
  const test::CommandResult strict =
      test::RunRpt(file + " --coco-image-ids mvor --coco-min-score 0.6 --out " + (dir / "min").string());
  ASSERT_EQ(strict.exit_code, 0) << strict.err;
  size_t persons = 0, kept = 0;
  const Json m = ReadJson(dir / "min" / "predictions.json");
  for (size_t f = 0; f < a["frames"].size(); ++f) {
    persons += a["frames"][f]["persons"].size();
    kept += m["frames"][f]["persons"].size();
  }
  EXPECT_LT(kept, persons);
  EXPECT_GT(kept, 0u);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt
