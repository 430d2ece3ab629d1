// SPDX-License-Identifier: MIT
// `rpt render`: overlays of the 2D detections against the reprojected 3D result, per camera and
// frame, as PNG files and/or MP4 videos, for papers and slides. Takes the same input options as
// `rpt eval` and runs the triangulator with the same --config/--set (so it draws what eval
// evaluates), or with --run DIR draws the predictions.json of an `rpt eval` or `rpt triangulate`
// output folder over its input, re-loaded from the command run.json records (cli/recorded_input.h).
// Each frame's result is projected into the selected cameras (engine/reprojection.h) and drawn
// (engine/render/render_overlay.h) on the camera's image (--images) or on a white canvas of the
// image size.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <optional>

#include "cli/commands.h"
#include "cli/config_args.h"
#include "cli/input_options.h"
#include "cli/recorded_input.h"
#include "core/closest_name.h"
#include "core/errors.h"
#include "core/option_codec.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "datasets/io/staged_output.h"
#include "engine/input.h"
#include "engine/output_place.h"
#include "engine/render/image_codecs.h"
#include "engine/render/render_overlay.h"
#include "engine/render/render_selection.h"
#include "engine/render/render_video.h"
#include "engine/report/report_run.h"
#include "engine/reprojection.h"
#include "engine/run.h"

