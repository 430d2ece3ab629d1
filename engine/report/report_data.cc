// SPDX-License-Identifier: MIT
#include "engine/report/report_data.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "engine/report/report_frame_outcomes.h"
#include "engine/reprojection.h"
#include "engine/track_palette.h"
#include "core/joints.h"
#include "core/option_codec.h"
#include "report_assets.h"

namespace rpt::engine {
namespace {

using OrderedJson = nlohmann::ordered_json;

// Rounded numbers keep the report small: metres to the millimetre, pixels to 0.1 px, errors to 0.1.
// A value that does not survive the rounding (1e308 / 1e-3 overflows) is null, like NaN.
OrderedJson Round(double value, double step) {
  const double rounded = std::round(value / step) * step;
  if (!std::isfinite(rounded)) return nullptr;
  return rounded;
}

// The 3D viewer draws cameras up to this far from the origin (it works in 32-bit floats); a camera
// farther away (accepted with a warning, e.g. T = 1e308) is listed without a position.
constexpr double kMaxDrawnCameraDistanceM = 1e6;
OrderedJson Metres(double value) { return Round(value, 1e-3); }
OrderedJson Tenths(double value) { return Round(value, 0.1); }

OrderedJson Edges(const JointNames& joints) {
  OrderedJson edges = OrderedJson::array();
  for (const LimbSpec& limb : LimbsFor(joints)) {
    const int a = FindJoint(joints, limb.a);
    const int b = FindJoint(joints, limb.b);
    if (a >= 0 && b >= 0) edges.push_back({a, b});
  }
  return edges;
}

// Joints of one 3D person: [x, y, z] in metres, null where the score is <= min_score.
OrderedJson Joints3D(const Poses3D& poses, int p, double min_score) {
  OrderedJson joints = OrderedJson::array();
  const auto person = poses.Person(p);
  for (int j = 0; j < poses.num_joints; ++j) {
    if (person(3, j) > min_score && person.col(j).head<3>().allFinite()) {
      joints.push_back({Metres(person(0, j)), Metres(person(1, j)), Metres(person(2, j))});
    } else {
      joints.push_back(nullptr);
    }
  }
  return joints;
}

OrderedJson Reprojected(const ReprojectedPerson& person) {
  OrderedJson uv = OrderedJson::array();
  OrderedJson error = OrderedJson::array();
  for (size_t j = 0; j < person.status.size(); ++j) {
    const bool has_pixel =
        person.status[j] == JointReprojection::kMeasured || person.status[j] == JointReprojection::kNotDetected;
    uv.push_back(has_pixel ? OrderedJson{Tenths(person.uv_px(0, j)), Tenths(person.uv_px(1, j))}
                           : OrderedJson(nullptr));
    error.push_back(Tenths(person.error_px[j]));
  }
  return {{"uv", uv}, {"error_px", error}, {"mean_error_px", Tenths(person.mean_error_px)},
          {"detection", person.detection_idx}, {"track_id", person.track_id}};
}

OrderedJson CameraJson(const Camera& camera, double depth_m) {
  const Eigen::Vector3d center = camera.Center();
  if (!center.allFinite() || center.norm() > kMaxDrawnCameraDistanceM) {
    return {{"name", camera.name}, {"width", camera.width}, {"height", camera.height}, {"center", nullptr},
            {"corners", nullptr}};
  }
  OrderedJson corners = OrderedJson::array();
  const double w = camera.width, h = camera.height;
  for (const Eigen::Vector2d& uv : {Eigen::Vector2d(0, 0), Eigen::Vector2d(w, 0), Eigen::Vector2d(w, h),
                                   Eigen::Vector2d(0, h)}) {
    const Eigen::Vector2d xy = camera.PixelToNormalized(uv);
    const Eigen::Vector3d in_world = camera.R.transpose() * (Eigen::Vector3d(xy.x(), xy.y(), 1.0) * depth_m - camera.t);
    corners.push_back({Metres(in_world.x()), Metres(in_world.y()), Metres(in_world.z())});
  }
  return {{"name", camera.name},
          {"width", camera.width},
          {"height", camera.height},
          {"center", {Metres(center.x()), Metres(center.y()), Metres(center.z())}},
          {"corners", corners}};
}

// The world's up direction: the mean of the cameras' up vectors (-y of each camera), since
// cameras are mounted upright.
OrderedJson UpDirection(const std::vector<Camera>& cameras) {
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
  for (const Camera& camera : cameras) up -= camera.R.row(1).transpose();
  if (up.norm() < 1e-9) up = Eigen::Vector3d::UnitZ();
  up.normalize();
  return {Round(up.x(), 0.01), Round(up.y(), 0.01), Round(up.z(), 0.01)};
}

OrderedJson Steps(const OrderedJson& summary) {
  OrderedJson steps = OrderedJson::array();
  const auto times = summary.find("step_time_us_median");
  const auto counts = summary.find("step_count_per_frame");
  if (times == summary.end() || !times->is_object()) return steps;
  for (const auto& [name, time] : times->items()) {
    OrderedJson count = nullptr;
    if (counts != summary.end() && counts->contains(name)) count = (*counts)[name];
    steps.push_back({{"step", name}, {"time_us_median", time}, {"count_per_frame", count}});
  }
  return steps;
}

// Frames (sequence, frame) whose scene the report carries: all, or `max_frames` evenly spaced.
std::vector<std::pair<int, int>> SceneFrames(const std::vector<Sequence>& sequences, int max_frames) {
  std::vector<std::pair<int, int>> all;
  for (size_t s = 0; s < sequences.size(); ++s) {
    for (size_t f = 0; f < sequences[s].frames.size(); ++f) all.emplace_back(static_cast<int>(s), static_cast<int>(f));
  }
  if (static_cast<int>(all.size()) <= max_frames) return all;
  std::vector<std::pair<int, int>> picked;
  for (int k = 0; k < max_frames; ++k) {
    picked.push_back(all[static_cast<size_t>(static_cast<double>(k) * all.size() / max_frames)]);
  }
  return picked;
}

OrderedJson SceneJson(const Sequence& sequence, int s, int f, const Poses3D& predictions,
                      const JointNames& prediction_joints, const FrameOutcome& outcome, double min_gt_score) {
  const SequenceFrame& frame = sequence.frames[f];
  OrderedJson gt = OrderedJson::array();
  for (int g = 0; g < frame.gt.num_persons(); ++g) {
    gt.push_back({{"joints", Joints3D(frame.gt, g, min_gt_score)}, {"state", outcome.gt_state[g]}});
  }
  OrderedJson persons = OrderedJson::array();
  for (int p = 0; p < predictions.num_persons(); ++p) {
    persons.push_back({{"joints", Joints3D(predictions, p, 0.0)},
                       {"track_id", predictions.track_ids[p]},
                       {"invalid", static_cast<bool>(outcome.pred_invalid[p])},
                       {"error_mm", Tenths(outcome.pred_error_mm[p])}});
  }
  ReprojectionOptions reprojection;
  reprojection.gt_min_score = min_gt_score;
  const std::vector<ViewReprojection> views =
      ReprojectFrame(sequence.cameras, frame.views, sequence.detection_joints, {&predictions, &prediction_joints},
                     {&frame.gt, &sequence.gt_joints}, reprojection);
  OrderedJson views_json = OrderedJson::array();
  for (size_t c = 0; c < views.size(); ++c) {
    OrderedJson detections = OrderedJson::array();
    if (c < frame.views.size()) {
      const Poses2D& view = frame.views[c];
      for (int d = 0; d < view.num_persons(); ++d) {
        OrderedJson joints = OrderedJson::array();
        const auto person = view.Person(d);
        for (int j = 0; j < view.num_joints; ++j) {
          joints.push_back(person(2, j) > 0
                               ? OrderedJson{Tenths(person(0, j)), Tenths(person(1, j)), Round(person(2, j), 0.01)}
                               : OrderedJson(nullptr));
        }
        detections.push_back(joints);
      }
    }
    OrderedJson projected = OrderedJson::array();
    for (const ReprojectedPerson& person : views[c].predictions) projected.push_back(Reprojected(person));
    OrderedJson projected_gt = OrderedJson::array();
    for (const ReprojectedPerson& person : views[c].gt) projected_gt.push_back(Reprojected(person)["uv"]);
    // The view's mean over its measured joints, as rpt render's legend has it.
    const ViewError view_error = MeanPredictionError(views[c]);
    views_json.push_back({{"detections", detections},
                          {"predictions", projected},
                          {"gt", projected_gt},
                          {"mean_error_px", Tenths(view_error.mean_px)},
                          {"error_joints", view_error.joints}});
  }
  return {{"sequence", s}, {"frame", f},       {"id", frame.id}, {"gt", gt},
          {"predictions", persons}, {"views", views_json}};
}

}  // namespace

OrderedJson PaperResultsFor(const std::string& dataset) {
  const OrderedJson paper = OrderedJson::parse(assets::kPaperJson);
  const OrderedJson& datasets = paper["datasets"];
  return datasets.contains(dataset) ? datasets[dataset] : OrderedJson(nullptr);
}

OrderedJson BuildReportData(const RecordedRun& run, const std::vector<Sequence>* sequences,
                            const std::string& why_no_input, const metrics::EvalOptions& eval_options,
                            const ReportDataOptions& options, std::vector<std::string>* warnings) {
  OrderedJson data;
  const std::string dataset = RecordedDataset(run);
  const bool triangulation = RecordedWords(run).size() > 1 && RecordedWords(run)[1] == "triangulate";
  data["title"] = (!dataset.empty() ? dataset : triangulation ? std::string("triangulation") : std::string("generic labels")) +
                  " - " + run.dir.filename().string();
  data["dataset"] = dataset;
  // Without ground truth (rpt triangulate) nothing is matched: predictions are persons, not invalid.
  const auto evaluated_key = run.summary.find("evaluated");
  const bool evaluated = evaluated_key == run.summary.end() || !evaluated_key->is_boolean() || evaluated_key->get<bool>();
  data["evaluated"] = evaluated;
  data["summary"] = run.summary;
  data["paper"] = PaperResultsFor(dataset);
  data["per_joint"] = run.per_joint;
  data["steps"] = Steps(run.summary);
  data["config"] = run.config;
  data["run"] = run.run_info;
  OrderedJson palette = OrderedJson::array();  // the tracks' colours, as rpt render draws them
  for (const Rgb& c : kTrackPalette) {
    char hex[8];
    std::snprintf(hex, sizeof(hex), "#%02x%02x%02x", c.r, c.g, c.b);
    palette.push_back(hex);
  }
  data["track_palette"] = palette;
  data["max_scene_frames"] = options.max_scene_frames;
  std::vector<std::vector<Poses3D>> predictions;
  std::string why = why_no_input;
  if (sequences != nullptr && !SplitPredictions(run.predictions, *sequences, &predictions, &why)) sequences = nullptr;
  if (sequences == nullptr) {
    warnings->push_back("the run's input could not be re-loaded (" + why +
                        "): the report shows the recorded tables only, without frames, cameras or overlays");
    data["warnings"] = *warnings;
    data["input_loaded"] = false;
    return data;
  }
  const JointNames& prediction_joints = run.predictions.joints;
  RunOutcomes outcomes = EvaluateFrameOutcomes(*sequences, predictions, prediction_joints, eval_options);
  if (!evaluated) {
    for (auto& frames : outcomes.frames) {
      for (FrameOutcome& o : frames) {
        o.pred_invalid.assign(o.pred_invalid.size(), false);
        o.num_invalid = 0;
      }
    }
  }
  const auto recorded_gt = run.summary.find("gt_persons");
  if (recorded_gt != run.summary.end() && recorded_gt->is_number() &&
      recorded_gt->get<long>() != outcomes.metrics.num_gt_persons) {
    warnings->push_back("summary.json counts " + std::to_string(recorded_gt->get<long>()) +
                        " GT persons, the re-loaded input " + std::to_string(outcomes.metrics.num_gt_persons) +
                        ": the input changed since the run");
  }
  data["input_loaded"] = true;
  data["prediction_joints"] = prediction_joints;
  data["prediction_edges"] = Edges(prediction_joints);
  data["recall_curve"] = {{"threshold_mm", outcomes.recall_threshold_mm}, {"recall", outcomes.recall}};
  OrderedJson sequences_json = OrderedJson::array();
  for (size_t s = 0; s < sequences->size(); ++s) {
    const Sequence& sequence = (*sequences)[s];
    OrderedJson cameras = OrderedJson::array();
    for (const Camera& camera : sequence.cameras) cameras.push_back(CameraJson(camera, 0.4));
    OrderedJson ids = OrderedJson::array(), mpjpe = OrderedJson::array(), num_gt = OrderedJson::array(),
                matched = OrderedJson::array(), invalid = OrderedJson::array(), num_pred = OrderedJson::array();
    for (size_t f = 0; f < sequence.frames.size(); ++f) {
      const FrameOutcome& o = outcomes.frames[s][f];
      ids.push_back(sequence.frames[f].id);
      mpjpe.push_back(Tenths(o.mpjpe_mm));
      num_gt.push_back(o.num_gt);
      matched.push_back(o.num_matched);
      invalid.push_back(o.num_invalid);
      num_pred.push_back(predictions[s][f].num_persons());
    }
    sequences_json.push_back({{"name", sequence.name},
                              {"gt_joints", sequence.gt_joints},
                              {"gt_edges", Edges(sequence.gt_joints)},
                              {"detection_joints", sequence.detection_joints},
                              {"detection_edges", Edges(sequence.detection_joints)},
                              {"up", UpDirection(sequence.cameras)},
                              {"cameras", cameras},
                              {"frame_ids", ids},
                              {"mpjpe_mm", mpjpe},
                              {"num_gt", num_gt},
                              {"num_predictions", num_pred},
                              {"num_matched", matched},
                              {"num_invalid", invalid}});
  }
  data["sequences"] = sequences_json;
  auto scene_json = [&](int s, int f) {
    return SceneJson((*sequences)[s], s, f, predictions[s][f], prediction_joints, outcomes.frames[s][f],
                     eval_options.min_gt_score);
  };
  // The size of a scene, estimated from (at most) the first 10 of the even spacing, bounds how many
  // frames carry one.
  std::vector<std::pair<int, int>> picked = SceneFrames(*sequences, options.max_scene_frames);
  double sample_bytes = 0;
  const size_t sample = std::min<size_t>(picked.size(), 10);
  for (size_t k = 0; k < sample; ++k) sample_bytes += static_cast<double>(scene_json(picked[k].first, picked[k].second).dump().size());
  const double budget_bytes = options.max_scene_mb * 1e6;
  if (sample > 0 && sample_bytes / sample * picked.size() > budget_bytes) {
    const int fitting = std::max(1, static_cast<int>(budget_bytes / (sample_bytes / sample)));
    warnings->push_back(std::to_string(fitting) + " frames carry a 3D scene, not " + std::to_string(picked.size()) +
                        ": a scene of this run takes about " + std::to_string(static_cast<long>(sample_bytes / sample / 1e3)) +
                        " kB and the scenes are kept under " + FormatOption(options.max_scene_mb) +
                        " MB (--max-scene-mb)");
    picked = SceneFrames(*sequences, fitting);
  }
  OrderedJson scenes = OrderedJson::array();
  for (const auto& [s, f] : picked) scenes.push_back(scene_json(s, f));
  data["scenes"] = scenes;
  data["warnings"] = *warnings;
  return data;
}

}  // namespace rpt::engine
