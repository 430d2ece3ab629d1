// SPDX-License-Identifier: MIT
// Options of the simulated 2D detector and its named profiles (docs/detector_model.md).
//
// Two error models share the person-level options (misses, false positives, swaps, truncation):
// - the hand-tuned "clean" model (fitted.enabled = false, the defaults of DetectorOptions): per-axis
//   Gaussian pixel noise relative to the person's 2D box plus rare outliers, the confidence
//   derived from the error;
// - the fitted model (fitted.enabled = true; profiles realistic and hard, fitted to real OpenPose
//   detections of Shelf and MVOR): the confidence is drawn
//   first and a heavy-tailed error given it, in metres at the person's depth; joints hidden by
//   other persons, furniture or the own torso are reported displaced with medium confidence or
//   dropped; systematic per-joint offsets in 3D (skeleton definitions); per-camera calibration
//   error.
#pragma once

#include <string>
#include <vector>

namespace rpt::synthetic {

// Where the detector's skeleton puts a joint relative to the dataset's, in metres in the person's
// 3D body frame (e.g. COCO hips sit lower and closer together than MVOR's hip labels).
struct JointOffset {
  std::string joint;     // output joint name
  double down_m = 0;     // along the body axis, shoulder centre -> hip centre
  double out_m = 0;      // sideways: away from the midline for left/right joints, to the person's left otherwise
  double forward_m = 0;  // towards the person's front
};

// Per-joint parts of the fitted model.
struct FittedJoint {
  std::string joint;         // output joint name
  double error_factor = 1.0;  // factor on the error scale of the joint when visible
  double hidden_drop = -1.0;  // chance the joint is dropped when hidden; < 0: FittedErrorOptions::occluded_drop
  double score_factor = 1.0;  // factor on its drawn confidence (the error follows the drawn value)
};

// A per-joint chance.
struct JointChance {
  std::string joint;
  double probability = 0.0;
};

// Occluders of the fitted model; a hidden joint is labelled kLabelOccluded in Detect()'s labels.
struct OcclusionOptions {
  bool enabled = false;
  // Persons: a joint is hidden when its projection falls inside another person's silhouette
  // (capsules around the projected bones: limbs, torso, head) that is closer to the camera by the
  // depth margin; limb joints are also hidden behind their own torso.
  double limb_radius_m = 0.06;
  double torso_radius_m = 0.09;
  double head_radius_m = 0.11;
  double depth_margin_m = 0.1;       // m, the occluding bone must be this much closer to the camera
  bool self_occlusion = true;        // arms and legs behind the own torso
  // Furniture (tables, beds, equipment) in front of a person hides every joint below its top
  // edge: per person and camera, in blocks of frames (staggered per person), with this chance.
  double furniture_probability = 0.0;
  int furniture_block_frames = 50;
  double furniture_top_min_m = -0.4;  // m, top edge relative to the person's hip centre (world z up)
  double furniture_top_max_m = 0.2;
  // Clutter the scene does not model (equipment, drapes, clothing, objects in the hands): each
  // listed joint not hidden otherwise is hidden with its chance, per frame, camera and person.
  std::vector<JointChance> clutter;
};

// The fitted error model (used when enabled).
struct FittedErrorOptions {
  bool enabled = false;
  // Confidences are score_max times a Beta draw (a detector's ceiling: OpenPose rarely reports
  // more than 0.9). Visible joints: the Beta has this mean and concentration (a + b); the error
  // is a 2D Student-t with scale error_m * exp(error_growth * (1 - confidence)) metres at the
  // person's depth (pixels per metre at the depth of its joints' centroid).
  double score_max = 1.0;
  double visible_score_mean = 0.7;
  double visible_score_concentration = 8.0;
  double error_m = 0.01;
  double error_growth = 2.0;
  double error_dof = 3.0;            // Student-t degrees of freedom (<= 0: Gaussian)
  std::vector<FittedJoint> joints;   // per output joint name; others: factor 1, occluded_drop
  // Per person and view: a log-normal factor on all its error scales (sigma of its log), and a
  // shift of all its joints (per-axis sigma, metres at its depth).
  double person_spread = 0.3;
  double person_shift_m = 0.0;
  // A visible joint is a stray (reported far off, e.g. on another person's limb) with this
  // chance: a Student-t error (3 degrees of freedom) of scale stray_error_m, same confidence.
  double stray_probability = 0.0;
  double stray_error_m = 0.3;
  // Hidden joints (OcclusionOptions): dropped with occluded_drop, else confidence = score_max *
  // Beta(mean, concentration) and a Student-t error of scale occluded_error_m; with occluded_snap a joint
  // hidden by another person is reported on that person's same joint instead.
  double occluded_drop = 0.3;
  double occluded_score_mean = 0.45;
  double occluded_score_concentration = 5.0;
  double occluded_error_m = 0.1;
  double occluded_error_dof = 3.0;   // Student-t degrees of freedom of their error
  double occluded_snap = 0.0;
  // A person is missed with person_miss + person_miss_hidden * h^2, h = the hidden share of its
  // in-image joints (partly hidden persons are found, mostly hidden ones often not).
  double person_miss_hidden = 0.0;
  // Each joint of a false positive is reported with this chance (fragments of persons).
  double false_positive_joint_keep = 1.0;
  // Per detected person, each left/right pair of joints is exchanged with this chance (on top
  // of left_right_swap, which exchanges all of them); exchanged joints' confidences are
  // multiplied by swap_score_factor (a confused detector is less sure).
  double pair_swap = 0.0;
  double swap_score_factor = 1.0;
};

struct DetectorOptions {
  double noise_relative = 0.008;          // fraction of the person's 2D bbox diagonal: per-axis Gaussian pixel sigma
  double noise_absolute_px = 0.5;         // px, added to the relative sigma
  double outlier_probability = 0.01;      // per joint, chance of a heavy-tailed error instead of the normal one
  double outlier_relative = 0.05;         // fraction of the bbox diagonal: per-axis sigma of outlier errors
  double joint_dropout = 0.03;            // per visible joint, chance it is reported missing (score 0)
  double person_miss = 0.03;              // per person and view, chance it is not detected
  double false_positives_per_view = 0.2;  // Poisson mean of spurious persons per view (each seen in one view only)
  double false_positive_score_scale = 0.7;  // factor on the confidences of false positives
  double left_right_swap = 0.01;          // per detected person, chance its left and right joints are exchanged
  int min_visible_joints = 5;             // a person with fewer in-image joints is not detected
  double score_base = 0.95;               // confidence of an error-free joint
  double score_error_slope = 0.1;         // confidence lost per inlier sigma of pixel error
  double score_jitter = 0.03;             // sigma of Gaussian noise added to confidences
  double score_min = 0.05;                // lower clamp of confidences of reported joints (upper clamp: 1)
  bool shuffle_persons = true;            // randomise the order of persons within a view

