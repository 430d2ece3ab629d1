// SPDX-License-Identifier: MIT
#include "bench/baseline_triangulator.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace rpt::bench {
namespace {

struct Candidate {
  std::vector<Eigen::Vector3d> points;
  std::vector<double> scores;
  double pair_score = 0;
};

Eigen::Vector2d ProjectPinhole(const Camera& camera, const Eigen::Vector3d& point) {
  const Eigen::Vector3d c = camera.R * point + camera.t;
  const Eigen::Vector3d h = camera.K * (c / c.z());
  return h.head<2>();
}

}  // namespace

BaselineTriangulator::BaselineTriangulator(std::vector<Camera> cameras, JointNames joints)
    : cameras_(std::move(cameras)), joints_(std::move(joints)) {}

Poses3D BaselineTriangulator::Process(std::span<const Poses2D> views) const {
  const int num_joints = static_cast<int>(joints_.size());
  // Undistort every detection into fresh containers.
  std::vector<std::vector<std::vector<Eigen::Vector3d>>> undistorted(views.size());  // view, person, joint (u, v, score)
  for (size_t v = 0; v < views.size(); ++v) {
    for (int p = 0; p < views[v].num_persons(); ++p) {
      std::vector<Eigen::Vector3d> person;
      for (int j = 0; j < num_joints; ++j) {
        const auto kp = views[v].Person(p).col(j);
        const Eigen::Vector2d uv = kp(2) > 0.1 ? cameras_[v].UndistortPixel(kp.head<2>()) : Eigen::Vector2d::Zero();
        person.emplace_back(uv.x(), uv.y(), kp(2) > 0.1 ? kp(2) : 0.0);
      }
      undistorted[v].push_back(person);
    }
  }
  // Triangulate every pair with every joint (SVD), score by reprojection.
  std::vector<Candidate> candidates;
  for (size_t a = 0; a < views.size(); ++a) {
    for (size_t b = a + 1; b < views.size(); ++b) {
      Eigen::MatrixXd Pa(3, 4), Pb(3, 4);
      Pa << cameras_[a].R, cameras_[a].t;
      Pb << cameras_[b].R, cameras_[b].t;
      Pa = cameras_[a].K * Pa;
      Pb = cameras_[b].K * Pb;
      for (const auto& pa : undistorted[a]) {
        for (const auto& pb : undistorted[b]) {
          Candidate c;
          double sum = 0;
          int n = 0;
          for (int j = 0; j < num_joints; ++j) {
            if (pa[j].z() <= 0 || pb[j].z() <= 0) {
              c.points.emplace_back(Eigen::Vector3d::Zero());
              c.scores.push_back(0);
              continue;
            }
            Eigen::MatrixXd A(4, 4);
            A.row(0) = pa[j].x() * Pa.row(2) - Pa.row(0);
            A.row(1) = pa[j].y() * Pa.row(2) - Pa.row(1);
            A.row(2) = pb[j].x() * Pb.row(2) - Pb.row(0);
            A.row(3) = pb[j].y() * Pb.row(2) - Pb.row(1);
            Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
            const Eigen::VectorXd h = svd.matrixV().col(3);
            const Eigen::Vector3d X = h.head(3) / h(3);
            const double error = 0.5 * ((ProjectPinhole(cameras_[a], X) - pa[j].head<2>()).norm() +
                                        (ProjectPinhole(cameras_[b], X) - pb[j].head<2>()).norm());
            const double score = std::exp(-std::pow(error / 25.0, 2)) * std::sqrt(pa[j].z() * pb[j].z());
            c.points.push_back(X);
            c.scores.push_back(score);
            sum += score;
            ++n;
          }
          c.pair_score = n > 0 ? sum / n : 0;
          if (n >= 3 && c.pair_score > 0.5) candidates.push_back(c);
        }
      }
    }
  }
  // Greedy grouping by mean joint distance, then a score-weighted mean per joint.
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& x, const Candidate& y) { return x.pair_score > y.pair_score; });
  std::vector<std::vector<const Candidate*>> groups;
  for (const Candidate& c : candidates) {
    int best = -1;
    double best_distance = 0.3;
    for (size_t g = 0; g < groups.size(); ++g) {
      const Candidate& first = *groups[g].front();
      double sum = 0;
      int n = 0;
      for (int j = 0; j < num_joints; ++j) {
        if (c.scores[j] <= 0 || first.scores[j] <= 0) continue;
        sum += (c.points[j] - first.points[j]).norm();
        ++n;
      }
      if (n > 0 && sum / n < best_distance) {
        best_distance = sum / n;
        best = static_cast<int>(g);
      }
    }
    if (best < 0) {
      groups.push_back({&c});
    } else {
      groups[best].push_back(&c);
    }
  }
  Poses3D persons;
  persons.Clear(num_joints);
  for (const auto& group : groups) {
    auto person = persons.AddPerson();
    for (int j = 0; j < num_joints; ++j) {
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      double weights = 0;
      for (const Candidate* c : group) {
        sum += c->scores[j] * c->points[j];
        weights += c->scores[j];
      }
      if (weights > 0) person.col(j) << sum / weights, weights / group.size();
    }
  }
  return persons;
}

}  // namespace rpt::bench
