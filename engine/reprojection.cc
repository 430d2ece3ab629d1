// SPDX-License-Identifier: MIT
#include "engine/reprojection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/nan.h"
#include "datasets/detector_stats/association.h"

namespace rpt::engine {
namespace {

// Per 3D joint (`num_joints` of them), the index of the detection joint of the same name, or -1
// (also when the names run short or the view holds fewer joints than the names say).
std::vector<int> DetectionIndex(int num_joints, const JointNames* joints, const JointNames& detection_joints,
                                int view_joints) {
  std::vector<int> index(num_joints, -1);
  for (int j = 0; j < num_joints && joints != nullptr && j < static_cast<int>(joints->size()); ++j) {
    const int d = FindJoint(detection_joints, (*joints)[j]);
    index[j] = d < view_joints ? d : -1;
  }
  return index;
}

// Projects person `p` into `camera`; the association's view of it (present joints, box) goes to
// *projected.
ReprojectedPerson Project(const Camera& camera, const Poses3D& persons, int p, double min_score,
                          detector_stats::ProjectedPerson* projected) {
  const int num_joints = persons.num_joints;
  const auto person = persons.Person(p);
  ReprojectedPerson out;
  out.person_idx = p;
  out.track_id = persons.track_ids[p];
  out.uv_px.setZero(2, num_joints);
  out.status.assign(num_joints, JointReprojection::kMissing3D);
  out.error_px.assign(num_joints, kNaN);
  out.mean_error_px = kNaN;
  projected->gt_person = p;
  projected->uv.setZero(2, num_joints);
  projected->present.assign(num_joints, 0);
  projected->in_image.assign(num_joints, 0);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (int j = 0; j < num_joints; ++j) {
    if (!(person(3, j) > min_score) || !person.col(j).head<3>().allFinite()) continue;
    Eigen::Vector2d uv;
    if (!camera.Project(person.col(j).head<3>(), &uv) || !uv.allFinite()) {
      out.status[j] = JointReprojection::kBehindCamera;
      continue;
    }
    out.uv_px.col(j) = uv;
    out.status[j] = JointReprojection::kNotDetected;
    projected->uv.col(j) = uv;
    projected->present[j] = 1;
    lo = lo.cwiseMin(uv);
    hi = hi.cwiseMax(uv);
    if (uv.x() >= 0 && uv.x() < camera.width && uv.y() >= 0 && uv.y() < camera.height) {
      projected->in_image[j] = 1;
      ++projected->num_in_image;
    }
  }
  out.in_image = projected->num_in_image > 0;
  if (lo.x() <= hi.x()) {  // the box of the projected joints, clipped to the image (as the association expects)
    const Eigen::Vector2d size(camera.width, camera.height);
    lo = lo.cwiseMax(Eigen::Vector2d::Zero()).cwiseMin(size);
    hi = hi.cwiseMax(Eigen::Vector2d::Zero()).cwiseMin(size);
    projected->box << lo, hi;
    projected->diagonal = (hi - lo).norm();
  }
  return out;
}

// Projects and matches every person of `persons` in one view; per detection, the matched person
// goes to *of_detection.
std::vector<ReprojectedPerson> ReprojectPersons(const Camera& camera, const Poses2D* view,
                                                const JointNames& detection_joints, const PersonsWithJoints& persons,
                                                double min_score, const ReprojectionOptions& options,
                                                std::vector<int>* of_detection) {
  std::vector<ReprojectedPerson> out;
  if (persons.persons == nullptr) return out;
  const Poses3D& poses = *persons.persons;
  const std::vector<int> det_index =
      DetectionIndex(poses.num_joints, persons.joints, detection_joints, view != nullptr ? view->num_joints : 0);
  std::vector<detector_stats::ProjectedPerson> projected(poses.num_persons());
  for (int p = 0; p < poses.num_persons(); ++p) out.push_back(Project(camera, poses, p, min_score, &projected[p]));
  if (view == nullptr || view->num_persons() == 0 || out.empty()) return out;
  detector_stats::AssociationOptions association_options;
  association_options.gate_relative = options.gate_relative;
  association_options.min_common_joints = options.min_common_joints;
  const detector_stats::Association association =
      detector_stats::Associate(projected, *view, det_index, association_options);
  *of_detection = association.person_of_detection;
  for (size_t p = 0; p < out.size(); ++p) {
    ReprojectedPerson& person = out[p];
    person.detection_idx = association.detection_of_person[p];
    if (person.detection_idx < 0) continue;
    const auto detection = view->Person(person.detection_idx);
    double sum = 0;
    for (int j = 0; j < poses.num_joints; ++j) {
      const int d = det_index[j];
      if (person.status[j] != JointReprojection::kNotDetected || d < 0 || !(detection(2, d) > 0)) continue;
      person.error_px[j] = (detection.col(d).head<2>() - person.uv_px.col(j)).norm();
      person.status[j] = JointReprojection::kMeasured;
      sum += person.error_px[j];
      ++person.num_measured;
    }
    if (person.num_measured > 0) person.mean_error_px = sum / person.num_measured;
  }
  return out;
}

}  // namespace

std::vector<ViewReprojection> ReprojectFrame(const std::vector<Camera>& cameras, const std::vector<Poses2D>& views,
                                             const JointNames& detection_joints, const PersonsWithJoints& predictions,
                                             const PersonsWithJoints& gt, const ReprojectionOptions& options) {
  std::vector<ViewReprojection> out(cameras.size());
  for (size_t c = 0; c < cameras.size(); ++c) {
    const Poses2D* view = c < views.size() ? &views[c] : nullptr;
    ViewReprojection& result = out[c];
    const int num_detections = view != nullptr ? view->num_persons() : 0;
    result.prediction_of_detection.assign(num_detections, -1);
    result.gt_of_detection.assign(num_detections, -1);
    result.predictions = ReprojectPersons(cameras[c], view, detection_joints, predictions, options.prediction_min_score,
                                          options, &result.prediction_of_detection);
    result.gt = ReprojectPersons(cameras[c], view, detection_joints, gt, options.gt_min_score, options,
                                 &result.gt_of_detection);
  }
  return out;
}

ViewError MeanPredictionError(const ViewReprojection& view) {
  double sum = 0;
  long count = 0;
  for (const ReprojectedPerson& p : view.predictions) {
    for (size_t j = 0; j < p.error_px.size(); ++j) {
      if (p.status[j] == JointReprojection::kMeasured) sum += p.error_px[j], ++count;
    }
  }
  return {.mean_px = count > 0 ? sum / static_cast<double>(count) : kNaN, .joints = count};
}

}  // namespace rpt::engine
