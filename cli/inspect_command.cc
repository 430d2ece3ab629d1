// SPDX-License-Identifier: MIT
// `rpt inspect`: what a dataset input contains, and whether its conventions agree: per camera, the
// distance between the projected ground truth and the nearest 2D detection (pixels and relative
// to the person's box), and whether detections fit the GT of another frame better. A wrong axis,
// unit, distortion or camera order shows at once as hundreds of pixels. The same checks give
// eval's warnings (engine/detection_checks.h), printed here too.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include "core/printable_text.h"
#include "datasets/io/json_output.h"
#include "cli/commands.h"
#include "engine/diagnostics.h"
#include "cli/input_options.h"
#include "engine/input.h"
#include "engine/detection_checks.h"

namespace rpt::cli {
namespace {

struct InspectArgs {
  engine::InputSpec input;
  bool json = false;
};

void PrintReport(const nlohmann::ordered_json& report, const std::vector<std::string>& shift_lines);

void RunInspect(const InspectArgs& args) {
  InputWarnings input_warnings;
  const std::vector<Sequence> sequences = engine::LoadInput(args.input, {.detections = false}, &input_warnings);
  PrintInputWarnings(input_warnings);
  nlohmann::ordered_json report = nlohmann::ordered_json::array();
  std::vector<std::string> shift_lines;
  std::vector<std::string> warnings;
  for (const Sequence& s : sequences) {
    long persons = 0, frames_with_views = 0;
    for (const SequenceFrame& f : s.frames) {
      persons += f.gt.num_persons();
      // At least one person in some view: frames the detections list as empty (or lack) do not count.
      frames_with_views +=
          std::any_of(f.views.begin(), f.views.end(), [](const Poses2D& view) { return view.num_persons() > 0; });
    }
    // All frames are measured: inspect is run on purpose, eval samples.
    engine::DetectionCheckOptions check_options;
    check_options.max_frames = 0;
    check_options.shift_frames = 0;
    const engine::SequenceCheck check = engine::CheckDetections(s, TrackOptions{}.max_gap_s, check_options);
    nlohmann::ordered_json seq;
    seq["sequence"] = s.name;
    seq["frames"] = s.frames.size();
    seq["frames_with_detections"] = frames_with_views;
    seq["gt_persons"] = persons;
    seq["gt_joints"] = s.gt_joints.size();
    seq["detection_joints"] = s.detection_joints.size();
    seq["room_center_m"] = {s.room.center_m.x(), s.room.center_m.y(), s.room.center_m.z()};
    seq["room_size_m"] = {s.room.size_m.x(), s.room.size_m.y(), s.room.size_m.z()};
    seq["cameras"] = nlohmann::ordered_json::array();
    for (size_t c = 0; c < s.cameras.size(); ++c) {
      const Camera& camera = s.cameras[c];
      const engine::CameraCheck& measured = check.cameras[c];
      const Eigen::Vector3d center = camera.Center();
      nlohmann::ordered_json cam;
      cam["name"] = camera.name;
      cam["center_m"] = {center.x(), center.y(), center.z()};
      cam["image"] = {camera.width, camera.height};
      cam["model"] = DistortionModelName(camera.model);
      cam["focal_px"] = {camera.K(0, 0), camera.K(1, 1)};
      cam.update(engine::CameraCheckJson(measured));
      seq["cameras"].push_back(cam);
    }
    seq["frame_shift"] = engine::ShiftCheckJson(check.shift);
    shift_lines.push_back(engine::ShiftLine(check.shift));
    seq["warnings"] = nlohmann::ordered_json::array();
    // Without detections (none given, none of the reader's own) the checks that compare them with
    // the ground truth would blame frame ids and joint names: one line says what is missing.
    const std::vector<engine::CheckWarning> checks =
        s.detection_joints.empty()
            ? std::vector<engine::CheckWarning>{{"no_detections", s.name + ": no 2D detections (pass --detections FILE "
                                                                           "or --simulate to compare them with the "
                                                                           "ground truth): cameras and ground truth only"}}
            : engine::DetectionWarnings(check);
    for (const engine::CheckWarning& w : checks) {
      seq["warnings"].push_back({{"code", w.code}, {"message", w.message}});
      warnings.push_back(w.message);
    }
    report.push_back(seq);
  }
  if (args.json) {
    std::cout << io::DumpJson(report, 2) << "\n";  // invalid UTF-8 (a name) as U+FFFD, not an error
  } else {
    PrintReport(report, shift_lines);
  }
  std::fflush(stdout);
  for (const std::string& w : warnings) std::cerr << "warning: " << PrintableText(w) << "\n";
}

void PrintReport(const nlohmann::ordered_json& report, const std::vector<std::string>& shift_lines) {
  for (size_t i = 0; i < report.size(); ++i) {
    const auto& seq = report[i];
    std::printf(
        "sequence %s: %d frames (%d with detections), %ld GT person-frames, %d GT joints, %d detection joints\n",
        PrintableText(seq["sequence"].get<std::string>(), LineBreaks::kEscape).c_str(), seq["frames"].get<int>(),
        seq["frames_with_detections"].get<int>(), seq["gt_persons"].get<long>(), seq["gt_joints"].get<int>(),
        seq["detection_joints"].get<int>());
    const auto& size = seq["room_size_m"];
    if (size[0].get<double>() <= 0 && size[1].get<double>() <= 0 && size[2].get<double>() <= 0) {
      std::printf("  room: none (nothing is dropped for being outside it; room_check.size_m sets one)\n");
    } else {
      std::printf("  room centre (%.2f, %.2f, %.2f) m, size (%.2f, %.2f, %.2f) m\n", seq["room_center_m"][0].get<double>(),
                  seq["room_center_m"][1].get<double>(), seq["room_center_m"][2].get<double>(),
                  seq["room_size_m"][0].get<double>(), seq["room_size_m"][1].get<double>(),
                  seq["room_size_m"][2].get<double>());
    }
    std::printf("  %-10s %-26s %-11s %-8s %10s %10s %18s %14s\n", "camera", "centre (m)", "image", "model",
                "detections", "GT comp.", "GT->det px (med)", "rel. to box");
    for (const auto& cam : seq["cameras"]) {
      char centre[64], image[32], median[32], relative[32];
      std::snprintf(centre, sizeof(centre), "(%.2f, %.2f, %.2f)", cam["center_m"][0].get<double>(),
                    cam["center_m"][1].get<double>(), cam["center_m"][2].get<double>());
      std::snprintf(image, sizeof(image), "%dx%d", cam["image"][0].get<int>(), cam["image"][1].get<int>());
      std::snprintf(median, sizeof(median), "-");
      std::snprintf(relative, sizeof(relative), "-");
      if (!cam["gt_to_detection_px_median"].is_null()) {
        std::snprintf(median, sizeof(median), "%.1f", cam["gt_to_detection_px_median"].get<double>());
        std::snprintf(relative, sizeof(relative), "%.3f", cam["gt_to_detection_rel_median"].get<double>());
      }
      std::printf("  %-10s %-26s %-11s %-8s %10ld %10ld %18s %14s\n",
                  PrintableText(cam["name"].get<std::string>(), LineBreaks::kEscape).c_str(), centre, image,
                  cam["model"].get<std::string>().c_str(), cam["detections"].get<long>(),
                  cam["gt_persons_compared"].get<long>(), median, relative);
    }
    std::printf("  %s\n", PrintableText(shift_lines[i], LineBreaks::kEscape).c_str());
  }
}

}  // namespace

void RegisterInspectCommand(CLI::App& app) {
  auto args = std::make_shared<InspectArgs>();
  CLI::App* command = app.add_subcommand("inspect", "Show cameras, counts and GT-to-detection distances of an input");
  AddInputOptions(command, &args->input);
  AddCamerasOptions(command, &args->input);
  command->add_flag("--json", args->json, "print the report as JSON");
  command->callback([args] { RunInspect(*args); });
}

}  // namespace rpt::cli
