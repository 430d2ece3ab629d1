// SPDX-License-Identifier: MIT
#include "datasets/readers/fourda_text.h"

#include <cstdint>
#include <limits>
#include <set>
#include <utility>

#include "datasets/io/text_tokens.h"
#include "datasets/readers/openpose_body25.h"

namespace rpt {
namespace {

// Counts are bounded by TextTokens::CheckCount (what the rest of the file can hold), not here.
constexpr std::int64_t kAnyCount = std::numeric_limits<std::int64_t>::max();
constexpr std::int64_t kMaxSkeletonJoints = 10000;

std::string FramePrefix(std::int64_t frame) { return "frame " + std::to_string(frame); }

// Nothing may follow the last frame: a longer file means the header or a count is wrong.
void ExpectEnd(io::TextTokens& tokens, std::int64_t frames) {
  tokens.ExpectEnd("the " + std::to_string(frames) + " frames the header announces");
}

void ParseDetectionFrame(io::TextTokens& tokens, std::int64_t frame, InputWarnings* warnings, PafCandidates* out) {
  const PafSkeleton& skeleton = Body25PafSkeleton();
  const JointNames& names = Body25Joints();
  out->joints.resize(static_cast<size_t>(skeleton.num_joints));
  for (int j = 0; j < skeleton.num_joints; ++j) {
    const auto where = [&] { return FramePrefix(frame) + ", joint " + std::to_string(j) + " (" + names[j] + ")"; };
    const std::int64_t n = tokens.Int(0, kAnyCount, [&] { return where() + ": candidate count"; });
    tokens.CheckCount(n, 3, [&] { return where() + ": candidate count"; });
    Eigen::Matrix3Xd& candidates = out->joints[static_cast<size_t>(j)];
    candidates.resize(3, static_cast<Eigen::Index>(n));
    static const char* const kRows[] = {"x", "y", "score"};
    for (int row = 0; row < 3; ++row) {
      for (Eigen::Index i = 0; i < candidates.cols(); ++i) {
        const double value =
            tokens.Number([&] { return where() + ", candidate " + std::to_string(i) + ": " + kRows[row]; });
        candidates(row, i) =
            row < 2 ? value : AcceptScore(value, tokens.source(), warnings, [&] { return tokens.Here(); });
      }
    }
  }
  out->pafs.resize(skeleton.limbs.size());
  for (size_t k = 0; k < skeleton.limbs.size(); ++k) {
    const int a = skeleton.limbs[k].first, b = skeleton.limbs[k].second;  // lambdas capture them (clang 14)
    const Eigen::Index rows = out->joints[static_cast<size_t>(a)].cols();
    const Eigen::Index cols = out->joints[static_cast<size_t>(b)].cols();
    const auto where = [&] {
      return FramePrefix(frame) + ", PAF " + std::to_string(k) + " (" + names[a] + "-" + names[b] + ")";
    };
    tokens.CheckCount(static_cast<std::int64_t>(rows) * cols, 1, [&] { return where() + ": PAF entries"; });
    Eigen::MatrixXd& paf = out->pafs[k];
    paf.resize(rows, cols);
    for (Eigen::Index r = 0; r < rows; ++r) {
      for (Eigen::Index c = 0; c < cols; ++c) {
        paf(r, c) = tokens.Number([&] { return where() + ", entry (" + std::to_string(r) + ", " + std::to_string(c) + ")"; });
      }
    }
  }
}

FourDaDetections ParseDetections(io::TextTokens& tokens, InputWarnings* warnings) {
  FourDaDetections out;
  out.skel_type = static_cast<int>(tokens.Int(0, std::numeric_limits<int>::max(), [] { return std::string("header: skeleton type"); }));
  if (out.skel_type != kFourDaBody25) {
    tokens.Fail("header: skeleton type " + std::to_string(out.skel_type) + " is not supported (only " +
                std::to_string(kFourDaBody25) + " = BODY25, OpenPose's 25-joint model)");
  }
  const std::int64_t frames = tokens.Int(0, kAnyCount, [] { return std::string("header: frame count"); });
  tokens.CheckCount(frames, kBody25Joints, [] { return std::string("header: frame count"); });
  out.frames.resize(static_cast<size_t>(frames));
  for (std::int64_t f = 0; f < frames; ++f) ParseDetectionFrame(tokens, f, warnings, &out.frames[static_cast<size_t>(f)]);
  ExpectEnd(tokens, frames);
  return out;
}

FourDaSkeletons ParseSkeletons(io::TextTokens& tokens) {
  FourDaSkeletons out;
  out.num_joints =
      static_cast<int>(tokens.Int(1, kMaxSkeletonJoints, [] { return std::string("header: joint count"); }));
  const std::int64_t frames = tokens.Int(0, kAnyCount, [] { return std::string("header: frame count"); });
  tokens.CheckCount(frames, 1, [] { return std::string("header: frame count"); });
  out.frames.resize(static_cast<size_t>(frames));
  static const char* const kRows[] = {"x", "y", "z", "validity"};
  for (std::int64_t f = 0; f < frames; ++f) {
    const std::int64_t persons = tokens.Int(0, kAnyCount, [&] { return FramePrefix(f) + ": person count"; });
    tokens.CheckCount(persons, 1 + 4 * static_cast<std::int64_t>(out.num_joints),
                      [&] { return FramePrefix(f) + ": person count"; });
    std::vector<FourDaPerson>& frame = out.frames[static_cast<size_t>(f)];
    frame.resize(static_cast<size_t>(persons));
    std::set<int> identities;
    for (std::int64_t p = 0; p < persons; ++p) {
      const auto where = [&] { return FramePrefix(f) + ", person " + std::to_string(p); };
      FourDaPerson& person = frame[static_cast<size_t>(p)];
      person.identity = static_cast<int>(
          tokens.Int(std::numeric_limits<int>::min(), std::numeric_limits<int>::max(), [&] { return where() + ": identity"; }));
      if (!identities.insert(person.identity).second) {
        tokens.Fail(where() + ": identity " + std::to_string(person.identity) + " appears twice in this frame");
      }
      person.line = tokens.line();
      person.joints.resize(4, out.num_joints);
      for (int row = 0; row < 4; ++row) {
        for (int j = 0; j < out.num_joints; ++j) {
          const auto what = [&] { return where() + ", joint " + std::to_string(j) + ": " + kRows[row]; };
          const double value = tokens.Number(what);
          if (row == 3 && !(value >= 0.0 && value <= 1.0)) tokens.Fail(what() + " " + std::to_string(value) + " outside [0, 1]");
          person.joints(row, j) = value;
        }
      }
    }
  }
  ExpectEnd(tokens, frames);
  return out;
}

}  // namespace

const PafSkeleton& Body25PafSkeleton() {
  static const PafSkeleton skeleton = [] {
    PafSkeleton s;
    s.num_joints = kBody25Joints;
    s.limbs.assign(Body25PafPairs().begin(), Body25PafPairs().end());
    return s;
  }();
  return skeleton;
}

FourDaDetections ParseFourDaDetections(std::string text, const std::string& source, InputWarnings* warnings) {
  io::TextTokens tokens(std::move(text), source);
  return ParseDetections(tokens, warnings);
}

FourDaDetections ReadFourDaDetections(const std::filesystem::path& path, InputWarnings* warnings) {
  io::TextTokens tokens = io::TextTokens::FromFile(path);
  return ParseDetections(tokens, warnings);
}

FourDaSkeletons ParseFourDaSkeletons(std::string text, const std::string& source) {
  io::TextTokens tokens(std::move(text), source);
  return ParseSkeletons(tokens);
}

FourDaSkeletons ReadFourDaSkeletons(const std::filesystem::path& path) {
  io::TextTokens tokens = io::TextTokens::FromFile(path);
  return ParseSkeletons(tokens);
}

}  // namespace rpt
