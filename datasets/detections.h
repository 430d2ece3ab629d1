// SPDX-License-Identifier: MIT
// 2D detections independent of their file format, keyed by frame id and camera name, and how
// they attach to a Sequence.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/joints.h"
#include "core/poses.h"
#include "datasets/sequence.h"

namespace rpt {

struct FrameDetections {
  std::string frame_id;              // matches SequenceFrame::id
  std::vector<std::string> cameras;  // camera names, one per entry of `views`
  std::vector<Poses2D> views;        // pixels of the original (distorted) image; score 0 = missing
  // The frame's time in seconds where the file gives one (generic JSON's "time"); kUnknownTime
  // (NaN) otherwise. Used only without labels (datasets/readers/detection_frames.h): labels carry
  // the times of their frames.
  double time_s = kUnknownTime;
};

struct Detections {
  JointNames joints;                   // joint names of every Poses2D
  std::vector<FrameDetections> frames;
  InputWarnings warnings;              // corrections the reader applied (one line per file and kind)
  // What a camera left out of a frame means: true where the format lists the cameras that were
  // processed (generic JSON, the live lines, OpenPose folders, rpt's HDF5 cache): the camera has no
  // data for that frame (Poses2D::unavailable), and so has every camera of a frame the file leaves
  // out; false where a format lists only cameras with detections (COCO result lists): it saw
  // nobody. A camera the file mentions in no frame at all has no data in any frame either way.
  bool unlisted_cameras_unavailable = false;
};

// Marks the views of a frame that the detections give no data for: `listed[c]` says whether the
// frame lists camera c (`frame_in_file`: whether the file has the frame at all), `mentioned[c]`
// whether any frame of the file does. The views must be empty already (Clear).
void MarkUnavailableViews(const Detections& detections, bool frame_in_file, std::span<const char> listed,
                          std::span<const char> mentioned, std::span<Poses2D> views);

// `detections` for a format where a camera left out of a frame has no data there (generic JSON,
// rpt's HDF5 cache): where unlisted_cameras_unavailable is false, each frame also lists, with no
// persons, every camera the file mentions in some frame. Returns nullptr when nothing changes
// (the caller writes `detections` itself).
std::unique_ptr<Detections> WithUnlistedCamerasUnavailable(const Detections& detections);

// mentioned[c] for `cameras` (by name): whether any frame of `detections` lists the camera.
std::vector<char> CamerasMentioned(const Detections& detections, const std::vector<std::string>& cameras);

struct AttachReport {
  int frames_with_detections = 0;  // input frames listed in the detections (possibly with no person)
  int frames_without = 0;          // input frames absent from the detections (no persons)
  int unused_frames = 0;           // detection frames whose id is no frame of the input (ignored)
  std::string first_frame_without;  // id of the first of frames_without
  std::string first_unused_frame;   // id of the first of unused_frames
};

// Detectors write (0, 0) for a joint they did not find, some of them with its low confidence: a
// detected joint at exactly pixel (0, 0) with a score above 0 is set to score 0 (missing). Returns
// how many were; the readers of detection files (ReadDetectionsFile, the live lines) count them
// under the file as kOriginJointsRead. The simulated detector reports a joint it would clamp into
// that corner as not found (datasets/synthetic/detector_simulator.cc), so it never writes one.
long ReadOriginJointsAsMissing(Poses2D* view);
inline constexpr const char* kOriginJointsRead =
    "detected joints at pixel (0, 0) with a score above 0 read as missing (what detectors write for a joint they "
    "did not find)";

// Sets every sequence's detection_joints and its frames' views (camera order of the sequence)
// from `detections`. Each detection frame goes to the sequence that holds its frame id, so one
// file may serve several sequences (the scenes of a labels file, MVOR's days) and behaves as if
// each sequence had its own file. Cameras are matched by name; a camera the detections do not
// mention gets no persons. Throws InputError naming `source` and the frame when a detection
// camera is not a camera of the frame's sequence, on joint-count mismatches, and naming the
// sequence when none of its frame ids is in the detections. The frames that do not match
// (AttachReport::unused_frames, frames_without) are counted under `source` in `warnings` as
// unused input, one line each with the first id. `detections.warnings` is not copied (one
// Detections may be attached more than once): the caller reports it once.
AttachReport AttachDetections(const Detections& detections, const std::string& source, std::span<Sequence> sequences,
                              InputWarnings* warnings);
// Its parts, for readers that attach their own detections frame by frame: the unmatched frames
// of `report` counted under `source` in `warnings` (the two lines above), and the error when none
// of a sequence's frames is in the detections (`num_detection_frames` ids, the first
// `first_detection_id`).
void CountUnattachedFrames(const AttachReport& report, const std::string& source, InputWarnings* warnings);
InputError NoFrameMatchesError(const std::string& source, size_t num_detection_frames,
                               const std::string& first_detection_id, const std::string& sequence_name,
                               const std::string& first_frame_id);

}  // namespace rpt
