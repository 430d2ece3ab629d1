// SPDX-License-Identifier: MIT
// The HDF5 cache: detections (and optionally labels) in one file that loads fast.
//
// Layout (all datasets contiguous, uncompressed; strings fixed-length, variable-length strings
// are read too). P = all persons of all views, V = all views, F = frames, J = joints:
//   /detections                 group, attributes format = "rpt-detections", version = 1
//     joints         [J]        joint names
//     cameras        [C]        camera names used by the views
//     frame_ids      [F]
//     view_offsets   [F+1]      int64, frame f owns views view_offsets[f] .. view_offsets[f+1]-1
//     view_cameras   [V]        int32 index into cameras
//     person_offsets [V+1]      int64, view v owns persons person_offsets[v] .. [v+1]-1
//     keypoints      [P, J, 3]  float32 (default) or float64: u, v (pixels), score
//   /sequences                  group, attributes format = "rpt-sequences", version = 1, count
//     /sequences/<i>            group per sequence (i = 0, 1, ...), attributes name, fps
//       room_center [3], room_size [3]            float64
//       camera_names [C], camera_models [C]       strings ("none", "opencv", "h36m", "fisheye")
//       camera_image_size [C, 2] int32 (width, height); camera_K [C, 3, 3]; camera_dist [C, 5];
//       camera_R [C, 3, 3]; camera_t [C, 3]       float64 (cam_from_world, metres)
//       gt_joints [J], frame_ids [F], timestamps [F] float64
//       gt_offsets [F+1] int64, gt_poses [P, J, 4] float64, gt_track_ids [P] int32
// Sequences keep cameras and ground truth only (frame views are not stored).
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "datasets/detections.h"
#include "datasets/frame_source.h"
#include "datasets/sequence.h"

namespace rpt {

struct Hdf5WriteOptions {
  bool add_to_existing = false;  // add (or replace) this group in an existing cache instead of a new file
  bool float64 = false;          // detection keypoints as float64 (exact) instead of float32
};

// Throws InputError naming the file when it cannot be written or the detections are invalid
// (ValidateDetections).
void WriteDetectionsHdf5(const std::filesystem::path& path, const Detections& detections,
                         const Hdf5WriteOptions& options = {});
// Throws InputError naming the file and the HDF5 dataset path on anything malformed: not an
// HDF5 file, no /detections group, wrong shapes, offsets that do not add up, camera indices out
// of range, NaN or infinite values, negative scores or scores above 1.5, unknown joint names.
// Scores in (1, 1.5] (a cache written by another tool) are clamped to 1 and counted in
// Detections::warnings.
Detections ReadDetectionsHdf5(const std::filesystem::path& path);

// Sequences (cameras + ground truth). The writer checks them (ValidateSequence) first. The reader
// opens one source per sequence: the arrays are read and checked when it opens, each frame cut out
// of them when it is pulled. Same error behaviour as above; camera_R within 1e-3 of a rotation is
// replaced by the nearest rotation and counted in the source's warnings (AcceptRotation), farther
// is an error. A NaN timestamp is an unknown time (written for labels without times), counted in
// one warning per file (InputWarningKind::kMissing); an infinite one is an error.
void WriteSequencesHdf5(const std::filesystem::path& path, const std::vector<Sequence>& sequences,
                        const Hdf5WriteOptions& options = {});
std::vector<std::unique_ptr<FrameSource>> OpenSequencesHdf5(const std::filesystem::path& path);

// What a cache file holds. Throws InputError when the file is missing or not HDF5.
struct Hdf5CacheContents {
  bool detections = false;
  bool sequences = false;
};
Hdf5CacheContents ProbeHdf5Cache(const std::filesystem::path& path);

// Keeps the HDF5 library from running its clean-up at process exit; call first thing in main(),
// before any other HDF5 call (the readers call it too, for programs that do not). HDF5 1.10
// crashes in that clean-up (segmentation fault in H5F__close_cb, fixed in 1.14) when closing a
// file failed earlier, as it does when a write fails (full disk, file size limit), and prints
// "HDF5: infinite loop closing library" after reading some damaged files (its own leak, upstream
// issue #3790). Every file rpt opens is closed by its owner (RAII), so the clean-up has nothing
// else to do.
void SkipHdf5CleanupAtExit();

}  // namespace rpt
