// SPDX-License-Identifier: MIT
#include "datasets/synthetic/person_motion.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "datasets/synthetic/random.h"

namespace rpt::synthetic {
namespace {

using Eigen::Vector3d;
// Gait phase (rad) of the peak swing knee flexion and the half width of the flexion bump; the leg
// phase is pi/2 at maximal hip flexion.
constexpr double kKneePeakPhase = 0.6;
constexpr double kKneeBumpHalfWidth = 1.8;

// COCO body joint indices (order of CocoBodyJoints()).
enum Body {
  kNose, kEyeL, kEyeR, kEarL, kEarR, kShoulderL, kShoulderR, kElbowL, kElbowR,
  kWristL, kWristR, kHipL, kHipR, kKneeL, kKneeR, kAnkleL, kAnkleR, kNumBody
};
// COCO-WholeBody blocks (order of CocoWholeBodyJoints()).
constexpr int kFeetStart = 17;   // big toe, small toe, heel; left then right
constexpr int kFaceStart = 23;   // 68 iBUG face points
constexpr int kHandStart = 91;   // 21 points per hand; left then right
constexpr int kNumWholeBody = 133;

// Head geometry relative to the head centre (x forward, y left, z up), in units of head_scale_m.
const Vector3d kNoseOffset(0.063, 0.0, -0.020);
const Vector3d kEyeOffset(0.045, 0.018, 0.011);  // left eye; mirrored in y for the right
const Vector3d kEarOffset(-0.005, 0.043, 0.0);
// Head centre relative to the shoulder centre (units of head_scale_m).
const Vector3d kHeadCenterOffset(0.01, 0.0, 0.105);

// The 68-point iBUG face template (point 0 = the subject's right jaw end), head-centre relative,
// units of head_scale_m.
std::array<Vector3d, 68> MakeFaceTemplate() {
  std::array<Vector3d, 68> face;
  // Jaw 0-16: from the right temple around the chin to the left temple.
  for (int i = 0; i <= 16; ++i) {
    const double t = i / 16.0;
    const double c = std::cos(std::numbers::pi * t), s = std::sin(std::numbers::pi * t);
    face[i] = Vector3d(0.046 - 0.048 * std::pow(std::abs(c), 1.5), -0.042 * c, 0.004 - 0.063 * std::pow(s, 1.1));
  }
  // Brows 17-21 (right, outer to inner) and 22-26 (left, inner to outer).
  for (int k = 0; k < 5; ++k) {
    const double arch = 0.023 + 0.004 * std::sin(std::numbers::pi * k / 4.0);
    const double y_right = -0.036 + 0.007 * k;
    const double y_left = 0.008 + 0.007 * k;
    face[17 + k] = Vector3d(0.050 - 0.010 * std::pow(y_right / 0.036, 2), y_right, arch);
    face[22 + k] = Vector3d(0.050 - 0.010 * std::pow(y_left / 0.036, 2), y_left,
                            0.023 + 0.004 * std::sin(std::numbers::pi * (4 - k) / 4.0));
  }
  // Nose bridge 27-30 (30 = nose tip) and lower nose 31-35.
  const double bridge_x[4] = {0.050, 0.055, 0.059, 0.063};
  const double bridge_z[4] = {0.011, 0.000, -0.010, -0.020};
  for (int k = 0; k < 4; ++k) face[27 + k] = Vector3d(bridge_x[k], 0.0, bridge_z[k]);
  const double lower_y[5] = {-0.012, -0.006, 0.0, 0.006, 0.012};
  const double lower_z[5] = {-0.027, -0.029, -0.030, -0.029, -0.027};
  const double lower_x[5] = {0.050, 0.054, 0.056, 0.054, 0.050};
  for (int k = 0; k < 5; ++k) face[31 + k] = Vector3d(lower_x[k], lower_y[k], lower_z[k]);
  // Eyes: right 36-41 (outer corner, upper lid x2, inner corner, lower lid x2), left 42-47
  // (inner corner, upper lid x2, outer corner, lower lid x2).
  const double eye_dy[6] = {-0.008, -0.003, 0.003, 0.008, 0.003, -0.003};
  const double eye_dz[6] = {0.0, 0.003, 0.003, 0.0, -0.0025, -0.0025};
  for (int k = 0; k < 6; ++k) {
    const double dy = eye_dy[k];
    face[36 + k] = Vector3d(0.045 - 0.006 * std::abs(dy) / 0.008 * (dy < 0 ? 1.0 : 0.3), -0.018 + dy, 0.011 + eye_dz[k]);
    face[42 + k] = Vector3d(0.045 - 0.006 * std::abs(dy) / 0.008 * (dy > 0 ? 1.0 : 0.3), 0.018 + dy, 0.011 + eye_dz[k]);
  }
  // Mouth: outer lip 48-59 (right corner, upper lip, left corner, lower lip), inner 60-67.
  const double outer_y[12] = {-0.014, -0.009, -0.004, 0.0, 0.004, 0.009, 0.014, 0.009, 0.004, 0.0, -0.004, -0.009};
  const double outer_z[12] = {0.0, 0.004, 0.006, 0.005, 0.006, 0.004, 0.0, -0.005, -0.007, -0.0075, -0.007, -0.005};
  for (int k = 0; k < 12; ++k) {
    face[48 + k] = Vector3d(0.052 - 0.010 * std::pow(outer_y[k] / 0.014, 2), outer_y[k], -0.040 + outer_z[k]);
  }
  const double inner_y[8] = {-0.011, -0.004, 0.0, 0.004, 0.011, 0.004, 0.0, -0.004};
  const double inner_z[8] = {0.0, 0.0015, 0.0015, 0.0015, 0.0, -0.0015, -0.0015, -0.0015};
  for (int k = 0; k < 8; ++k) {
    face[60 + k] = Vector3d(0.051 - 0.010 * std::pow(inner_y[k] / 0.014, 2), inner_y[k], -0.040 + inner_z[k]);
  }
  return face;
}

const std::array<Vector3d, 68>& FaceTemplate() {
  static const std::array<Vector3d, 68> face = MakeFaceTemplate();
  return face;
}

// One finger of the hand template, in units of hand_m, in the hand frame (e1 along the forearm,
// e2 towards the thumb, e3 out of the palm).
struct FingerSpec {
  Vector3d base;       // first point (thumb: CMC, others: MCP)
  Vector3d direction;  // straight direction of the first segment
  double segments[3];  // segment lengths to the following three points
  double curl_scale;   // factor on the finger curl
};
const std::array<FingerSpec, 5> kFingers = {{
    {{0.12, 0.10, 0.03}, {0.60, 0.75, 0.25}, {0.20, 0.16, 0.13}, 0.6},   // thumb
    {{0.45, 0.11, 0.0}, {1.0, 0.08, 0.0}, {0.22, 0.14, 0.10}, 1.0},      // index
    {{0.47, 0.03, 0.0}, {1.0, 0.0, 0.0}, {0.24, 0.16, 0.11}, 1.0},       // middle
    {{0.45, -0.05, 0.0}, {1.0, -0.06, 0.0}, {0.22, 0.15, 0.10}, 1.1},    // ring
    {{0.40, -0.13, 0.0}, {1.0, -0.14, 0.0}, {0.17, 0.11, 0.09}, 1.2},    // pinky
}};

// Writes the 21 hand points (root = wrist) starting at column `start`.
void PoseHand(const BodyShape& shape, const Vector3d& wrist, const Vector3d& e1, const Vector3d& e2,
              const Vector3d& palm, int start, Eigen::Matrix3Xd* joints) {
  const double length = shape.hand_m;
  joints->col(start) = wrist;
  int column = start + 1;
  for (const FingerSpec& finger : kFingers) {
    Vector3d point = wrist + length * (finger.base.x() * e1 + finger.base.y() * e2 + finger.base.z() * palm);
    const Vector3d straight =
        (finger.direction.x() * e1 + finger.direction.y() * e2 + finger.direction.z() * palm).normalized();
    const Vector3d bend = (palm - palm.dot(straight) * straight).normalized();  // towards the palm
    joints->col(column++) = point;
    for (int k = 0; k < 3; ++k) {
      const double angle = (k + 1) * shape.finger_curl_rad * finger.curl_scale;
      point += length * finger.segments[k] * (std::cos(angle) * straight + std::sin(angle) * bend);
      joints->col(column++) = point;
    }
  }
}

double ClampedNormal(Rng& rng, double sigma, double bound) {
  return std::clamp(1.0 + rng.Normal(0.0, sigma), 1.0 - bound, 1.0 + bound);
}

}  // namespace

BodyShape BodyShapeFromHeight(double height_m) {
  const double h = height_m;
  BodyShape shape;
  shape.height_m = h;
  shape.hip_half_width_m = 0.060 * h;
  shape.shoulder_half_width_m = 0.103 * h;
  shape.torso_length_m = 0.298 * h;
  shape.thigh_m = 0.245 * h;
  shape.shank_m = 0.246 * h;
  shape.ankle_height_m = 0.039 * h;
  shape.upper_arm_m = 0.186 * h;
  shape.forearm_m = 0.146 * h;
  shape.hand_m = 0.108 * h;
  shape.foot_length_m = 0.152 * h;
  shape.head_scale_m = h;
  return shape;
}

BodyShape RandomBodyShape(Rng& rng) {
  BodyShape shape = BodyShapeFromHeight(rng.Uniform(1.5, 1.95));
  const double leg = ClampedNormal(rng, 0.03, 0.07);
  const double thigh_ratio = ClampedNormal(rng, 0.015, 0.03);
  const double arm = ClampedNormal(rng, 0.03, 0.07);
  const double torso = ClampedNormal(rng, 0.03, 0.07);
  const double hips = ClampedNormal(rng, 0.05, 0.12);
  const double shoulders = ClampedNormal(rng, 0.05, 0.12);
  const double head = ClampedNormal(rng, 0.03, 0.07);
  shape.thigh_m *= leg * thigh_ratio;
  shape.shank_m *= leg / thigh_ratio;
  shape.upper_arm_m *= arm;
  shape.forearm_m *= arm;
  shape.hand_m *= arm;
  shape.torso_length_m *= torso;
  shape.hip_half_width_m *= hips;
  shape.shoulder_half_width_m *= shoulders;
  shape.head_scale_m *= head;
  shape.foot_length_m *= leg;
  shape.arm_swing = rng.Uniform(0.7, 1.3);
  shape.elbow_bend_rad = rng.Uniform(0.1, 0.4);
  shape.arm_abduction_rad = rng.Uniform(0.08, 0.16);
  shape.forward_lean_rad = rng.Uniform(0.0, 0.08);
  shape.finger_curl_rad = rng.Uniform(0.1, 0.5);
  shape.toe_out_rad = rng.Uniform(0.05, 0.2);
  return shape;
}

double StrideFrequencyHz(double speed_mps) { return 0.55 + 0.35 * std::max(0.0, speed_mps); }

void AdvanceGaitPhase(double dt_s, GaitState* state) {
  state->phase_rad = std::remainder(
      state->phase_rad + 2.0 * std::numbers::pi * StrideFrequencyHz(state->speed_mps) * dt_s, 2.0 * std::numbers::pi);
}

int NumPosedJoints(bool whole_body) { return whole_body ? kNumWholeBody : kNumBody; }

void PoseJoints(const BodyShape& shape, const GaitState& state, bool whole_body, Eigen::Matrix3Xd* joints) {
  joints->resize(3, NumPosedJoints(whole_body));
  const double speed = std::max(0.0, state.speed_mps);
  const double leg_length = shape.thigh_m + shape.shank_m;
  const double stride = speed / StrideFrequencyHz(speed);
  const double hip_amplitude = std::asin(std::min(0.5, 0.25 * stride / leg_length));
  const double amplitude = hip_amplitude / 0.35;  // ~1 at a normal walk
  const double phase = state.phase_rad;

  // Frames: heading (legs), torso (rigid: hips, shoulders, head, face).
  const Vector3d up = Vector3d::UnitZ();
  const Vector3d forward(std::cos(state.heading_rad), std::sin(state.heading_rad), 0.0);
  const Vector3d left = up.cross(forward);
  const double yaw_sway = -0.03 * amplitude * std::sin(phase);
  const double lean = 0.01 + shape.forward_lean_rad * std::min(1.0, speed / 1.2);
  const Eigen::Matrix3d torso = (Eigen::AngleAxisd(state.heading_rad + yaw_sway, up) *
                                 Eigen::AngleAxisd(lean, Vector3d::UnitY()))
                                    .toRotationMatrix();
  const Vector3d torso_forward = torso.col(0);
  const Vector3d arm_forward = Vector3d(torso_forward.x(), torso_forward.y(), 0.0).normalized();
  const Vector3d arm_left = up.cross(arm_forward);

  // Pelvis at height 0 for now; shifted onto the floor at the end.
  const Vector3d pelvis(state.position_m.x(), state.position_m.y(), 0.0);
  Eigen::Matrix3Xd& out = *joints;
  std::array<Vector3d, 6> feet;  // big toe, small toe, heel; left then right

  for (int side_index = 0; side_index < 2; ++side_index) {
    const double side = side_index == 0 ? 1.0 : -1.0;  // +1 left
    const double leg_phase = phase + side_index * std::numbers::pi;

    // Leg: hip flexion, knee flexion in early swing, foot pitch.
    const Vector3d hip = pelvis + torso * Vector3d(0.0, side * shape.hip_half_width_m, 0.0);
    const double hip_flexion = hip_amplitude * std::sin(leg_phase) + 0.03 * amplitude;
    // Swing knee flexion: a raised-cosine bump from push-off to just before heel strike, peaking
    // (~55 deg at a normal walk) while the thigh swings forward.
    const double from_peak = std::remainder(leg_phase - kKneePeakPhase, 2.0 * std::numbers::pi) / kKneeBumpHalfWidth;
    const double bump = std::abs(from_peak) < 1.0 ? std::pow(std::cos(0.5 * std::numbers::pi * from_peak), 2) : 0.0;
    const double knee_flexion = 0.08 + std::min(1.0, 2.6 * hip_amplitude) * bump;
    const Vector3d thigh_direction =
        (std::sin(hip_flexion) * forward - std::cos(hip_flexion) * up - side * 0.04 * left).normalized();
    const double shank_angle = hip_flexion - knee_flexion;
    const Vector3d shank_direction =
        (std::sin(shank_angle) * forward - std::cos(shank_angle) * up - side * 0.02 * left).normalized();
    const Vector3d knee = hip + shape.thigh_m * thigh_direction;
    const Vector3d ankle = knee + shape.shank_m * shank_direction;
    out.col(kHipL + side_index) = hip;
    out.col(kKneeL + side_index) = knee;
    out.col(kAnkleL + side_index) = ankle;

    const double pitch = 0.22 * amplitude * std::sin(leg_phase);
    const double toe_yaw = side * shape.toe_out_rad;
    const Vector3d foot_flat = std::cos(toe_yaw) * forward + std::sin(toe_yaw) * left;
    const Vector3d foot_forward = std::cos(pitch) * foot_flat + std::sin(pitch) * up;
    const Vector3d foot_up = -std::sin(pitch) * foot_flat + std::cos(pitch) * up;
    const Vector3d foot_out = side * up.cross(foot_flat);  // lateral, away from the body
    const double f = shape.foot_length_m / 0.152;          // template units: fraction of height
    const double a = shape.ankle_height_m;
    feet[3 * side_index + 0] = ankle + f * (0.115 * foot_forward - 0.010 * foot_out) - a * foot_up;
    feet[3 * side_index + 1] = ankle + f * (0.090 * foot_forward + 0.022 * foot_out) - a * foot_up;
    feet[3 * side_index + 2] = ankle + f * (-0.035 * foot_forward) - 0.9 * a * foot_up;

    // Arm: swings opposite to the leg of the same side, elbow bends more when forward.
    const Vector3d shoulder = pelvis + torso * Vector3d(0.0, side * shape.shoulder_half_width_m, shape.torso_length_m);
    const double arm_angle = -0.75 * shape.arm_swing * hip_amplitude * std::sin(leg_phase) + 0.03;
    const double elbow = shape.elbow_bend_rad + 0.5 * std::max(0.0, arm_angle) + 0.1 * amplitude;
    const double abduction = shape.arm_abduction_rad;
    const Vector3d upper_direction = std::sin(arm_angle) * std::cos(abduction) * arm_forward +
                                     side * std::sin(abduction) * arm_left -
                                     std::cos(arm_angle) * std::cos(abduction) * up;
    const double forearm_abduction = 0.5 * abduction;
    const Vector3d forearm_direction = std::sin(arm_angle + elbow) * std::cos(forearm_abduction) * arm_forward +
                                       side * std::sin(forearm_abduction) * arm_left -
                                       std::cos(arm_angle + elbow) * std::cos(forearm_abduction) * up;
    const Vector3d elbow_point = shoulder + shape.upper_arm_m * upper_direction.normalized();
    const Vector3d wrist = elbow_point + shape.forearm_m * forearm_direction.normalized();
    out.col(kShoulderL + side_index) = shoulder;
    out.col(kElbowL + side_index) = elbow_point;
    out.col(kWristL + side_index) = wrist;

    if (whole_body) {
      const Vector3d e1 = forearm_direction.normalized();
      const Vector3d e2 = e1.cross(arm_left).normalized();  // thumb side (forward for a hanging arm)
      const Vector3d palm = side * e1.cross(e2);            // palm faces the body
      PoseHand(shape, wrist, e1, e2, palm, kHandStart + 21 * side_index, joints);
    }
  }

  // Head and face: rigid with the torso.
  const double hs = shape.head_scale_m;
  const Vector3d head_center = pelvis + torso * (Vector3d(0.0, 0.0, shape.torso_length_m) + hs * kHeadCenterOffset);
  auto head_point = [&](const Vector3d& offset) -> Vector3d { return head_center + torso * (hs * offset); };
  const Vector3d mirror(1.0, -1.0, 1.0);
  out.col(kNose) = head_point(kNoseOffset);
  out.col(kEyeL) = head_point(kEyeOffset);
  out.col(kEyeR) = head_point(kEyeOffset.cwiseProduct(mirror));
  out.col(kEarL) = head_point(kEarOffset);
  out.col(kEarR) = head_point(kEarOffset.cwiseProduct(mirror));
  if (whole_body) {
    for (int i = 0; i < 6; ++i) out.col(kFeetStart + i) = feet[i];
    const std::array<Vector3d, 68>& face = FaceTemplate();
    for (int i = 0; i < 68; ++i) out.col(kFaceStart + i) = head_point(face[i]);
  }

  // Stand on the floor: the lowest foot point touches z = 0.
  double lowest = feet[0].z();
  for (const Vector3d& p : feet) lowest = std::min(lowest, p.z());
  out.row(2).array() -= lowest;
}

}  // namespace rpt::synthetic
