// SPDX-License-Identifier: MIT
// Procedural human body: fixed per-person proportions and a walking gait, posed as the 17 COCO
// body joints or the 133 COCO-WholeBody joints (order of CocoBodyJoints() / CocoWholeBodyJoints()).
//
// World frame: metres, z up, floor z = 0. The torso, head and face form one rigid body, every
// limb segment has a fixed length, hands are rigid on the forearm and feet rigid on the shank's
// end, so all bone lengths are constant over time. The lowest foot point always touches the floor.
#pragma once

#include <Eigen/Core>

namespace rpt::synthetic {

class Rng;

// Proportions and movement style of one person; constant over time.
struct BodyShape {
  double height_m = 1.75;              // m, nominal standing height (top of head)
  double hip_half_width_m = 0.105;     // m, hip-centre to each hip joint
  double shoulder_half_width_m = 0.18;  // m, shoulder-centre to each shoulder joint
  double torso_length_m = 0.52;        // m, hip-centre to shoulder-centre (upright)
  double thigh_m = 0.43;               // m, hip to knee
  double shank_m = 0.43;               // m, knee to ankle
  double ankle_height_m = 0.068;       // m, ankle above the sole
  double upper_arm_m = 0.325;          // m, shoulder to elbow
  double forearm_m = 0.255;            // m, elbow to wrist
  double hand_m = 0.19;                // m, wrist to middle fingertip (straight hand)
  double foot_length_m = 0.266;        // m, heel to big toe
  double head_scale_m = 1.75;          // m, scale of the head and face template (~height)
  double arm_swing = 1.0;              // factor on the arm swing amplitude
  double elbow_bend_rad = 0.25;        // rad, elbow flexion with the arm hanging
  double arm_abduction_rad = 0.12;     // rad, upper arm away from the body
  double forward_lean_rad = 0.04;      // rad, torso lean while walking (scaled by speed)
  double finger_curl_rad = 0.3;        // rad, flexion per finger joint
  double toe_out_rad = 0.12;           // rad, feet turned outwards
};

// Nominal proportions for a standing height (anthropometric ratios, no randomness).
BodyShape BodyShapeFromHeight(double height_m);
// Random person: height uniform in [1.5, 1.95] m, segment factors within a few percent
// (left/right symmetric), random movement style.
BodyShape RandomBodyShape(Rng& rng);

// Instantaneous locomotion state.
struct GaitState {
  Eigen::Vector2d position_m = Eigen::Vector2d::Zero();  // m, floor point below the hip centre (world x, y)
  double heading_rad = 0.0;  // rad, facing direction, counter-clockwise from world +x
  double speed_mps = 0.0;    // m/s, (smoothed) walking speed; sets stride, swing amplitudes and lean; 0 = standing
  double phase_rad = 0.0;    // rad, gait cycle phase; the left leg is fully forward at pi/2
};

// Strides per second at a walking speed (cadence / 2).
double StrideFrequencyHz(double speed_mps);
// Advances the gait phase by dt at the state's speed.
void AdvanceGaitPhase(double dt_s, GaitState* state);

// Number of joints posed: 133 for whole body, else 17.
int NumPosedJoints(bool whole_body);
// Poses the person: writes 3 x NumPosedJoints(whole_body) world coordinates (resizes `joints`).
void PoseJoints(const BodyShape& shape, const GaitState& state, bool whole_body, Eigen::Matrix3Xd* joints);

}  // namespace rpt::synthetic
