// SPDX-License-Identifier: MIT
#include "core/pipeline/options.h"

#include <cmath>
#include <sstream>

namespace rpt {
namespace {

// Collects the first problem found, formatted "section.key: problem".
class Checker {
 public:
  void Range(const char* key, double value, double lo, double hi) {
    if (!error_.empty()) return;
    if (!std::isfinite(value) || value < lo || value > hi) {
      std::ostringstream s;
      s << key << ": " << value << " is outside [" << lo << ", " << hi << "]";
      error_ = s.str();
    }
  }
  void Positive(const char* key, double value) {
    if (!error_.empty()) return;
    if (!std::isfinite(value) || value <= 0) {
      std::ostringstream s;
      s << key << ": " << value << " must be > 0";
      error_ = s.str();
    }
  }
  void Finite(const char* key, const Eigen::Vector3d& v) {
    if (error_.empty() && !v.allFinite()) error_ = std::string(key) + ": must be finite";
  }
  std::string error() const { return error_; }

 private:
  std::string error_;
};

}  // namespace

std::string TriangulatorOptions::Check() const {
  Checker c;
  c.Range("undistort.min_joint_score", undistort.min_joint_score, 0, 1);
  c.Range("prefilter.max_distance_rel", prefilter.max_distance_rel, 0, 100);
  c.Range("prefilter.person_speed_m_s", prefilter.person_speed_m_s, 0, 1000);
  c.Range("prefilter.ambiguity_ratio", prefilter.ambiguity_ratio, 1, 1000);
  c.Range("prefilter.max_pairs_per_person", prefilter.max_pairs_per_person, -1, 1e9);
  c.Range("triangulate.min_core_joints", triangulate.min_core_joints, 1, 1000);
  c.Finite("room_check.center_m", room_check.center_m);
  c.Finite("room_check.size_m", room_check.size_m);
  c.Range("room_check.margin_m", room_check.margin_m, 0, 1e6);
  c.Positive("score.scale_factor", score.scale_factor);
  c.Positive("score.noise_prior_m", score.noise_prior_m);
  c.Range("score.trim_fraction", score.trim_fraction, 0, 0.9);
  c.Positive("score.reprojection_scale_rel", score.reprojection_scale_rel);
  c.Positive("score.ray_gap_scale_m", score.ray_gap_scale_m);
  c.Range("filter.min_match_score", filter.min_match_score, 0, 1);
  c.Positive("group.max_distance_m", group.max_distance_m);
  c.Range("group.min_group_size", group.min_group_size, 0, 1e6);
  c.Range("merge.max_distance_m", merge.max_distance_m, -1e6, 1e6);
  c.Range("merge.top_k", merge.top_k, -1e6, 1e6);
  c.Range("merge.min_joint_score", merge.min_joint_score, 0, 1);
  c.Range("verify.min_empty_views", verify.min_empty_views, 1, 1e6);
  c.Range("verify.min_inside_fraction", verify.min_inside_fraction, 0, 1);
  c.Range("single_view.min_joint_score", single_view.min_joint_score, 0, 1);
  c.Range("single_view.min_core_joints", single_view.min_core_joints, 2, 1e6);
  c.Range("single_view.score_factor", single_view.score_factor, 1e-6, 1);
  c.Range("single_view.duplicate_distance_m", single_view.duplicate_distance_m, 0, 1e6);
  c.Range("single_view.max_overlap_iou", single_view.max_overlap_iou, 0, 1);
  c.Range("postprocess.min_valid_joints", postprocess.min_valid_joints, 0, 1e6);
  c.Range("postprocess.min_extent_m", postprocess.min_extent_m, 0, 1e6);
  c.Range("postprocess.max_extent_m", postprocess.max_extent_m, postprocess.min_extent_m, 1e6);
  c.Range("postprocess.filled_joint_score", postprocess.filled_joint_score, 1e-9, 1);
  c.Positive("track.max_distance_m", track.max_distance_m);
  c.Range("track.max_gap_s", track.max_gap_s, 0, 1e9);
  c.Range("track.max_missing_frames", track.max_missing_frames, 0, 1e6);
  c.Positive("clip_speed.max_speed_m_s", clip_speed.max_speed_m_s);
  c.Range("bone_lengths.tolerance_rel", bone_lengths.tolerance_rel, 0.01, 10);
  c.Range("bone_lengths.min_tolerance_m", bone_lengths.min_tolerance_m, 0, 10);
  c.Range("bone_lengths.window", bone_lengths.window, 1, 10000);
  c.Range("bone_lengths.min_observations", bone_lengths.min_observations, 1, bone_lengths.window);
  c.Range("smooth.measurement_noise_m", smooth.measurement_noise_m, 1e-6, 100);
  c.Range("smooth.acceleration_m_s2", smooth.acceleration_m_s2, 1e-6, 1e6);
  c.Range("smooth.offline_sigma_s", smooth.offline_sigma_s, 1e-4, 1e3);
  c.Range("smooth.offline_degree", smooth.offline_degree, 1, 3);
  return c.error();
}

}  // namespace rpt