namespace rpt::cli {
namespace {

struct RenderArgs {
  engine::InputSpec input;
  ConfigArgs config;
  std::string run;  // --run DIR: the recorded predictions over the recorded input
  std::string out;
  std::string frames = "0";
  std::vector<std::string> cameras;
  std::vector<std::string> sequences;
  std::string format = "png";
  double fps = 0;
  std::string images;
  bool gt = false;
  double max_megapixels = 100;  // the image of one camera (a 60000 x 40000 camera took 7.7 GB for one PNG)
};

// A camera's image is allocated whole (canvas, background, encoder): its size is checked before.
void CheckImageSize(const Camera& camera, const std::string& sequence, double max_megapixels) {
  const double megapixels = static_cast<double>(camera.width) * camera.height / 1e6;
  if (megapixels <= max_megapixels) return;
  throw InputError("sequence " + QuoteName(sequence) + ", camera " + QuoteName(camera.name) + ": image " + std::to_string(camera.width) +
                   " x " + std::to_string(camera.height) + " px (" + std::to_string(static_cast<long long>(megapixels)) +
                   " megapixels), above --max-megapixels (" + FormatOption(max_megapixels) +
                   "); raise it if the camera is genuine");
}

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
  if (args.images.empty()) return engine::BlankCanvas(camera);
  const std::string path = engine::ImagePath(args.images, camera.name, camera_idx, frame.id, frame_idx);
  // Only a regular file is read: a FIFO (or a link to one) would block the decoder for ever.
  std::error_code ec;
  cv::Mat image;
  if (std::filesystem::is_regular_file(path, ec)) image = engine::LoadImageCodecs().read_color(path);
  if (image.empty()) {
    if (problems->missing++ == 0) problems->first_missing = path;
    return engine::BlankCanvas(camera);
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
      throw ConfigError("--sequence: the input has no sequence " + QuoteName(name) + DidYouMean(name, names) +
                        " (sequences: " + JoinNames(names) + ")");
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

// One sequence into `root / sequence_file` (root: the staging folder): PNGs and/or videos per
// camera, then its reprojection errors on stdout. File names are engine::UniqueFileNames of the
// camera names and frame ids, so distinct names never share a file; every file is staged and
// renamed into place, and folders are created inside `root` only (io::CreateFolderInside).
// `persons`: the 3D result of every frame of the sequence, its joints `output_joints`.
void RenderSequence(const RenderArgs& args, const Sequence& sequence, const std::vector<Poses3D>& persons,
                    const JointNames& output_joints, const std::filesystem::path& root,
                    const std::string& sequence_file, ImageProblems* problems, long* pngs,
                    std::vector<std::string>* videos) {
  const bool png = args.format != "mp4", mp4 = args.format != "png";
  const engine::FrameRange range =
      engine::ParseFrameRange(args.frames, static_cast<long>(sequence.frames.size()), sequence.name);
  const std::vector<int> cameras = engine::SelectCameras(args.cameras, sequence.cameras, sequence.name);
  for (const int c : cameras) CheckImageSize(sequence.cameras[c], sequence.name, args.max_megapixels);
  std::vector<std::string> camera_names, frame_ids;
  for (const Camera& camera : sequence.cameras) camera_names.push_back(camera.name);
  for (long f = range.first; f < range.end; ++f) frame_ids.push_back(sequence.frames[f].id);
  const std::vector<std::string> camera_files = engine::UniqueFileNames(camera_names);
  const std::vector<std::string> frame_files = engine::UniqueFileNames(frame_ids);
  const std::filesystem::path sequence_dir = io::CreateFolderInside(root, sequence_file);
  if (png) {
    for (const int c : cameras) io::CreateFolderInside(root, std::filesystem::path(sequence_file) / camera_files[c]);
  }
  std::map<int, std::unique_ptr<engine::Mp4Writer>> writers;
  if (mp4) {
    const double fps = args.fps > 0 ? args.fps : (sequence.fps > 0 ? sequence.fps : 10.0);
    for (const int c : cameras) {
      const Camera& camera = sequence.cameras[c];
      const std::filesystem::path path = sequence_dir / (camera_files[c] + ".mp4");
      writers[c] = std::make_unique<engine::Mp4Writer>(path, cv::Size(camera.width, camera.height), fps);
    }
  }
  std::map<int, ErrorSum> errors;
  for (long f = range.first; f < range.end; ++f) {
    const SequenceFrame& frame = sequence.frames[f];
    const std::vector<engine::ViewReprojection> views = engine::ReprojectFrame(
        sequence.cameras, frame.views, sequence.detection_joints, {&persons[f], &output_joints},
        args.gt ? engine::PersonsWithJoints{&frame.gt, &sequence.gt_joints} : engine::PersonsWithJoints{});
    for (const int c : cameras) {
      const Camera& camera = sequence.cameras[c];
      cv::Mat canvas = Background(args, camera, c, frame, f, problems);
      engine::OverlayInput overlay;
      overlay.camera = &camera;
      overlay.detections = c < static_cast<int>(frame.views.size()) ? &frame.views[c] : nullptr;
      overlay.detection_joints = &sequence.detection_joints;
      overlay.reprojection = &views[c];
      overlay.prediction_joints = &output_joints;
      overlay.gt_joints = args.gt ? &sequence.gt_joints : nullptr;
      overlay.title = {sequence.name, "camera " + camera.name, "frame " + frame.id};
      engine::DrawOverlay(overlay, &canvas);
      for (const engine::ReprojectedPerson& p : views[c].predictions) {
        if (p.num_measured > 0)
          errors[c].sum_px += p.mean_error_px * p.num_measured, errors[c].joints += p.num_measured;
      }
      if (png) {
        const std::filesystem::path path = sequence_dir / camera_files[c] / (frame_files[f - range.first] + ".png");
        io::StagedFile file(path, io::NamedBy::kRpt, /*keep_extension=*/true);  // OpenCV picks PNG by the extension
        if (!engine::LoadImageCodecs().write_png(file.path().string(), canvas)) {
          throw InputError(path.string() + ": cannot write the PNG");
        }
        file.Commit();
        ++*pngs;
      }
      if (mp4) writers[c]->Write(canvas);
    }
  }
  for (const auto& [c, writer] : writers) {
    writer->Finish();
    videos->push_back((std::filesystem::path(sequence_file) / (camera_files[c] + ".mp4")).string());
    videos->back() += " (" + std::to_string(writer->frames()) + " frames, " + writer->codec() + ")";
  }
  std::printf("%s: frames %ld to %ld, mean reprojection error of the 3D result against the matched detections:\n",
              PrintableText(sequence.name, LineBreaks::kEscape).c_str(), range.first, range.end - 1);
  // One column of names as wide as the longest (at most 60 characters; a longer name runs on).
  int width = 12;
  for (const int c : cameras) {
    width = std::max(width, std::min(60, static_cast<int>(PrintableText(sequence.cameras[c].name, LineBreaks::kEscape).size())));
  }
  for (const int c : cameras) {
    const ErrorSum& e = errors[c];
    const std::string name = PrintableText(sequence.cameras[c].name, LineBreaks::kEscape);
    if (e.joints > 0) {
      std::printf("  %-*s %7.1f px over %ld joints\n", width, name.c_str(), e.sum_px / e.joints, e.joints);
    } else {
      std::printf("  %-*s       - (no reprojected joint matched a detection)\n", width, name.c_str());
    }
  }
}

// The 3D result of every frame of `sequence`: the whole sequence run as eval runs it (tracking and
// smoothing see every frame).
std::vector<Poses3D> RunSequence(const engine::Config& config, const Sequence& sequence, JointNames* output_joints) {
  engine::RunOptions options;
  options.triangulator = config.triangulator;
  options.eval.reset();
  engine::PredictionsCollector collected(1);
  engine::Run(std::span<const Sequence>(&sequence, 1), options, &collected);
  engine::PredictionsCollector::Sequence& run = collected.sequences().front();
  *output_joints = std::move(run.output_joints);
  return std::move(run.persons);
}

// With --run, the options that name an input or a configuration would be ignored: refused.
void CheckRunExcludes(const RenderArgs& args) {
  const engine::InputSpec& in = args.input;
  const std::pair<bool, const char*> options[] = {
      {!in.dataset.empty(), "--dataset"},
      {!in.root.empty(), "--root"},
      {!in.labels.empty(), "--labels"},
      {!in.detections.empty(), "--detections"},
      {!in.params.empty(), "--param"},
      {in.simulate || in.simulate_perfect || !in.detector.empty(), "--simulate"},
      {!in.mapping.empty(), "the detection mapping options"},
      {!args.config.config_file.empty(), "--config"},
      {!args.config.overrides.empty(), "--set"}};
  for (const auto& [given, name] : options) {
    if (given) {
      throw ConfigError(std::string("--run draws the run's recorded predictions over its recorded input and "
                                    "configuration; ") +
                        name + " does not apply with it");
    }
  }
}

// The input and the 3D result to draw: --run DIR's recorded ones, or the input options' run with
// --config/--set.
struct RenderInput {
  std::vector<Sequence> sequences;
  std::vector<std::vector<Poses3D>> persons;  // per sequence, per frame
  std::vector<JointNames> output_joints;      // per sequence
};

RenderInput RecordedRenderInput(const RenderArgs& args) {
  CheckRunExcludes(args);
  const engine::RecordedRun run = engine::ReadRecordedRun(args.run);
  std::string why;
  std::vector<std::string> warnings;
  std::optional<std::vector<Sequence>> sequences =
      ReloadRecordedInput(run, /*require_same_input=*/false, &why, &warnings);
  for (const std::string& line : warnings) std::fprintf(stderr, "warning: %s\n", PrintableText(line).c_str());
  if (!sequences) throw InputError(args.run + ": cannot re-load the run's input: " + why);
  const std::vector<std::string> words = engine::RecordedWords(run);
  if (args.gt && words.size() > 1 && words[1] == "triangulate") {
    throw ConfigError("--gt: " + args.run + " is an `rpt triangulate` run, which has no ground truth");
  }
  RenderInput input;
  if (!engine::SplitPredictions(run.predictions, *sequences, &input.persons, &why)) {
    throw InputError((run.dir / "predictions.json").string() + ": " + why);
  }
  input.sequences = std::move(*sequences);
  input.output_joints.assign(input.sequences.size(), run.predictions.joints);
  return input;
}

void RunRender(const RenderArgs& args) {
  if (!args.images.empty()) engine::ImagePath(args.images, "", 0, "", 0);  // a bad template fails before any work
  engine::LoadImageCodecs();  // so does a missing image and video module
  RenderInput input;
  if (!args.run.empty()) {
    input = RecordedRenderInput(args);
  } else {
    const engine::Config config = ResolveConfig(args.config);
    InputWarnings warnings;
    // render's --cameras selects the cameras drawn; a calibration (as triangulate's --cameras
    // FILE) comes with --labels, or the run folder of `rpt triangulate` with --run.
    if (args.input.dataset.empty() && args.input.labels.empty()) {
      throw ConfigError("give --run DIR (a folder of `rpt eval` or `rpt triangulate`), --dataset NAME (with --root DIR) "
                        "or --labels FILE; render's --cameras selects the cameras to draw (names or indices), it names "
                        "no calibration file");
    }
    input.sequences = engine::LoadInput(args.input, {}, &warnings);
    PrintInputWarnings(warnings);
    // Run only the sequences drawn.
    const std::vector<const Sequence*> selected = SelectSequences(input.sequences, args.sequences);
    input.persons.resize(input.sequences.size());
    input.output_joints.resize(input.sequences.size());
    for (const Sequence* sequence : selected) {
      const size_t s = static_cast<size_t>(sequence - input.sequences.data());
      input.persons[s] = RunSequence(config, *sequence, &input.output_joints[s]);
    }
  }
  const std::vector<Sequence>& sequences = input.sequences;
  std::string default_name = args.input.dataset.empty() ? "labels" : args.input.dataset;
  if (!args.run.empty()) {
    std::filesystem::path run = std::filesystem::absolute(args.run).lexically_normal();
    if (!run.has_filename()) run = run.parent_path();
    default_name = run.filename().string();
  }
  const std::filesystem::path out_dir = !args.out.empty() ? args.out : "out/render-" + default_name;
  engine::CheckOutputOutsideInput(out_dir, args.input);  // the input options' (empty with --run)
  const bool png = args.format != "mp4";
  ImageProblems problems;
  long pngs = 0;
  std::vector<std::string> videos;
  // Built beside out_dir and swapped in whole at the end, like eval's run folder: an interrupted or
  // failed render leaves the previous one intact; files of the old folder that this render does not
  // write are carried over.
  io::StagedFolder folder(out_dir);
  try {
    const std::vector<const Sequence*> selected = SelectSequences(sequences, args.sequences);
    std::vector<std::string> sequence_names;
    for (const Sequence* sequence : selected) sequence_names.push_back(sequence->name);
    const std::vector<std::string> sequence_files = engine::UniqueFileNames(sequence_names);
    for (size_t s = 0; s < selected.size(); ++s) {
      const Sequence* sequence = selected[s];
      const size_t index = static_cast<size_t>(sequence - sequences.data());
      try {
        RenderSequence(args, *sequence, input.persons[index], input.output_joints[index], folder.path(),
                       sequence_files[s], &problems, &pngs, &videos);
      } catch (const cv::Exception& e) {  // OpenCV allocates images itself: no std::bad_alloc
        if (e.code != cv::Error::StsNoMem) throw;
        throw InputError(sequence->name + ": out of memory drawing the camera images (lower --max-megapixels, or "
                         "render fewer cameras with --cameras)");
      }
    }
    folder.Commit();
  } catch (const InputError& e) {
    throw InputError(folder.NamedAsTarget(e.what()));
  }
  if (png) std::printf("%ld PNG file(s) in %s\n", pngs, PrintableText(out_dir.string()).c_str());
  for (const std::string& video : videos) {
    std::printf(
        "video %s\n",
        PrintableText((out_dir / video).string(), LineBreaks::kEscape).c_str());  // out_dir/<seq>/<cam>.mp4 (...)
  }
  std::fflush(stdout);
  if (problems.missing > 0) {
    std::cerr << "warning: --images: " << problems.missing
              << " image(s) could not be read (first: " << PrintableText(problems.first_missing, LineBreaks::kEscape)
              << "); drawn on a white canvas instead\n";
  }
  if (problems.resized > 0) {
    std::cerr << "warning: --images: " << problems.resized
              << " image(s) differ from the calibrated image size and were resized to it (first: "
              << PrintableText(problems.first_resized, LineBreaks::kEscape) << ")\n";
  }
}

}  // namespace

void RegisterRenderCommand(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* command = app.add_subcommand(
      "render", "Draw the 2D detections against the reprojected 3D result per camera and frame (PNG, MP4)");
  AddInputOptions(command, &args->input);
  AddConfigOptions(command, &args->config);
  command->add_option("--run", args->run,
                      "an `rpt eval` or `rpt triangulate` output folder: draw its predictions.json over its input "
                      "(re-loaded from run.json) instead of running the input options");
  command->add_option("--out", args->out, "output folder (default out/render-<dataset>, with --run render-<folder>)");
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
  command->add_option("--max-megapixels", args->max_megapixels, "a camera with a larger image is refused (memory)")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 1e6));
  command->callback([args] { RunRender(*args); });
}

}  // namespace rpt::cli
