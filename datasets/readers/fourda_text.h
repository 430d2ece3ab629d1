// SPDX-License-Identifier: MIT
// The text files of 4D-Association (Zhang et al., CVPR 2020, github.com/zhangyux15/4d_association):
// whitespace-separated numbers, matrices written row by row.
//
// Detection files (data/shelf/detection/<camera>.txt), OpenPose bottom-up output of one camera:
//   skelType frameCount                        skelType 4 = BODY25 (the only type read here)
//   per frame:
//     per joint (25):  n, then a 3 x n matrix: row x, row y (normalised to [0, 1]), row score
//     per PAF (26, Body25PafPairs() order): an nA x nB matrix of PAF scores (no count; the
//                      shape follows from the candidate counts, empty when either is 0)
//
// Skeleton files (data/shelf/gt.txt, and 4D-Association's own output skel.txt):
//   jointCount frameCount
//   per frame: personCount, then per person: identity, a 4 x jointCount matrix (rows x, y, z in
//              metres, row 4 = validity)
//
// Errors are InputErrors naming the file, line and token (datasets/io/text_tokens.h): truncated
// files, negative or oversized counts, non-numbers, a wrong header, tokens left over at the end.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

#include "datasets/input_warnings.h"
#include "datasets/readers/openpose_paf_association.h"

namespace rpt {

// 4D-Association's SkelType enum value of OpenPose BODY_25.
inline constexpr int kFourDaBody25 = 4;

// The BODY_25 skeleton as PafSkeleton (openpose_body25.h).
const PafSkeleton& Body25PafSkeleton();

struct FourDaDetections {
  int skel_type = kFourDaBody25;
  // One entry per frame; joint candidates with x, y as stored (normalised) and scores in [0, 1].
  std::vector<PafCandidates> frames;
};

// Candidate scores go through AcceptScore (values up to kMaxScoreOvershoot are clamped to 1 and
// counted under the file in `warnings`). Throws InputError for any skelType but 4.
FourDaDetections ParseFourDaDetections(std::string text, const std::string& source, InputWarnings* warnings);
FourDaDetections ReadFourDaDetections(const std::filesystem::path& path, InputWarnings* warnings);

struct FourDaPerson {
  int identity = 0;
  Eigen::Matrix4Xd joints;  // rows x, y, z, validity; one column per joint
  long line = 0;            // line of the identity in the file (for messages)
};

struct FourDaSkeletons {
  int num_joints = 0;
  std::vector<std::vector<FourDaPerson>> frames;  // persons per frame, file order
};

// Values must be finite and validities in [0, 1]; a duplicate identity within a frame is an error.
FourDaSkeletons ParseFourDaSkeletons(std::string text, const std::string& source);
FourDaSkeletons ReadFourDaSkeletons(const std::filesystem::path& path);

}  // namespace rpt