  // Fitted model (all off by default: DetectorOptions{} is the clean profile).
  FittedErrorOptions fitted;              // replaces noise_*, outlier_*, score_base/slope/jitter when enabled
  OcclusionOptions occlusion;
  std::vector<JointOffset> joint_offsets;  // applied to the GT in 3D before projection
  double calibration_px = 0.0;            // px, per camera: the detector sees a camera rotated by ~this much (per-axis sigma at the centre)

  // Exact projections, score 1, nothing dropped, missed, swapped or invented; GT order kept.
  // Truncation still applies (a person needs one in-image joint).
  static DetectorOptions Perfect();
  // The hand-tuned model used before the fit to real detectors: the defaults above.
  static DetectorOptions Clean();
  // Fitted to real OpenPose detections of a multi-camera room (4D-Association's Shelf, hidden
  // joints' behaviour from MVOR); the default profile.
  static DetectorOptions Realistic();
  // Fitted to real OpenPose detections of an occluded operating room (MVOR): clearly worse
  // than realistic (more occlusion, misses and noise).
  static DetectorOptions Hard();
};

// Profile names: perfect, clean, realistic, hard.
const std::vector<std::string>& DetectorProfileNames();
// The options of a profile by name ("none" is an alias of "perfect"); ConfigError otherwise.
DetectorOptions DetectorProfile(const std::string& name);

}  // namespace rpt::synthetic
