// SPDX-License-Identifier: MIT
// Generic labels: the RPT authors' "skelda" label list (shared/docs/datasets.md §12), read and
// written. Exact schema: docs/datasets/generic_formats.md.
//
// A file is a JSON list of labels, one per multi-view frame:
//   {"id": "...", "cameras": [{"name", "K" 3x3, "DC", "R" 3x3 world->camera, "T" camera centre
//    in metres 3x1, "width", "height", optional "type": "fisheye"}], "bodies3D": [person:
//    [joint: [x, y, z, visibility]]], "joints": [names], optional "splits", "scene" / "seq",
//    "room_size", "room_center", "bodyids", "timestamp", "fps"}.
// Labels are grouped into Sequences by "scene" (else "seq"; one sequence named after the file
// when neither is present), sequences and frames in file order.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "datasets/dataset_params.h"
#include "datasets/frame_source.h"
#include "datasets/sequence.h"

namespace rpt {

// Also the parameters of the "generic" dataset.
struct LabelsOptions {
  std::string split;  // keep only labels whose "splits" list contains it; empty = all labels
  // Frame rate for the times of labels with no "timestamp" and no "fps" (time = index in the
  // scene / fps); 0 = their times are unknown (NaN, one warning per file).
  double fps = 0;

  // "" or "generic.key: problem", the ranges of VisitFields (core/options_check.h).
  std::string Check() const;
};

template <class Visitor, OptionsOf<LabelsOptions> Self>
void VisitFields(Visitor& v, Self& o) {
  v("split", o.split, OptionSpec{.help = "keep only labels whose \"splits\" contain this name (default: all labels)"});
  v("fps", o.fps,
    OptionSpec{.help = "frame rate of labels without \"timestamp\" and \"fps\" (0 = their times are unknown)",
               .unit = "Hz",
               .min = 0});
}

// Opens a label file: one source per sequence. The file is kept as text and read once when it
// opens, for what the headers and times need (groups, ids, cameras, joints, times, rooms); each
// label's persons are parsed when its frame is pulled. Throws InputError naming the file and the
// JSON pointer: missing file, parse errors (with line and column), wrong shapes, unknown joint
// names, duplicate ids, and cameras that differ between two labels of one sequence (naming both
// labels); the errors of a label's persons ("bodies3D", "bodyids") when it is pulled. Frames have
// no detections (views empty). An R within 1e-3 of a rotation (max |R^T R - I|) is replaced by
// the nearest rotation and counted in the source's warnings; farther is an InputError naming the
// file and the camera's JSON pointer. Times: the labels' "timestamp"s, else index / fps (the
// scene's "fps", else options.fps), else unknown: NaN, counted in one warning per file
// (InputWarningKind::kMissing) that says how to give them. Without the ground truth (`ground_truth`
// false) "joints", "bodies3D" and "bodyids" are not read: frames with no persons, no GT joints.
std::vector<std::unique_ptr<FrameSource>> OpenLabels(const std::filesystem::path& path,
                                                     const LabelsOptions& options = {}, bool ground_truth = true);

// Writes the sequences as one label list ("scene" = sequence name, "timestamp" (null when unknown),
// "fps" (when known), "bodyids" when tracked, room). kH36M cameras are written with the extension "type": "h36m".
// Throws InputError naming the file when it cannot be written or a value is not finite. Returns the number of strings
// that were not valid UTF-8 (written as U+FFFD).
int WriteLabels(const std::filesystem::path& path, const std::vector<Sequence>& sequences);

// Registry pair: dataset "generic", --root = the label file, params split (default: all) and fps
// (default 0: times from the file, else unknown).
DatasetInfo GenericInfo();
std::vector<std::unique_ptr<FrameSource>> OpenGeneric(const DatasetRequest& request);

}  // namespace rpt
