// SPDX-License-Identifier: MIT
// `rpt render`: overlays of the 2D detections against the reprojected 3D result, per camera and
// frame, as PNG files and/or MP4 videos, for papers and slides. Takes the same input options as
// `rpt eval` and runs the triangulator with the same --config/--set (so it draws what eval
// evaluates: pass a run folder's config.json to redraw that run), then projects each frame's
// result into the selected cameras (cli/reprojection.h) and draws it (cli/render_overlay.h) on
// the camera's image (--images) or on a white canvas of the image size.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "cli/commands.h"
#include "cli/config_args.h"
#include "cli/load_input.h"
#include "cli/render_overlay.h"
#include "cli/render_selection.h"
#include "cli/render_video.h"
#include "cli/reprojection.h"
#include "cli/run_sequence.h"
#include "core/closest_name.h"
#include "core/errors.h"
#include "core/text.h"

namespace rpt::cli {
namespace {

struct RenderArgs {
  InputArgs input;
  ConfigArgs config;
  std::string out;
  std::string frames = "0";
  std::vector<std::string> cameras;
  std::vector<std::string> sequences;
  std::string format = "png";
  double fps = 0;
  std::string images;
  bool gt = false;
};

// What went wrong with --images, counted and reported once at the end.
struct ImageProblems {
  long missing = 0;
  std::string first_missing;
  long resized = 0;
  std::string first_resized;
};

// The camera's image for this frame, resized to the calibrated size when it differs, or a white
// canvas when there is no template or the file cannot be read.
cv::Mat Background(const RenderArgs& args, const Camera& camera, int camera_idx, const SequenceFrame& frame,
                   long frame_idx, ImageProblems* problems) {
  if (args.images.empty()) return BlankCanvas(camera);
  const std::string path = ImagePath(args.images, camera.name, camera_idx, frame.id, frame_idx);
  cv::Mat image = cv::imread(path, cv::IMREAD_COLOR);
  if (image.empty()) {
    if (problems->missing++ == 0) problems->first_missing = path;
    return BlankCanvas(camera);
  }
  if (image.cols != camera.width || image.rows != camera.height) {
    if (problems->resized++ == 0) {
      problems->first_resized = path + " (" + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                                ", camera " + camera.name + " " + std::to_string(camera.width) + "x" +
                                std::to_string(camera.height) + ")";
    }
    cv::resize(image, image, cv::Size(camera.width, camera.height), 0, 0, cv::INTER_AREA);
  }
  return image;
}

std::vector<const Sequence*> SelectSequences(const std::vector<Sequence>& sequences,
                                             const std::vector<std::string>& wanted) {
  std::vector<const Sequence*> out;
  if (wanted.empty()) {
    for (const Sequence& s : sequences) out.push_back(&s);
    return out;
  }
  std::vector<std::string> names;
  for (const Sequence& s : sequences) names.push_back(s.name);
  for (const std::string& name : wanted) {
    const Sequence* found = nullptr;
    for (const Sequence& s : sequences) found = s.name == name ? &s : found;
    if (found == nullptr) {
      throw ConfigError("--sequence: the input has no sequence '" + name + "'" + DidYouMean(name, names) +
                        " (sequences: " + Join(names) + ")");
    }
    out.push_back(found);
  }
  return out;
}

// Sum and count of the measured reprojection errors of one camera's predictions.
struct ErrorSum {
  double sum_px = 0;
  long joints = 0;
};

void RunRender(const RenderArgs& args) {
  if (!args.images.empty()) ImagePath(args.images, "", 0, "", 0);  // a bad template fails before any work
  const Config config = ResolveConfig(args.config);
  InputWarnings warnings;
  const std::vector<Sequence> sequences = LoadInput(args.input, /*require_detections=*/true, &warnings);
  PrintInputWarnings(warnings);
  const std::filesystem::path out_dir =
      !args.out.empty() ? args.out : "out/render-" + (args.input.dataset.empty() ? "labels" : args.input.dataset);
  const bool png = args.format != "mp4", mp4 = args.format != "png";
  RunOptions options;
  options.triangulator = config.triangulator;
  options.eval = config.metrics;
  options.progress = false;
  ImageProblems problems;
  long pngs = 0;
  std::vector<std::string> videos;
  for (const Sequence* sequence : SelectSequences(sequences, args.sequences)) {
    const FrameRange range = ParseFrameRange(args.frames, static_cast<long>(sequence->frames.size()), sequence->name);
    const std::vector<int> cameras = SelectCameras(args.cameras, sequence->cameras, sequence->name);
    const std::filesystem::path sequence_dir = out_dir / FileNameOf(sequence->name);
    std::error_code ec;
    for (const int c : cameras) {
      std::filesystem::create_directories(png ? sequence_dir / FileNameOf(sequence->cameras[c].name) : sequence_dir,
                                          ec);
      if (ec) throw InputError(sequence_dir.string() + ": cannot create output folder: " + ec.message());
    }
    std::map<int, std::unique_ptr<Mp4Writer>> writers;
    if (mp4) {
      const double fps = args.fps > 0 ? args.fps : (sequence->fps > 0 ? sequence->fps : 10.0);
      for (const int c : cameras) {
        const Camera& camera = sequence->cameras[c];
        const std::filesystem::path path = sequence_dir / (FileNameOf(camera.name) + ".mp4");
        writers[c] = std::make_unique<Mp4Writer>(path, cv::Size(camera.width, camera.height), fps);
      }
    }
    // The whole sequence, as eval runs it (tracking and smoothing see every frame).
    const TriangulatedSequence run = TriangulateSequence(*sequence, options);
    std::map<int, ErrorSum> errors;
    for (long f = range.first; f < range.end; ++f) {
      const SequenceFrame& frame = sequence->frames[f];
      const std::vector<ViewReprojection> views = ReprojectFrame(
          sequence->cameras, frame.views, sequence->detection_joints, {&run.predictions[f], &run.output_joints},
          args.gt ? PersonsWithJoints{&frame.gt, &sequence->gt_joints} : PersonsWithJoints{});
      for (const int c : cameras) {
        const Camera& camera = sequence->cameras[c];
        cv::Mat canvas = Background(args, camera, c, frame, f, &problems);
        OverlayInput overlay;
        overlay.camera = &camera;
        overlay.detections = c < static_cast<int>(frame.views.size()) ? &frame.views[c] : nullptr;
        overlay.detection_joints = &sequence->detection_joints;
        overlay.reprojection = &views[c];
        overlay.prediction_joints = &run.output_joints;
        overlay.gt_joints = args.gt ? &sequence->gt_joints : nullptr;
        overlay.title = sequence->name + "  " + camera.name + "  frame " + frame.id;
        DrawOverlay(overlay, &canvas);
        for (const ReprojectedPerson& p : views[c].predictions) {
          if (p.num_measured > 0)
            errors[c].sum_px += p.mean_error_px * p.num_measured, errors[c].joints += p.num_measured;
        }
        if (png) {
          const std::filesystem::path path = sequence_dir / FileNameOf(camera.name) / (FileNameOf(frame.id) + ".png");
          if (!cv::imwrite(path.string(), canvas)) throw InputError(path.string() + ": cannot write the PNG");
          ++pngs;
        }
        if (mp4) writers[c]->Write(canvas);
      }
    }
    for (const auto& [c, writer] : writers) {
      videos.push_back((sequence_dir / (FileNameOf(sequence->cameras[c].name) + ".mp4")).string() + " (" +
                       std::to_string(writer->frames()) + " frames, " + writer->codec() + ")");
    }
    std::printf("%s: frames %ld to %ld, mean reprojection error of the 3D result against the matched detections:\n",
                sequence->name.c_str(), range.first, range.end - 1);
    for (const int c : cameras) {
      const ErrorSum& e = errors[c];
      if (e.joints > 0) {
        std::printf("  %-12s %7.1f px over %ld joints\n", sequence->cameras[c].name.c_str(), e.sum_px / e.joints,
                    e.joints);
      } else {
        std::printf("  %-12s       - (no reprojected joint matched a detection)\n", sequence->cameras[c].name.c_str());
      }
    }
  }
  if (png) std::printf("%ld PNG file(s) in %s\n", pngs, out_dir.string().c_str());
  for (const std::string& video : videos) std::printf("video %s\n", video.c_str());
  std::fflush(stdout);
  if (problems.missing > 0) {
    std::cerr << "warning: --images: " << problems.missing
              << " image(s) could not be read (first: " << problems.first_missing
              << "); drawn on a white canvas instead\n";
  }
  if (problems.resized > 0) {
    std::cerr << "warning: --images: " << problems.resized
              << " image(s) differ from the calibrated image size and were resized to it (first: "
              << problems.first_resized << ")\n";
  }
}

}  // namespace

void RegisterRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* command = app.add_subcommand(
      "render", "Draw the 2D detections against the reprojected 3D result per camera and frame (PNG, MP4)");
  AddInputOptions(command, &args->input);
  AddConfigOptions(command, &args->config);
  command->add_option("--out", args->out, "output folder (default out/render-<dataset>)");
  command
      ->add_option("--frames", args->frames,
                   "frame indices (0-based): N, A:B (B excluded), A:, :B or : (all); default 0")
      ->capture_default_str();
  command->add_option("--cameras", args->cameras, "cameras by name or 0-based index, e.g. 0,2 (default all)")
      ->delimiter(',');
  command->add_option("--sequence", args->sequences, "only these sequences (repeatable; default all)");
  command->add_option("--format", args->format, "png: one PNG per camera and frame; mp4: one video per camera; both")
      ->check(CLI::IsMember({"png", "mp4", "both"}))
      ->capture_default_str();
  command->add_option("--fps", args->fps, "frame rate of the videos (default: the sequence's, else 10)")
      ->check(CLI::PositiveNumber);
  command->add_option("--images", args->images,
                      "image file template, e.g. 'Shelf/Camera{camera_idx}/img_{frame}.png'; placeholders {camera}, "
                      "{camera_idx}, {frame_id}, {frame} (digits ending the frame id), {frame_idx}; "
                      "{camera_idx:2}/{frame_idx:6} pad with zeros. Default: a white canvas of the image size");
  command->add_flag("--gt", args->gt, "also draw the reprojected ground truth");
  command->callback([args] { RunRender(*args); });
}

}  // namespace rpt::cli
