// SPDX-License-Identifier: MIT
// `rpt inspect`: what a dataset input contains, and whether its conventions agree: per camera, the
// distance between the projected ground truth and the nearest 2D detection. A wrong axis,
// unit, distortion or camera order shows at once as hundreds of pixels.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <vector>

#include "cli/commands.h"
#include "cli/load_input.h"
#include "metrics/timing.h"

namespace rpt::cli {
namespace {

struct InspectArgs {
  InputArgs input;
  bool json = false;
};

// Mean pixel distance between GT person `g` projected into `camera` and detection `d`, over the
// joints both have (by name); -1 when fewer than 3 joints are comparable.
double ProjectedDistance(const Camera& camera, const Poses3D& gt, int g, const Poses2D& view, int d,
                         const std::vector<int>& det_of_gt) {
  double sum = 0;
  int n = 0;
  const auto person = gt.Person(g);
  const auto det = view.Person(d);
  for (int j = 0; j < gt.num_joints; ++j) {
    const int k = det_of_gt[j];
    if (k < 0 || person(3, j) <= 0.1 || det(2, k) <= 0) continue;
    Eigen::Vector2d uv;
    if (!camera.Project(person.col(j).head<3>(), &uv)) continue;
    sum += (uv - det.col(k).head<2>()).norm();
    ++n;
  }
  return n >= 3 ? sum / n : -1;
}

void RunInspect(const InspectArgs& args) {
  InputWarnings warnings;
  const std::vector<Sequence> sequences = LoadInput(args.input, /*require_detections=*/false, &warnings);
  PrintInputWarnings(warnings);
  nlohmann::ordered_json report = nlohmann::ordered_json::array();
  for (const Sequence& s : sequences) {
    long persons = 0, frames_with_views = 0;
    for (const SequenceFrame& f : s.frames) {
      persons += f.gt.num_persons();
      frames_with_views += f.views.empty() ? 0 : 1;
    }
    std::vector<int> det_of_gt(s.gt_joints.size(), -1);
    for (size_t j = 0; j < s.gt_joints.size(); ++j) det_of_gt[j] = FindJoint(s.detection_joints, s.gt_joints[j]);
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
      std::vector<double> distances;
      long detections = 0;
      for (const SequenceFrame& f : s.frames) {
        if (f.views.empty()) continue;
        const Poses2D& view = f.views[c];
        detections += view.num_persons();
        for (int g = 0; g < f.gt.num_persons(); ++g) {
          double best = -1;
          for (int d = 0; d < view.num_persons(); ++d) {
            const double e = ProjectedDistance(camera, f.gt, g, view, d, det_of_gt);
            if (e >= 0 && (best < 0 || e < best)) best = e;
          }
          if (best >= 0) distances.push_back(best);
        }
      }
      const Eigen::Vector3d center = camera.Center();
      nlohmann::ordered_json cam;
      cam["name"] = camera.name;
      cam["center_m"] = {center.x(), center.y(), center.z()};
      cam["image"] = {camera.width, camera.height};
      cam["model"] = DistortionModelName(camera.model);
      cam["focal_px"] = {camera.K(0, 0), camera.K(1, 1)};
      cam["detections"] = detections;
      cam["gt_persons_compared"] = distances.size();
      cam["gt_to_detection_px_median"] = distances.empty() ? nlohmann::ordered_json(nullptr)
                                                           : nlohmann::ordered_json(metrics::Median(distances));
      seq["cameras"].push_back(cam);
    }
    report.push_back(seq);
  }
  if (args.json) {
    std::cout << report.dump(2) << "\n";
    return;
  }
  for (const auto& seq : report) {
    std::printf("sequence %s: %d frames (%d with detections), %ld GT person-frames, %d GT joints, %d detection joints\n",
                seq["sequence"].get<std::string>().c_str(), seq["frames"].get<int>(),
                seq["frames_with_detections"].get<int>(), seq["gt_persons"].get<long>(), seq["gt_joints"].get<int>(),
                seq["detection_joints"].get<int>());
    std::printf("  room centre (%.2f, %.2f, %.2f) m, size (%.2f, %.2f, %.2f) m\n", seq["room_center_m"][0].get<double>(),
                seq["room_center_m"][1].get<double>(), seq["room_center_m"][2].get<double>(),
                seq["room_size_m"][0].get<double>(), seq["room_size_m"][1].get<double>(),
                seq["room_size_m"][2].get<double>());
    std::printf("  %-10s %-26s %-11s %-8s %10s %10s %18s\n", "camera", "centre (m)", "image", "model", "detections",
                "GT comp.", "GT->det px (med)");
    for (const auto& cam : seq["cameras"]) {
      char centre[64], image[32], median[32];
      std::snprintf(centre, sizeof(centre), "(%.2f, %.2f, %.2f)", cam["center_m"][0].get<double>(),
                    cam["center_m"][1].get<double>(), cam["center_m"][2].get<double>());
      std::snprintf(image, sizeof(image), "%dx%d", cam["image"][0].get<int>(), cam["image"][1].get<int>());
      if (cam["gt_to_detection_px_median"].is_null()) {
        std::snprintf(median, sizeof(median), "-");
      } else {
        std::snprintf(median, sizeof(median), "%.1f", cam["gt_to_detection_px_median"].get<double>());
      }
      std::printf("  %-10s %-26s %-11s %-8s %10ld %10ld %18s\n", cam["name"].get<std::string>().c_str(), centre, image,
                  cam["model"].get<std::string>().c_str(), cam["detections"].get<long>(),
                  cam["gt_persons_compared"].get<long>(), median);
    }
  }
}

}  // namespace

void RegisterInspectCommand(CLI::App& app) {
  auto args = std::make_shared<InspectArgs>();
  CLI::App* command = app.add_subcommand("inspect", "Show cameras, counts and GT-to-detection distances of an input");
  AddInputOptions(command, &args->input);
  command->add_flag("--json", args->json, "print the report as JSON");
  command->callback([args] { RunInspect(*args); });
}

}  // namespace rpt::cli
