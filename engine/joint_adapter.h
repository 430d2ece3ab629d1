// SPDX-License-Identifier: MIT
// A joint-definition adapter (docs/joint_adapter.md): per prediction joint, an offset in the
// person's body frame (core/body_frame.h, core/joint_offsets.h), fitted by `rpt fit-adapter` on
// one part of a dataset and applied by `rpt eval --adapter` to another. The file states where it
// was fitted (dataset, parameters, sequences, every frame id, matched persons); a run refuses to
// evaluate a frame the adapter was fitted on, and an adapter fitted for other joints.
#pragma once

#include <Eigen/Core>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <unordered_set>
#include <vector>

#include "core/joint_offsets.h"
#include "core/joints.h"

namespace rpt::engine {

// Where an adapter was fitted.
struct JointAdapterFitInfo {
  std::string dataset;               // the dataset reader ("" for other inputs)
  std::string root;                  // as given
  std::vector<std::string> params;   // key=value, as given: the split (e.g. frames=0-149, days=1,2)
  std::vector<std::string> sequences;
  long frames = 0;                   // frames triangulated
  long matched_persons = 0;          // matched (prediction, GT) pairs with a body frame
  long persons_without_body_frame = 0;  // matched pairs left out: the prediction had no body frame
  long min_samples = 0;              // joints with fewer residuals get no offset
  std::vector<std::string> frame_ids;  // every frame of the fit, in input order
  std::string command;               // the rpt command that fitted it
  std::string git_revision;
};

struct JointAdapter {
  std::string path;  // the file it was read from (for messages); "" when made in memory
  OffsetStatistic statistic = OffsetStatistic::kMedian;
  JointNames joints;                       // the prediction joints, in the predictions' order
  std::vector<Eigen::Vector3d> offset_m;   // per joint, body frame (x right, y forward, z up), metres
  std::vector<long> samples;               // per joint, residuals fitted
  std::vector<double> spread_m;            // per joint, median distance of the residuals from the offset
  JointAdapterFitInfo fit;

  // True when frame `id` is one of the fit's frames (fit.frame_ids; Index() builds the lookup).
  bool IsFitFrame(const std::string& id) const { return fit_frames_.count(id) > 0; }
  void Index() { fit_frames_ = {fit.frame_ids.begin(), fit.frame_ids.end()}; }
  // "the adapter 'a.json'" or "the adapter" (in memory), for messages.
  std::string Name() const;

 private:
  std::unordered_set<std::string> fit_frames_;
};

// Largest offset a file may give a joint (metres): more is no joint definition but a wrong file.
inline constexpr double kMaxJointOffsetM = 1.0;

// Reads and checks an adapter file; throws InputError naming the file and the JSON path.
JointAdapter ReadJointAdapter(const std::filesystem::path& path);
// Writes `adapter` to `path` (the user's --out; InputError naming it when it cannot be written).
void WriteJointAdapter(const std::filesystem::path& path, const JointAdapter& adapter);
// The adapter as its file's JSON; without the frame ids (their count and first and last only) for
// a run's summary.json.
nlohmann::ordered_json JointAdapterJson(const JointAdapter& adapter, bool with_frame_ids = true);
// One line: "shelf-4da frames=0-149: 150 frames, 420 matched persons".
std::string FitDescription(const JointAdapterFitInfo& fit);

// Throws ConfigError naming the adapter's file when its joints are not `joints` (the predictions'
// output joints) in the same order, or when `joints` lack the hips and shoulders of a body frame.
void CheckAdapterJoints(const JointAdapter& adapter, const JointNames& joints);

const char* OffsetStatisticName(OffsetStatistic statistic);

}  // namespace rpt::engine
