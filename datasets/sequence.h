// SPDX-License-Identifier: MIT
// The dataset-independent representation every reader produces: cameras, the capture volume,
// and frames with ground-truth 3D persons and 2D detections, all in metres and the world frame.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "core/camera.h"
#include "core/joints.h"
#include "core/poses.h"
#include "core/room.h"
#include "datasets/input_warnings.h"

namespace rpt {

// How a dataset (or the detector simulator) labels one person in one image. COCO convention for
// the per-joint flags.
enum : int8_t {
  kLabelAbsent = 0,    // not labelled in this image (outside it, or the annotator gave no position)
  kLabelOccluded = 1,  // labelled, hidden behind something
  kLabelVisible = 2,   // labelled and visible
};
struct PersonLabel2D {
  int gt_person = -1;                   // index into SequenceFrame::gt; -1 = labelled in 2D only (no 3D label)
  Eigen::Vector4d box_px = Eigen::Vector4d::Zero();  // x0, y0, x1, y1 in the image; all zero = none
  std::vector<int8_t> visibility;       // per GT joint (gt_joints order): kLabel*; empty = not labelled
};

// SequenceFrame::timestamp_s of a frame whose time is unknown: nothing is carried over from the
// frame before (no tracking, no pre-filter, no speed limit across it).
inline constexpr double kUnknownTime = std::numeric_limits<double>::quiet_NaN();

struct SequenceFrame {
  std::string id;                // unique label id (e.g. "shelf_000300")
  double timestamp_s = 0;        // for speed clipping and tracking; kUnknownTime (NaN) = unknown
  Poses3D gt;                    // ground truth; joint score = visibility (> 0.1 visible)
  std::vector<Poses2D> views;    // detections per camera (may be empty when not loaded)
  // Per camera, the persons labelled in that image (datasets with 2D labels such as MVOR, and
  // simulated detections: the simulator's own occlusion). Empty when there are none; only the
  // detector statistics (`rpt detector-stats`) use them.
  std::vector<std::vector<PersonLabel2D>> labels_2d;
  // Microseconds the reader spent grouping this frame's raw detection candidates into persons
  // (the shelf-4da reader's part-affinity grouping, all views, including the conversion of the
  // persons to views); negative = the reader grouped nothing. Reported as the step table's row
  // "paf_grouping (reader)" (metrics/timing.h): work a user feeding raw candidates pays per frame
  // on top of the pipeline.
  double paf_grouping_us = -1;
};

// What a sequence is, without its frames: what a FrameSource (datasets/frame_source.h) announces
// before its first frame.
struct SequenceHeader {
  std::string name;                 // e.g. "shelf", "panoptic/160906_band1"
  std::vector<Camera> cameras;
  JointNames gt_joints;             // joint names of SequenceFrame::gt
  JointNames detection_joints;      // joint names of SequenceFrame::views
  JointNames evaluated_joints;      // the dataset's evaluated joints; empty = the paper's 13
  Room room;
  double fps = 0;  // 0 = unknown (frames without a rate)
  // The GT's track ids name one person in every frame of the sequence (false: they number the
  // persons of one frame, as MVOR's person_id; identity switches are then not counted).
  bool gt_ids_across_frames = true;
};

// A sequence with all its frames in memory.
struct Sequence : SequenceHeader {
  std::vector<SequenceFrame> frames;
  InputWarnings warnings;           // corrections the reader applied (one line per file and kind)
};

// Checks shapes and values (camera validity, joint counts, finite coordinates, scores in [0, 1],
// unique frame ids; a time may be unknown, NaN). Throws InputError naming `source`, the frame id
// and the view on failure. Strict on purpose: readers correct real-world imprecision first
// (rotations re-orthonormalised, scores clamped; datasets/input_warnings.h) but do not validate:
// the consumer validates every frame once (datasets/frame_source.h).
void ValidateSequence(const Sequence& sequence, const std::string& source);
// Its two parts, for frames that stream (datasets/frame_source.h): the header (cameras), and one
// frame against its header (repeated frame ids are left to the consumer).
void ValidateSequenceHeader(const SequenceHeader& sequence, const std::string& source);
void ValidateFrame(const SequenceHeader& sequence, const SequenceFrame& frame, const std::string& source);

}  // namespace rpt
