// SPDX-License-Identifier: MIT
// A detections file (any format ReadDetectionsFile reads) attached to the frames of an input's
// sequences as they stream past: each frame gets the views of the detection frame with its id,
// cameras matched by name. One file may serve several sequences (the scenes of a labels file,
// MVOR's days): each frame goes to the sequence that holds its id, as if each sequence had its
// own file.
//
// Errors (InputError naming the file and the frame): a detection camera that is not a camera of
// the frame's sequence, a view whose joint count differs from the file's joints, a sequence none
// of whose frame ids is in the file. Counted as unused input (one warning line each, under the
// file): frames of a sequence absent from the file (triangulated without detections), and, once
// every sequence is done, detection frames whose id is no frame of the input.
#pragma once

#include <atomic>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "datasets/detections.h"
#include "datasets/frame_source.h"
#include "datasets/input_warnings.h"

namespace rpt::engine {

class AttachedDetections {
 public:
  // `source` names the file in messages. Without `report_unused_frames`, detection frames no
  // sequence uses are not reported (a VoxelPose cache covers every image of a dataset).
  AttachedDetections(Detections detections, std::string source, bool report_unused_frames = true);
  ~AttachedDetections();

  // `frames` with the detections attached (header: detection_joints = the file's joints).
  std::unique_ptr<FrameSource> Wrap(std::unique_ptr<FrameSource> frames);

  // The file's own corrections (clamped scores, ...): reported once however many sequences use it.
  const InputWarnings& file_warnings() const { return detections_.warnings; }
  // What the wrapped sequences did not use, complete once every one is exhausted: detection
  // frames no sequence used, then frames of the sequences absent from the file (one line each,
  // counted over all sequences).
  InputWarnings Unused() const;
  // Detection frames whose id starts with `prefix` and ends in a digit are ids of the dataset
  // (DatasetInfo::frame_id_prefix): one no sequence used was left out by the reader's selection
  // (frames=, every=, days=, sequences=), not reported by Unused(). Empty: every one is reported.
  void SetDatasetFrameIdPrefix(std::string prefix) { dataset_prefix_ = std::move(prefix); }

 private:
  class Source;
  Detections detections_;
  std::string source_;
  bool report_unused_frames_;
  std::string dataset_prefix_;
  std::unordered_map<std::string, int> frame_index_;  // frame id -> index into detections_.frames
  std::unique_ptr<std::atomic<bool>[]> used_;         // per detection frame: attached to some frame
  // Per wrapped sequence (in the order wrapped): its frames absent from the file, and the first.
  struct Absent {
    long count = 0;
    std::string first;
  };
  std::vector<Absent> absent_;
};

}  // namespace rpt::engine
