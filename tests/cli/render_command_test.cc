// SPDX-License-Identifier: MIT
// `rpt render` on a generated scene: PNGs of the camera's size with the reprojected joints drawn
// where the cameras see them, MP4 videos that read back with the right frame count, and its errors.
// Also the selection helpers (engine/render/render_selection.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <string>
#include <vector>

#include "engine/input.h"
#include "engine/render/render_overlay.h"
#include "engine/render/render_selection.h"
#include "engine/frame_sink.h"
#include "engine/run.h"
#include "core/errors.h"
#include "tests/cli/cli_test_util.h"
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
  long checked = 0, in_colour = 0;
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
          EXPECT_FALSE(IsWhite(pixel)) << path << " joint " << j << " of person " << p << " at " << x << "," << y;
          bool same = true;
          for (int k = 0; k < 3; ++k) same &= std::abs(pixel[k] - colour[k]) <= 10;
          in_colour += same ? 1 : 0;
        }
      }
    }
  }
  EXPECT_GT(checked, 40);
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
  // A solid blue image for camera 0, frame 0 only; camera 1's is missing.
  const cv::Mat blue(camera.height, camera.width, CV_8UC3, cv::Scalar(200, 0, 0));
  ASSERT_TRUE(cv::imwrite((out / ("cam0_" + sequences[0].frames[0].id + ".png")).string(), blue));
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
  fs::remove_all(out);
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
