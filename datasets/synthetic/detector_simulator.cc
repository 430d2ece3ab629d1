// SPDX-License-Identifier: MIT
#include "datasets/synthetic/detector_simulator.h"

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>

#include "core/errors.h"
#include "datasets/gt_presence.h"
#include "datasets/synthetic/camera_rig.h"
#include "datasets/synthetic/detector_error_model.h"
#include "datasets/synthetic/detector_occlusion.h"
#include "datasets/synthetic/person_motion.h"
#include "datasets/synthetic/random.h"

namespace rpt::synthetic {
namespace {

constexpr int kFalsePositiveAttempts = 10;

// Per-camera quantities shared by all persons of a view.
struct ViewContext {
  const Camera* camera;
  double max_radius;      // normalised radius where the lens model stops being monotonic
  double image_diagonal;  // px
};

struct Candidate {
  Eigen::Matrix3Xd joints;  // u, v, score per output joint
  DetectionSource source;
};

// Projects a joint for detection: false when behind the camera, beyond the lens model's monotonic
// range or not finite.
bool ProjectJoint(const ViewContext& view, const Eigen::Vector3d& point, Eigen::Vector2d* uv) {
  const Camera& camera = *view.camera;
  const Eigen::Vector3d p_cam = camera.R * point + camera.t;
  if (!(p_cam.z() > 0.0)) return false;
  if (std::hypot(p_cam.x(), p_cam.y()) / p_cam.z() >= view.max_radius) return false;
  return camera.Project(point, uv) && uv->allFinite();
}

bool InImage(const Camera& camera, const Eigen::Vector2d& uv) {
  return uv.x() >= 0.0 && uv.x() < camera.width && uv.y() >= 0.0 && uv.y() < camera.height;
}

}  // namespace

DetectorSimulator::DetectorSimulator(DetectorOptions options, JointNames output_joints, uint64_t seed)
    : options_(std::move(options)), output_joints_(std::move(output_joints)), seed_(seed) {
  const int num_joints = static_cast<int>(output_joints_.size());
  mirror_.resize(num_joints);
  from_whole_body_.resize(num_joints);
  for (int k = 0; k < num_joints; ++k) {
    const int partner = FindJoint(output_joints_, rpt::MirrorJointName(output_joints_[k]));
    mirror_[k] = partner >= 0 ? partner : k;
    from_whole_body_[k] = FindJoint(CocoWholeBodyJoints(), output_joints_[k]);
  }
  joint_factor_.assign(num_joints, 1.0);
  hidden_drop_.assign(num_joints, options_.fitted.occluded_drop);
  score_factor_.assign(num_joints, 1.0);
  for (const FittedJoint& joint : options_.fitted.joints) {
    const int k = FindJoint(output_joints_, joint.joint);
    if (k < 0) continue;
    joint_factor_[k] = joint.error_factor;
    if (joint.hidden_drop >= 0.0) hidden_drop_[k] = joint.hidden_drop;
    score_factor_[k] = joint.score_factor;
  }
  offsets_ = ResolveOffsets(options_.joint_offsets, output_joints_);
  bones_ = BodyBones(output_joints_, options_.occlusion);
  clutter_.assign(num_joints, 0.0);
  for (const JointChance& chance : options_.occlusion.clutter) {
    const int k = FindJoint(output_joints_, chance.joint);
    if (k >= 0) clutter_[k] = chance.probability;
  }
}

namespace {

// Projects one person (world points per output joint; `present` marks joints that exist) and
// corrupts the detection. Returns false when fewer than min_visible_joints are in the image.
bool DetectPerson(const DetectorOptions& options, const ViewContext& view, const Eigen::Matrix3Xd& points,
                  const std::vector<char>& present, Rng& rng, Eigen::Matrix3Xd* out) {
  const Camera& camera = *view.camera;
  const int num_joints = static_cast<int>(points.cols());
  out->setZero(3, num_joints);
  std::vector<char> visible(num_joints, 0);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  int num_visible = 0;
  for (int k = 0; k < num_joints; ++k) {
    if (!present[k]) continue;
    const Eigen::Vector3d p_cam = camera.R * points.col(k) + camera.t;
    if (!(p_cam.z() > 0.0)) continue;  // behind the camera: never visible
    if (std::hypot(p_cam.x(), p_cam.y()) / p_cam.z() >= view.max_radius) continue;  // folds back
    Eigen::Vector2d uv;
    if (!camera.Project(points.col(k), &uv) || !uv.allFinite()) continue;
    lo = lo.cwiseMin(uv);
    hi = hi.cwiseMax(uv);
    out->col(k).head<2>() = uv;
    if (uv.x() >= 0.0 && uv.x() < camera.width && uv.y() >= 0.0 && uv.y() < camera.height) {
      visible[k] = 1;
      ++num_visible;
    }
  }
  if (num_visible < options.min_visible_joints || num_visible == 0) return false;

  const double diagonal = std::min((hi - lo).norm(), view.image_diagonal);
  const double sigma = options.noise_relative * diagonal + options.noise_absolute_px;
  const double outlier_sigma = options.outlier_relative * diagonal;
  for (int k = 0; k < num_joints; ++k) {
    if (!visible[k]) {
      out->col(k).setZero();
      continue;
    }
    Eigen::Vector2d error = Eigen::Vector2d::Zero();
    const bool outlier = options.outlier_probability > 0.0 && rng.Bernoulli(options.outlier_probability);
    const double joint_sigma = outlier ? outlier_sigma : sigma;
    if (joint_sigma > 0.0) {
      const double dy = rng.Normal(), dx = rng.Normal();  // in this order (random.h)
      error = Eigen::Vector2d(dx, dy) * joint_sigma;
    }
    const bool dropped = options.joint_dropout > 0.0 && rng.Bernoulli(options.joint_dropout);
    const double jitter = options.score_jitter > 0.0 ? options.score_jitter * rng.Normal() : 0.0;
    if (dropped) {
      out->col(k).setZero();
      continue;
    }
    const double relative_error = sigma > 0.0 ? error.norm() / sigma : 0.0;
    Eigen::Vector2d uv = out->col(k).head<2>() + error;
    if (error.x() != 0.0 || error.y() != 0.0) {
      // A detector reports pixels inside the image.
      uv.x() = std::clamp(uv.x(), 0.0, static_cast<double>(camera.width));
      uv.y() = std::clamp(uv.y(), 0.0, static_cast<double>(camera.height));
    }
    if (uv.x() == 0.0 && uv.y() == 0.0) {  // clamped into the corner: what detectors write for "not found",
      out->col(k).setZero();               // and what the readers of detection files read as missing
      continue;
    }
    out->col(k).head<2>() = uv;
    (*out)(2, k) =
        std::clamp(options.score_base - options.score_error_slope * relative_error + jitter, options.score_min, 1.0);
  }
  return true;
}

// The fitted model's detection of one person: like DetectPerson, but the confidence is drawn
// first and the error given it, hidden joints are displaced or dropped, all joints share a
// per-person error factor and shift. `snap_uv` / `snap_ok` (may be empty) are the other persons'
// projections, where a joint hidden by one of them may be reported. *hidden_share receives the
// hidden fraction of the in-image joints.
bool DetectPersonFitted(const DetectorOptions& options, const ViewContext& view, const Eigen::Matrix3Xd& points,
                        const std::vector<char>& present, const std::vector<char>& hidden,
                        const std::vector<int>& occluder, const std::vector<double>& joint_factor,
                        const std::vector<double>& hidden_drop, const std::vector<double>& score_factor,
                        const std::vector<Eigen::Matrix2Xd>& snap_uv, const std::vector<std::vector<char>>& snap_ok,
                        Rng& rng, Eigen::Matrix3Xd* out, double* hidden_share) {
  const FittedErrorOptions& fitted = options.fitted;
  const Camera& camera = *view.camera;
  const int num_joints = static_cast<int>(points.cols());
  out->setZero(3, num_joints);
  std::vector<char> visible(num_joints, 0);
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  int num_visible = 0, num_projected = 0, num_hidden = 0;
  for (int k = 0; k < num_joints; ++k) {
    Eigen::Vector2d uv;
    if (!present[k] || !ProjectJoint(view, points.col(k), &uv)) continue;
    out->col(k).head<2>() = uv;
    centroid += camera.R * points.col(k) + camera.t;
    ++num_projected;
    if (InImage(camera, uv)) {
      visible[k] = 1;
      ++num_visible;
      num_hidden += hidden[k] != 0;
    }
  }
  if (num_visible < options.min_visible_joints || num_visible == 0) return false;
  *hidden_share = static_cast<double>(num_hidden) / num_visible;

  const double pixels_per_metre = PixelsPerMetre(camera, centroid / num_projected);
  const double person_factor = fitted.person_spread > 0.0 ? std::exp(fitted.person_spread * rng.Normal()) : 1.0;
  Eigen::Vector2d shift = Eigen::Vector2d::Zero();
  if (fitted.person_shift_m > 0.0) {
    const double dy = rng.Normal(), dx = rng.Normal();  // in this order (random.h)
    shift = Eigen::Vector2d(dx, dy) * (fitted.person_shift_m * pixels_per_metre);
  }
  for (int k = 0; k < num_joints; ++k) {
    if (!visible[k]) {
      out->col(k).setZero();
      continue;
    }
    Eigen::Vector2d base = out->col(k).head<2>();
    JointDraw draw;
    if (hidden[k]) {
      draw = DrawHiddenJoint(fitted, hidden_drop[k], pixels_per_metre, rng);
      const int q = occluder[k];
      if (draw.reported && fitted.occluded_snap > 0.0 && q >= 0 && q < static_cast<int>(snap_ok.size()) &&
          snap_ok[q][k] && rng.Bernoulli(fitted.occluded_snap)) {
        base = snap_uv[q].col(k);
      }
    } else if (!(options.joint_dropout > 0.0 && rng.Bernoulli(options.joint_dropout))) {
      draw = DrawVisibleJoint(fitted, pixels_per_metre, person_factor * joint_factor[k], rng);
      if (fitted.stray_probability > 0.0 && rng.Bernoulli(fitted.stray_probability)) {
        draw.error_px = StudentError(fitted.stray_error_m * pixels_per_metre, 3.0, rng);
      }
    }
    if (!draw.reported) {
      out->col(k).setZero();
      continue;
    }
    Eigen::Vector2d uv = base + shift + draw.error_px;
    uv.x() = std::clamp(uv.x(), 0.0, static_cast<double>(camera.width));
    uv.y() = std::clamp(uv.y(), 0.0, static_cast<double>(camera.height));
    if (uv.x() == 0.0 && uv.y() == 0.0) {  // the corner: not reported, as above (ReadOriginJointsAsMissing)
      out->col(k).setZero();
      continue;
    }
    out->col(k).head<2>() = uv;
    (*out)(2, k) = std::clamp(draw.score * score_factor[k], options.score_min, 1.0);
  }
  return true;
}

// The simulator's 2D label of GT person `p` (appended to `out` when a joint is in the image):
// projections with the true camera, hidden joints as occluded.
void LabelPerson(const ViewContext& view, const Eigen::Matrix3Xd& points, const std::vector<char>& present,
                 const std::vector<char>& hidden, const std::vector<int>& from_gt, int num_gt_joints, int p,
                 std::vector<PersonLabel2D>* out) {
  const Camera& camera = *view.camera;
  PersonLabel2D label;
  label.gt_person = p;
  label.visibility.assign(num_gt_joints, kLabelAbsent);
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = -lo;
  bool any = false;
  for (size_t k = 0; k < from_gt.size(); ++k) {
    Eigen::Vector2d uv;
    if (!present[k] || !ProjectJoint(view, points.col(k), &uv)) continue;
    lo = lo.cwiseMin(uv);
    hi = hi.cwiseMax(uv);
    if (InImage(camera, uv)) {
      label.visibility[from_gt[k]] = hidden[k] ? kLabelOccluded : kLabelVisible;
      any = true;
    }
  }
  if (!any) return;
  const Eigen::Vector2d size(camera.width, camera.height);
  label.box_px << lo.cwiseMax(Eigen::Vector2d::Zero()).cwiseMin(size), hi.cwiseMax(Eigen::Vector2d::Zero()).cwiseMin(size);
  out->push_back(std::move(label));
}

// A random person placed in front of the camera (built in the camera frame, so the world's up
// direction does not matter), as world points per output joint.
void RandomPersonInView(const Camera& camera, const std::vector<int>& from_whole_body, Rng& rng,
                        Eigen::Matrix3Xd* points, std::vector<char>* present) {
  const BodyShape shape = RandomBodyShape(rng);
  GaitState gait;
  gait.heading_rad = rng.Uniform(-std::numbers::pi, std::numbers::pi);
  gait.speed_mps = rng.Uniform(0.0, 1.5);
  gait.phase_rad = rng.Uniform(-std::numbers::pi, std::numbers::pi);
  Eigen::Matrix3Xd local;
  PoseJoints(shape, gait, /*whole_body=*/true, &local);
  const Eigen::Vector3d hip_center = 0.5 * (local.col(11) + local.col(12));

  // Hip centre at a random pixel (pinhole approximation) and depth.
  const double u = rng.Uniform(0.1, 0.9) * camera.width;
  const double v = rng.Uniform(0.2, 0.8) * camera.height;
  const double y_n = (v - camera.K(1, 2)) / camera.K(1, 1);
  const double x_n = (u - camera.K(0, 2) - camera.K(0, 1) * y_n) / camera.K(0, 0);
  const Eigen::Vector3d hip_cam = rng.Uniform(2.5, 9.0) * Eigen::Vector3d(x_n, y_n, 1.0);
  // Local x -> camera x, local y (horizontal) -> camera z, local z (up) -> camera -y.
  Eigen::Matrix3d local_to_cam;
  local_to_cam << 1, 0, 0, 0, 0, -1, 0, 1, 0;

  const int num_joints = static_cast<int>(from_whole_body.size());
  points->setZero(3, num_joints);
  present->assign(num_joints, 0);
  for (int k = 0; k < num_joints; ++k) {
    if (from_whole_body[k] < 0) continue;
    const Eigen::Vector3d p_cam = local_to_cam * (local.col(from_whole_body[k]) - hip_center) + hip_cam;
    points->col(k) = camera.R.transpose() * (p_cam - camera.t);
    (*present)[k] = 1;
  }
}

}  // namespace

void DetectorSimulator::Detect(std::span<const Camera> cameras, const Poses3D& gt, const JointNames& gt_joints,
                               uint64_t frame_index, std::vector<Poses2D>* views,
                               std::vector<std::vector<DetectionSource>>* sources,
                               std::vector<std::vector<PersonLabel2D>>* labels) const {
  if (gt.num_persons() > 0 && gt.num_joints != static_cast<int>(gt_joints.size())) {
    throw InputError("detector simulator: ground truth has " + std::to_string(gt.num_joints) + " joints but " +
                     std::to_string(gt_joints.size()) + " joint names");
  }
  const int num_joints = static_cast<int>(output_joints_.size());
  const int num_persons = gt.num_persons();
  const bool fitted = options_.fitted.enabled;
  std::vector<int> from_gt(num_joints);
  for (int k = 0; k < num_joints; ++k) from_gt[k] = FindJoint(gt_joints, output_joints_[k]);

  // The GT per output joint (camera independent), and where the detector's skeleton puts it.
  std::vector<Eigen::Matrix3Xd> gt_points(num_persons, Eigen::Matrix3Xd::Zero(3, num_joints));
  std::vector<std::vector<char>> present(num_persons, std::vector<char>(num_joints, 0));
  for (int p = 0; p < num_persons; ++p) {
    const auto person = gt.Person(p);
    for (int k = 0; k < num_joints; ++k) {
      const int g = from_gt[k];
      present[p][k] = g >= 0 && person(3, g) > kGtPresentScore && person.col(g).head<3>().allFinite();
      if (g >= 0) gt_points[p].col(k) = person.col(g).head<3>();
    }
  }
  std::vector<Eigen::Matrix3Xd> detector_points = gt_points;
  const BodyJoints body(output_joints_);
  for (int p = 0; p < num_persons; ++p) ApplyJointOffsets(offsets_, body, present[p], &detector_points[p]);

  views->resize(cameras.size());
  if (sources != nullptr) sources->assign(cameras.size(), {});
  if (labels != nullptr) labels->assign(cameras.size(), {});
  Eigen::Matrix3Xd points(3, num_joints);
  std::vector<char> fp_present(num_joints);
  const std::vector<char> none_hidden(num_joints, 0);
  const std::vector<int> no_occluder(num_joints, -1);
  std::vector<Candidate> candidates;
  ViewOcclusion occlusion;
  std::vector<Eigen::Matrix2Xd> snap_uv;
  std::vector<std::vector<char>> snap_ok;
  for (size_t c = 0; c < cameras.size(); ++c) {
    const Camera& camera = cameras[c];
    Rng rng(DeriveSeed(seed_, frame_index, c));
    // The detector works with the camera as miscalibrated; labels use the true one.
    const Camera seen = PerturbedCamera(camera, seed_, c, options_.calibration_px);
    const ViewContext true_view{&camera, MonotonicRadius(camera), std::hypot(camera.width, camera.height)};
    const ViewContext view{&seen, MonotonicRadius(seen), std::hypot(seen.width, seen.height)};
    ComputeOcclusion(options_.occlusion, bones_, body, clutter_, camera, gt_points, present, gt.track_ids, seed_, frame_index, c,
                     &occlusion);
    snap_uv.clear();
    snap_ok.clear();
    if (fitted && options_.fitted.occluded_snap > 0.0) {
      for (int p = 0; p < num_persons; ++p) {
        snap_uv.emplace_back(Eigen::Matrix2Xd::Zero(2, num_joints));
        snap_ok.emplace_back(num_joints, 0);
        for (int k = 0; k < num_joints; ++k) {
          Eigen::Vector2d uv;
          if (!present[p][k] || !ProjectJoint(view, detector_points[p].col(k), &uv) || !InImage(seen, uv)) continue;
          snap_uv[p].col(k) = uv;
          snap_ok[p][k] = 1;
        }
      }
    }
    candidates.clear();

    for (int p = 0; p < num_persons; ++p) {
      if (labels != nullptr) {
        LabelPerson(true_view, gt_points[p], present[p], occlusion.hidden[p], from_gt,
                    static_cast<int>(gt_joints.size()), p, &(*labels)[c]);
      }
      Candidate candidate;
      if (fitted) {
        double hidden_share = 0;
        if (!DetectPersonFitted(options_, view, detector_points[p], present[p], occlusion.hidden[p],
                                occlusion.occluder[p], joint_factor_, hidden_drop_, score_factor_, snap_uv,
                                snap_ok, rng, &candidate.joints,
                                &hidden_share)) {
          continue;
        }
        const double miss = options_.person_miss + options_.fitted.person_miss_hidden * hidden_share * hidden_share;
        if (miss > 0.0 && rng.Bernoulli(miss)) continue;
      } else {
        if (!DetectPerson(options_, view, detector_points[p], present[p], rng, &candidate.joints)) continue;
        if (options_.person_miss > 0.0 && rng.Bernoulli(options_.person_miss)) continue;
      }
      candidate.source.gt_person = p;
      if (options_.left_right_swap > 0.0 && rng.Bernoulli(options_.left_right_swap)) {
        const Eigen::Matrix3Xd original = candidate.joints;
        for (int k = 0; k < num_joints; ++k) candidate.joints.col(k) = original.col(mirror_[k]);
        candidate.source.swapped = true;
        if (fitted) {
          for (int k = 0; k < num_joints; ++k) {
            if (mirror_[k] != k) candidate.joints(2, k) *= options_.fitted.swap_score_factor;
          }
        }
      }
      if (fitted && options_.fitted.pair_swap > 0.0) {
        for (int k = 0; k < num_joints; ++k) {
          const int m = mirror_[k];
          if (m <= k || !rng.Bernoulli(options_.fitted.pair_swap)) continue;
          candidate.joints.col(k).swap(candidate.joints.col(m));
          candidate.joints(2, k) *= options_.fitted.swap_score_factor;
          candidate.joints(2, m) *= options_.fitted.swap_score_factor;
          ++candidate.source.pairs_swapped;
        }
      }
      candidates.push_back(std::move(candidate));
    }

    const int num_false_positives = rng.Poisson(options_.false_positives_per_view);
    for (int f = 0; f < num_false_positives; ++f) {
      for (int attempt = 0; attempt < kFalsePositiveAttempts; ++attempt) {
        RandomPersonInView(camera, from_whole_body_, rng, &points, &fp_present);
        Candidate candidate;
        if (fitted) {
          double hidden_share = 0;
          if (!DetectPersonFitted(options_, view, points, fp_present, none_hidden, no_occluder, joint_factor_, hidden_drop_,
                                  score_factor_, {}, {},
                                  rng, &candidate.joints, &hidden_share)) {
            continue;
          }
          int kept = 0;
          for (int k = 0; k < num_joints; ++k) {
            if (candidate.joints(2, k) <= 0.0) continue;
            if (rng.Bernoulli(options_.fitted.false_positive_joint_keep)) {
              ++kept;
            } else {
              candidate.joints.col(k).setZero();
            }
          }
          if (kept < 2) continue;
        } else if (!DetectPerson(options_, view, points, fp_present, rng, &candidate.joints)) {
          continue;
        }
        for (int k = 0; k < num_joints; ++k) {
          double& score = candidate.joints(2, k);
          if (score > 0.0) score = std::max(options_.score_min, score * options_.false_positive_score_scale);
        }
        candidates.push_back(std::move(candidate));
        break;
      }
    }

    if (options_.shuffle_persons) {
      for (int i = static_cast<int>(candidates.size()) - 1; i > 0; --i) {
        std::swap(candidates[i], candidates[rng.UniformInt(i + 1)]);
      }
    }
    Poses2D& out = (*views)[c];
    out.Clear(num_joints);
    for (const Candidate& candidate : candidates) {
      out.AddPerson() = candidate.joints;
      if (sources != nullptr) (*sources)[c].push_back(candidate.source);
    }
  }
}

}  // namespace rpt::synthetic
