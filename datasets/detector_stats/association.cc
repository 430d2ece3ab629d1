// SPDX-License-Identifier: MIT
#include "datasets/detector_stats/association.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "datasets/gt_presence.h"

namespace rpt::detector_stats {
ProjectedPerson ProjectPerson(const Camera& camera, const Poses3D& gt, int p, const std::vector<int>& gt_index) {
  const int num_joints = static_cast<int>(gt_index.size());
  ProjectedPerson out;
  out.gt_person = p;
  out.uv.setZero(2, num_joints);
  out.present.assign(num_joints, 0);
  out.in_image.assign(num_joints, 0);
  const auto person = gt.Person(p);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  for (int k = 0; k < num_joints; ++k) {
    const int g = gt_index[k];
    if (g < 0 || !(person(3, g) > kGtPresentScore) || !person.col(g).head<3>().allFinite()) continue;
    Eigen::Vector2d uv;
    if (!camera.Project(person.col(g).head<3>(), &uv) || !uv.allFinite()) {
      out.truncated = true;  // behind the camera
      continue;
    }
    out.uv.col(k) = uv;
    out.present[k] = 1;
    lo = lo.cwiseMin(uv);
    hi = hi.cwiseMax(uv);
    if (uv.x() >= 0 && uv.x() < camera.width && uv.y() >= 0 && uv.y() < camera.height) {
      out.in_image[k] = 1;
      ++out.num_in_image;
    } else {
      out.truncated = true;
    }
  }
  if (lo.x() <= hi.x()) {
    const Eigen::Vector2d size(camera.width, camera.height);
    lo = lo.cwiseMax(Eigen::Vector2d::Zero()).cwiseMin(size);
    hi = hi.cwiseMax(Eigen::Vector2d::Zero()).cwiseMin(size);
    out.box << lo, hi;
    out.diagonal = (hi - lo).norm();
  }
  return out;
}

double MeanDistance(const ProjectedPerson& person, const Poses2D& view, int d, const std::vector<int>& det_index,
                    int min_common_joints) {
  const auto det = view.Person(d);
  double sum = 0;
  int n = 0;
  for (size_t k = 0; k < det_index.size(); ++k) {
    const int j = det_index[k];
    if (j < 0 || !person.present[k] || !(det(2, j) > 0)) continue;
    sum += (det.col(j).head<2>() - person.uv.col(k)).norm();
    ++n;
  }
  return n >= std::max(1, min_common_joints) ? sum / n : -1;
}

Association Associate(const std::vector<ProjectedPerson>& persons, const Poses2D& view,
                      const std::vector<int>& det_index, const AssociationOptions& options) {
  Association out;
  out.detection_of_person.assign(persons.size(), -1);
  out.person_of_detection.assign(view.num_persons(), -1);
  out.distance_px.assign(persons.size(), -1);
  std::vector<std::tuple<double, int, int>> pairs;  // distance, person, detection
  for (size_t p = 0; p < persons.size(); ++p) {
    const double gate = options.gate_relative * std::max(persons[p].diagonal, 1.0);
    for (int d = 0; d < view.num_persons(); ++d) {
      const double distance = MeanDistance(persons[p], view, d, det_index, options.min_common_joints);
      if (distance >= 0 && distance <= gate) pairs.emplace_back(distance, static_cast<int>(p), d);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  for (const auto& [distance, p, d] : pairs) {
    if (out.detection_of_person[p] >= 0 || out.person_of_detection[d] >= 0) continue;
    out.detection_of_person[p] = d;
    out.person_of_detection[d] = p;
    out.distance_px[p] = distance;
  }
  return out;
}

}  // namespace rpt::detector_stats
