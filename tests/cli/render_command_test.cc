// SPDX-License-Identifier: MIT
// `rpt render` on a generated scene: PNGs of the camera's size with the reprojected joints drawn
// where the cameras see them, MP4 videos that read back with the right frame count, and its errors.
// Also the selection helpers (engine/render/render_selection.h).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.h"
#include "datasets/readers/generic_detections.h"
#include "engine/frame_sink.h"
#include "engine/input.h"
#include "engine/render/image_codecs.h"
#include "engine/render/render_overlay.h"
#include "engine/render/render_selection.h"
#include "engine/run.h"
#include "tests/cli/cli_test_util.h"
#include "tests/cli/triangulate_test_util.h"
#include "tests/error_message.h"

namespace rpt::cli {
namespace {

namespace fs = std::filesystem;

const char* const kScene =
    "--dataset synthetic --param frames=4 --param cameras=2 --param people=2 --param noise=clean";

engine::InputSpec SceneInput() {
  engine::InputSpec input;
  input.dataset = "synthetic";
  input.params = {"frames=4", "cameras=2", "people=2", "noise=clean"};
  return input;
}

bool IsWhite(const cv::Vec3b& pixel) { return pixel[0] == 255 && pixel[1] == 255 && pixel[2] == 255; }

TEST(RenderCommand, PngsOfTheImageSizeWithTheReprojectedJointsDrawn) {
  const fs::path out = test::TempDir("render_png");
  const test::CommandResult r = test::RunRpt(std::string("render ") + kScene + " --frames 1:3 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("4 PNG file(s)"), std::string::npos) << r.out;  // 2 frames x 2 cameras
  EXPECT_NE(r.out.find("mean reprojection error"), std::string::npos) << r.out;

  // The same scene and triangulation in process: where the 3D result lands in each camera.
  InputWarnings warnings;
  const std::vector<Sequence> sequences = engine::LoadInput(SceneInput(), {}, &warnings);
  ASSERT_EQ(sequences.size(), 1u);
  const Sequence& sequence = sequences[0];
  engine::PredictionsCollector collected(1);
  engine::Run(std::span<const Sequence>(sequences), engine::RunOptions{}, &collected);
  const engine::PredictionsCollector::Sequence& run = collected.sequences().front();
  long checked = 0, drawn = 0, in_colour = 0;
  for (int f = 1; f < 3; ++f) {
    for (const Camera& camera : sequence.cameras) {
      const fs::path path =
          out / engine::FileNameOf(sequence.name) / engine::FileNameOf(camera.name) / (engine::FileNameOf(sequence.frames[f].id) + ".png");
      const cv::Mat image = cv::imread(path.string(), cv::IMREAD_COLOR);
      ASSERT_FALSE(image.empty()) << path;
      EXPECT_EQ(image.cols, camera.width);
      EXPECT_EQ(image.rows, camera.height);
      EXPECT_TRUE(IsWhite(image.at<cv::Vec3b>(image.rows - 2, image.cols - 2))) << "blank canvas: " << path;
      const Poses3D& persons = run.persons[f];
      ASSERT_GT(persons.num_persons(), 0);
      for (int p = 0; p < persons.num_persons(); ++p) {
        const cv::Scalar colour = engine::PersonColour(persons.track_ids[p], p);
        for (int j = 0; j < persons.num_joints; ++j) {
          if (!(persons.Person(p)(3, j) > 0)) continue;
          Eigen::Vector2d uv;
          if (!camera.Project(persons.Person(p).col(j).head<3>(), &uv)) continue;
          const int x = static_cast<int>(std::lround(uv.x())), y = static_cast<int>(std::lround(uv.y()));
          if (x < 0 || y < 0 || x >= camera.width || y >= camera.height) continue;
          if (x < 0.6 * camera.width && y < 0.2 * camera.height) continue;  // the legend, top left
          const cv::Vec3b pixel = image.at<cv::Vec3b>(y, x);
          ++checked;
          drawn += IsWhite(pixel) ? 0 : 1;
          bool same = true;
          for (int k = 0; k < 3; ++k) same &= std::abs(pixel[k] - colour[k]) <= 10;
          in_colour += same ? 1 : 0;
        }
      }
    }
  }
  EXPECT_GT(checked, 40);
  // Every joint is drawn; another person's label (white-outlined text) may cover one (here the
  // held face joints of one person lie under the other's label in frame 1).
  EXPECT_GE(drawn, checked - 2) << drawn << " of " << checked;
  // Joints drawn over by another person's limbs, labels or error lines may differ in colour; most do not.
  EXPECT_GT(in_colour, checked * 3 / 4) << in_colour << " of " << checked;
  fs::remove_all(out);
}

TEST(RenderCommand, Mp4ReadsBackWithOneFramePerRenderedFrame) {
  const fs::path out = test::TempDir("render_mp4");
  const test::CommandResult r =
      test::RunRpt(std::string("render ") + kScene + " --frames : --format mp4 --cameras 1 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  InputWarnings warnings;
  const std::vector<Sequence> sequences = engine::LoadInput(SceneInput(), {}, &warnings);
  const Camera& camera = sequences[0].cameras[1];
  const fs::path video = out / engine::FileNameOf(sequences[0].name) / (engine::FileNameOf(camera.name) + ".mp4");
  // H.264 where the OpenCV build encodes it (Debian 12's does), else MPEG-4 Part 2 (docs/render.md).
  EXPECT_TRUE(r.out.find(video.string() + " (4 frames, avc1)") != std::string::npos ||
              r.out.find(video.string() + " (4 frames, mp4v)") != std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(out / engine::FileNameOf(sequences[0].name) / (engine::FileNameOf(sequences[0].cameras[0].name) + ".mp4")))
      << "only the selected camera";
  cv::VideoCapture capture(video.string());
  ASSERT_TRUE(capture.isOpened()) << video;
  EXPECT_EQ(capture.get(cv::CAP_PROP_FRAME_COUNT), 4);
  cv::Mat frame;
  int decoded = 0;
  while (capture.read(frame)) {
    ++decoded;
    EXPECT_EQ(frame.cols, camera.width);
    EXPECT_EQ(frame.rows, camera.height);
  }
  EXPECT_EQ(decoded, 4);
  EXPECT_FALSE(fs::exists(out / engine::FileNameOf(sequences[0].name) / engine::FileNameOf(camera.name)))
      << "no PNGs with --format mp4";
  fs::remove_all(out);
}

TEST(RenderCommand, DrawsOnTheImagesOfTheTemplateAndWarnsAboutMissingOnes) {
  const fs::path out = test::TempDir("render_images");
  InputWarnings warnings;
  const std::vector<Sequence> sequences = engine::LoadInput(SceneInput(), {}, &warnings);
  const Camera& camera = sequences[0].cameras[0];
  // A solid blue image for camera 0, frame 0 only; camera 1's is a FIFO (not read: it would block
  // the decoder for ever), the others are missing.
  const cv::Mat blue(camera.height, camera.width, CV_8UC3, cv::Scalar(200, 0, 0));
  ASSERT_TRUE(cv::imwrite((out / ("cam0_" + sequences[0].frames[0].id + ".png")).string(), blue));
  ASSERT_EQ(mkfifo((out / ("cam1_" + sequences[0].frames[0].id + ".png")).c_str(), 0600), 0);
  const test::CommandResult r = test::RunRpt(std::string("render ") + kScene + " --out " + out.string() +
                                             " --images '" + out.string() + "/cam{camera_idx}_{frame_id}.png'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("warning: --images: 1 image(s) could not be read (first: " + out.string() + "/cam1_"),
            std::string::npos)
      << r.err;
  const fs::path dir = out / engine::FileNameOf(sequences[0].name);
  const cv::Mat drawn = cv::imread((dir / engine::FileNameOf(camera.name) / (sequences[0].frames[0].id + ".png")).string());
  ASSERT_FALSE(drawn.empty());
  EXPECT_EQ(drawn.at<cv::Vec3b>(drawn.rows - 2, drawn.cols - 2), cv::Vec3b(200, 0, 0));
  const cv::Mat blank =
      cv::imread((dir / engine::FileNameOf(sequences[0].cameras[1].name) / (sequences[0].frames[0].id + ".png")).string());
  ASSERT_FALSE(blank.empty());
  EXPECT_TRUE(IsWhite(blank.at<cv::Vec3b>(blank.rows - 2, blank.cols - 2)));
  fs::remove_all(out);
}

TEST(RenderCommand, BadSelectionsExitTwoNamingTheOption) {
  const fs::path out = test::TempDir("render_errors");
  const std::string base = std::string("render ") + kScene + " --out " + out.string();
  const struct {
    std::string args;
    std::string message;
  } cases[] = {
      {" --frames 10:20", "error: --frames 10:20: sequence 'synthetic' has 4 frames (0 to 3)"},
      {" --frames 2:1", "error: --frames 2:1: the range is empty"},
      {" --frames x", "error: --frames x: expected N, A:B, A:, :B or :"},
      {" --cameras 7", "error: --cameras: sequence 'synthetic' has no camera '7'"},
      {" --images 'a{fram}.png'", "error: --images a{fram}.png: unknown placeholder {fram}; did you mean {frame}?"},
      {" --sequence nope", "error: --sequence: the input has no sequence 'nope' (sequences: synthetic)"},
  };
  for (const auto& c : cases) {
    const test::CommandResult r = test::RunRpt(base + c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
  }
  EXPECT_EQ(test::RunRpt(base + " --format gif").exit_code, 2);
  // triangulate's `--cameras FILE` habit: render's --cameras selects cameras, and the error says so
  // (it was only "give one of --dataset NAME ..., --labels FILE").
  const test::CommandResult calibration =
      test::RunRpt("render --cameras cameras.json --detections d.json --out " + out.string());
  EXPECT_EQ(calibration.exit_code, 2);
  EXPECT_NE(calibration.err.find("error: give --run DIR (a folder of `rpt eval` or `rpt triangulate`), --dataset NAME "
                                 "(with --root DIR) or --labels FILE; render's --cameras selects the cameras to draw"),
            std::string::npos)
      << calibration.err;
  fs::remove_all(out);
}

// The lines of the reprojection errors per camera ("  cam0   10.6 px over 64 joints").
std::vector<std::string> ErrorLines(const std::string& out) {
  std::vector<std::string> lines;
  std::stringstream s(out);
  for (std::string line; std::getline(s, line);) {
    if (line.find(" px over ") != std::string::npos) lines.push_back(line);
  }
  return lines;
}

// The share of the pixels of two images of the same size that differ.
double DifferentPixels(const fs::path& a, const fs::path& b) {
  const cv::Mat x = cv::imread(a.string(), cv::IMREAD_COLOR), y = cv::imread(b.string(), cv::IMREAD_COLOR);
  EXPECT_FALSE(x.empty()) << a;
  EXPECT_FALSE(y.empty()) << b;
  if (x.empty() || y.empty() || x.size() != y.size()) return 1;
  cv::Mat diff;
  cv::absdiff(x, y, diff);
  cv::cvtColor(diff, diff, cv::COLOR_BGR2GRAY);
  return static_cast<double>(cv::countNonZero(diff)) / static_cast<double>(diff.total());
}

// --run DIR draws an eval or a triangulate run's predictions over its re-loaded input.
class RenderRun : public test::SceneFilesTest {};

TEST_F(RenderRun, DrawsTheRecordedPredictionsOfEvalAndTriangulateRuns) {
  const std::vector<std::string> ids = test::Ids("take_", kFrames);
  WriteGenericDetections(dir_ / "detections.json", test::Coco17(scene_, ids));
  test::WriteLabelsAs(dir_ / "labels.json", scene_, ids);
  const std::string detections = " --detections " + (dir_ / "detections.json").string();
  const std::string labels = " --labels " + (dir_ / "labels.json").string() + detections;
  const fs::path eval = dir_ / "eval", tri = dir_ / "tri";
  ASSERT_EQ(test::RunRpt("eval --quiet" + labels + " --out " + eval.string()).exit_code, 0);
  const test::CommandResult t = test::RunRpt("triangulate --quiet --cameras " + (dir_ / "cameras.json").string() +
                                             detections + " --fps 25 --out " + tri.string());
  ASSERT_EQ(t.exit_code, 0) << t.err;

  // The eval run redrawn equals a render of the same input (the predictions.json's rounding to
  // micrometres moves no more than a few anti-aliased pixels).
  const test::CommandResult direct =
      test::RunRpt("render" + labels + " --frames 3:5 --out " + (dir_ / "direct").string());
  ASSERT_EQ(direct.exit_code, 0) << direct.err;
  const test::CommandResult from_eval =
      test::RunRpt("render --run " + eval.string() + " --frames 3:5 --gt --out " + (dir_ / "from_eval").string());
  ASSERT_EQ(from_eval.exit_code, 0) << from_eval.err;
  const test::CommandResult from_tri =
      test::RunRpt("render --run " + tri.string() + " --frames 3:5 --out " + (dir_ / "from_tri").string());
  ASSERT_EQ(from_tri.exit_code, 0) << from_tri.err;
  EXPECT_EQ(from_tri.err, "") << "no warning: the input is verified as the run's";
  EXPECT_NE(from_tri.out.find("8 PNG file(s)"), std::string::npos) << from_tri.out;  // 2 frames x 4 cameras
  const std::vector<std::string> errors = ErrorLines(direct.out);
  ASSERT_EQ(errors.size(), 4u) << direct.out;
  EXPECT_EQ(ErrorLines(from_eval.out), errors) << "the same predictions, the same errors";
  EXPECT_EQ(ErrorLines(from_tri.out), errors) << "triangulate's predictions are eval's";
  const std::string sequence = scene_.name;
  for (const char* camera : {"cam0", "cam3"}) {
    const fs::path png = fs::path(camera) / "take_000004.png";
    EXPECT_LT(DifferentPixels(dir_ / "direct" / sequence / png, dir_ / "from_tri" / "detections" / png), 0.02)
        << "the same persons drawn; only the title differs (the sequence's name)";
    // --gt adds the ground truth to the eval run's drawing: more pixels differ than without.
    EXPECT_GT(DifferentPixels(dir_ / "direct" / sequence / png, dir_ / "from_eval" / sequence / png), 0.0);
  }
  const test::CommandResult same =
      test::RunRpt("render --run " + eval.string() + " --frames 3:5 --out " + (dir_ / "from_eval_nogt").string());
  ASSERT_EQ(same.exit_code, 0) << same.err;
  for (const char* camera : {"cam0", "cam3"}) {
    const fs::path png = fs::path(sequence) / camera / "take_000004.png";
    EXPECT_LT(DifferentPixels(dir_ / "direct" / png, dir_ / "from_eval_nogt" / png), 1e-3) << png;
  }
  EXPECT_TRUE(fs::exists(dir_ / "direct" / sequence / "cam0" / "take_000003.png"));

  // Refused: --gt without GT, input or configuration options beside --run, a folder that is no run.
  const auto expect_refused = [](const std::string& args, const std::string& message) {
    const test::CommandResult r = test::RunRpt("render " + args + " --out /nonexistent/never");
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
  };
  expect_refused("--run " + tri.string() + " --gt", "is an `rpt triangulate` run, which has no ground truth");
  expect_refused("--run " + tri.string() + labels, "--labels does not apply with it");
  expect_refused("--run " + tri.string() + " --set smooth.mode=causal", "--set does not apply with it");
  expect_refused("--run " + (dir_ / "nothing").string(), "nothing");
}

// A 640 x 480 camera and a person of two joints (nose, neck) that no detection measured: what the
// overlay tests draw.
Camera OverlayCamera() {
  Camera camera;
  camera.name = "c";
  camera.width = 640;
  camera.height = 480;
  return camera;
}
engine::ReprojectedPerson UnmeasuredPerson(int track, const Eigen::Vector2d& nose, const Eigen::Vector2d& neck) {
  engine::ReprojectedPerson person;
  person.person_idx = track;
  person.track_id = track;
  person.uv_px = Eigen::Matrix2Xd(2, 2);
  person.uv_px << nose.x(), neck.x(), nose.y(), neck.y();
  person.status = {engine::JointReprojection::kNotDetected, engine::JointReprojection::kNotDetected};
  person.error_px = {std::nan(""), std::nan("")};
  person.mean_error_px = std::nan("");
  return person;
}

// The legend goes to the corner that covers nobody: a person drawn in the top-left corner sends it
// to the top right (black legend text there, none at the top left); a title longer than the image
// is cut to fit (no legend text in the image's last columns).
TEST(RenderOverlay, TheLegendAvoidsThePersonsAndFitsTheImage) {
  const Camera camera = OverlayCamera();
  const JointNames joints = {"nose", "neck"};
  engine::ViewReprojection view;
  view.predictions.push_back(UnmeasuredPerson(0, {40, 30}, {120, 90}));
  const auto draw = [&](std::vector<std::string> title) {
    cv::Mat canvas = engine::BlankCanvas(camera);
    engine::DrawOverlay({.camera = &camera, .reprojection = &view, .prediction_joints = &joints, .title = title},
                        &canvas);
    return canvas;
  };
  const auto black_pixels = [](const cv::Mat& canvas, const cv::Rect& box) {
    int black = 0;
    for (int y = box.y; y < box.y + box.height; ++y) {
      for (int x = box.x; x < box.x + box.width; ++x) {
        const cv::Vec3b& p = canvas.at<cv::Vec3b>(y, x);
        black += p[0] < 60 && p[1] < 60 && p[2] < 60 ? 1 : 0;
      }
    }
    return black;
  };
  const cv::Mat short_title = draw({"seq", "camera c", "frame 7"});
  EXPECT_GT(black_pixels(short_title, cv::Rect(400, 0, 240, 60)), 50) << "the legend at the top right";
  EXPECT_EQ(black_pixels(short_title, cv::Rect(0, 0, 200, 60)), 0) << "nothing over the person at the top left";
  const cv::Mat long_title = draw({std::string(400, 'x'), "camera c", "frame 7"});
  // As wide as the image, the legend covers the person at the top: it goes to the bottom left.
  EXPECT_GT(black_pixels(long_title, cv::Rect(0, 330, 640, 150)), 200) << "the legend at the bottom";
  EXPECT_EQ(black_pixels(long_title, cv::Rect(636, 0, 4, 480)), 0) << "the title runs past the image";
}

// Two persons whose labels would fall on the same place: the second is moved clear of the first
// (the rows of the two tracks' label colours above the persons do not overlap; they did).
TEST(RenderOverlay, LabelsOfACrowdDoNotOverlap) {
  const Camera camera = OverlayCamera();
  const JointNames joints = {"nose", "neck"};
  engine::ViewReprojection view;
  for (int track = 0; track < 2; ++track) {  // both at the same place: labels at the same spot
    view.predictions.push_back(UnmeasuredPerson(track, {320, 300}, {320, 400}));
  }
  cv::Mat canvas = engine::BlankCanvas(camera);
  engine::DrawOverlay({.camera = &camera, .reprojection = &view, .prediction_joints = &joints, .title = {"t"}}, &canvas);
  // Rows above the persons (y < 295) holding pixels of each track's colour.
  int first[2] = {-1, -1}, last[2] = {-1, -1};
  for (int track = 0; track < 2; ++track) {
    const cv::Scalar colour = engine::PersonColour(track, track);
    for (int y = 0; y < 295; ++y) {
      for (int x = 200; x < 440; ++x) {
        const cv::Vec3b& p = canvas.at<cv::Vec3b>(y, x);
        if (std::abs(p[0] - colour[0]) + std::abs(p[1] - colour[1]) + std::abs(p[2] - colour[2]) > 30) continue;
        if (first[track] < 0) first[track] = y;
        last[track] = y;
        break;
      }
    }
    ASSERT_GE(first[track], 0) << "track " << track << "'s label is drawn";
  }
  EXPECT_TRUE(last[1] < first[0] || last[0] < first[1])
      << "rows " << first[0] << "-" << last[0] << " and " << first[1] << "-" << last[1];
}

// The image and video module (engine/render/image_codecs.h): found where the build put it, its
// PNG functions read back what they wrote; a missing or foreign module names every place tried.
TEST(ImageCodecs, TheBuiltModuleWritesAndReadsPngs) {
  const engine::ImageCodecs& codecs = engine::LoadImageCodecs();
  EXPECT_EQ(codecs.version, engine::kImageCodecsVersion);
  cv::Mat image(7, 5, CV_8UC3, cv::Scalar(10, 20, 30));
  image.at<cv::Vec3b>(3, 2) = cv::Vec3b(200, 100, 0);
  const fs::path png = test::TempDir("codecs") / "x.png";
  ASSERT_TRUE(codecs.write_png(png.string(), image));
  const cv::Mat back = codecs.read_color(png.string());
  ASSERT_EQ(back.size(), image.size());
  EXPECT_EQ(cv::norm(back, image, cv::NORM_INF), 0.0);
  EXPECT_TRUE(codecs.read_color((png.parent_path() / "missing.png").string()).empty());
}

TEST(ImageCodecs, AModuleThatDoesNotLoadNamesEveryPlaceTried) {
  const fs::path dir = test::TempDir("codecs_missing");
  const fs::path text = dir / engine::kImageCodecsFile;
  std::ofstream(text) << "not a shared library\n";
  const std::vector<fs::path> places = {dir / "none" / engine::kImageCodecsFile, text};
  const std::string message = test::ErrorMessage<InstallationError>([&] { engine::LoadImageCodecsFrom(places); });
  EXPECT_NE(message.find("rpt render needs its image and video module librpt_image_codecs.so"), std::string::npos)
      << message;
  EXPECT_NE(message.find(places[0].string() + ": "), std::string::npos) << message;
  EXPECT_NE(message.find(places[1].string() + ": "), std::string::npos) << message;
  // The build's own module does load from that list's end.
  const std::vector<fs::path> with_build = {places[0], engine::ImageCodecsPlaces().back()};
  EXPECT_EQ(engine::LoadImageCodecsFrom(with_build).version, engine::kImageCodecsVersion);
}

TEST(RenderSelection, FrameRanges) {
  const auto range = [](const std::string& text) {
    const engine::FrameRange r = engine::ParseFrameRange(text, 10, "s");
    return std::make_pair(r.first, r.end);
  };
  EXPECT_EQ(range("3"), std::make_pair(3L, 4L));
  EXPECT_EQ(range("2:5"), std::make_pair(2L, 5L));
  EXPECT_EQ(range("2:"), std::make_pair(2L, 10L));
  EXPECT_EQ(range(":4"), std::make_pair(0L, 4L));
  EXPECT_EQ(range(":"), std::make_pair(0L, 10L));
  EXPECT_EQ(range("8:50"), std::make_pair(8L, 10L));  // clipped to the sequence
  EXPECT_THROW(range("10"), ConfigError);
  EXPECT_THROW(range("-1"), ConfigError);
  EXPECT_THROW(range("1:x"), ConfigError);
}

TEST(RenderSelection, CamerasByNameOrIndex) {
  std::vector<Camera> cameras(3);
  cameras[0].name = "left";
  cameras[1].name = "2";  // a name that looks like an index wins over the index
  cameras[2].name = "right";
  EXPECT_EQ(engine::SelectCameras({}, cameras, "s"), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(engine::SelectCameras({"right", "0"}, cameras, "s"), (std::vector<int>{2, 0}));
  EXPECT_EQ(engine::SelectCameras({"2"}, cameras, "s"), (std::vector<int>{1}));
  EXPECT_EQ(test::ErrorMessage<ConfigError>([&] { engine::SelectCameras({"rigth"}, cameras, "s"); }),
            "--cameras: sequence 's' has no camera 'rigth'; did you mean 'right'? (cameras: left, 2, right, or their "
            "indices 0 to 2)");
}

TEST(RenderSelection, ImagePathTemplates) {
  EXPECT_EQ(engine::ImagePath("Shelf/Camera{camera_idx}/img_{frame}.png", "Camera3", 3, "shelf_000300", 0),
            "Shelf/Camera3/img_000300.png");
  EXPECT_EQ(engine::ImagePath("{camera}/{frame_idx:6}.jpg", "00_03", 2, "x", 17), "00_03/000017.jpg");
  EXPECT_EQ(engine::ImagePath("c{camera_idx:2}_{frame_id}_{frame}", "a", 4, "noDigits", 0), "c04_noDigits_noDigits");
  EXPECT_THROW(engine::ImagePath("{frame", "a", 0, "f", 0), ConfigError);
  EXPECT_THROW(engine::ImagePath("{camera:3}", "a", 0, "f", 0), ConfigError);
}

// Distinct names never share a file: the cleaning is one-to-one (%XX), made unique also where case
// or a cut long name would join two (issue 19: 'cam a' and 'cam/a' were both 'cam_a').
TEST(RenderSelection, FileNamesAreOneToOne) {
  EXPECT_EQ(engine::FileNameOf("panoptic/160906 band1"), "panoptic%2F160906%20band1");
  EXPECT_EQ(engine::FileNameOf("cam a"), "cam%20a");
  EXPECT_EQ(engine::FileNameOf("cam/a"), "cam%2Fa");
  EXPECT_EQ(engine::FileNameOf("cam_a"), "cam_a");
  EXPECT_EQ(engine::FileNameOf("cam%20a"), "cam%2520a");
  EXPECT_EQ(engine::FileNameOf("Camera0.v2"), "Camera0.v2");
  EXPECT_EQ(engine::FileNameOf(".."), "%2E.");
  EXPECT_EQ(engine::FileNameOf("."), "%2E");
  EXPECT_EQ(engine::FileNameOf(".hidden"), "%2Ehidden");
  EXPECT_EQ(engine::FileNameOf(""), "%");
  EXPECT_EQ(engine::FileNameOf("\xc3\xa9\x1b"), "%C3%A9%1B");
  const std::string long_a(300, 'a'), long_b = std::string(299, 'a') + "b";
  const std::string cut_a = engine::FileNameOf(long_a), cut_b = engine::FileNameOf(long_b);
  EXPECT_EQ(cut_a.size(), 180u + 17u);
  EXPECT_EQ(cut_a.substr(0, 181), std::string(180, 'a') + "~");
  EXPECT_NE(cut_a, cut_b);
  EXPECT_LE(engine::FileNameOf(std::string(300, '/')).size(), 200u);
  EXPECT_EQ(engine::FileNameOf(std::string(300, '/')).substr(0, 180), [] {
    std::string s;
    for (int i = 0; i < 60; ++i) s += "%2F";
    return s;
  }()) << "a cut never splits a %XX";

  const std::vector<std::string> texts = {"cam a", "cam/a", "cam_a", "Cam_A", "cam_a~2", "", "%", "."};
  const std::vector<std::string> names = engine::UniqueFileNames(texts);
  EXPECT_EQ(names,
            (std::vector<std::string>{"cam%20a", "cam%2Fa", "cam_a", "Cam_A~2", "cam_a%7E2", "%", "%25", "%2E"}));
  std::set<std::string> lower;
  for (std::string name : names) {
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    lower.insert(name);
  }
  EXPECT_EQ(lower.size(), texts.size());
}

}  // namespace
}  // namespace rpt::cli
