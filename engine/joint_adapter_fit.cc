// SPDX-License-Identifier: MIT
#include "engine/joint_adapter_fit.h"

#include <limits>
#include <optional>

#include "core/body_frame.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "engine/input.h"
#include "metrics/accumulator.h"

namespace rpt::engine {
namespace {

// Collects the residuals of the matched persons of every sequence (each sequence its own state:
// sequences may run on different threads), merged in sequence order at the end.
class AdapterFitSink final : public FrameSink {
 public:
  AdapterFitSink(int num_sequences, const metrics::EvalOptions& eval) : eval_(eval), sequences_(num_sequences) {}

  void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) override {
    State& s = sequences_[static_cast<size_t>(sequence)];
    s.name = header.name;
    s.gt_joints = header.gt_joints;
    s.output_joints = output_joints;
    s.frame_joints = BodyFrameJoints::Find(output_joints);
    if (!s.frame_joints.complete()) {
      throw ConfigError(header.name + ": the predictions lack the hips and shoulders a body frame is built from "
                        "(hip_left, hip_right, shoulder_left, shoulder_right): no adapter can be fitted");
    }
    s.gt_of_output.clear();
    for (const std::string& name : output_joints) s.gt_of_output.push_back(FindJoint(header.gt_joints, name));
    s.metrics.emplace(eval_);
    s.fit.emplace(static_cast<int>(output_joints.size()));
    s.gt.resize(3, static_cast<long>(output_joints.size()));
  }

  void Frame(const FrameOutput& frame) override {
    State& s = sequences_[static_cast<size_t>(frame.sequence)];
    const SequenceFrame& input = *frame.input;
    s.frame_ids.push_back(input.id);
    s.metrics->Add(input.id, input.gt, s.gt_joints, *frame.persons, s.output_joints);
    const metrics::FrameRecords& records = s.metrics->LastFrame();
    for (const metrics::PairRecord& pair : records.pairs) {
      if ((pair.flags & metrics::kMatch) == 0 || pair.pred_idx < 0 || pair.gt_idx < 0) continue;
      const int gt_person = records.kept_gt_idx[static_cast<size_t>(pair.gt_idx)];
      const auto gt = input.gt.Person(gt_person);
      for (size_t j = 0; j < s.gt_of_output.size(); ++j) {
        const int g = s.gt_of_output[j];
        const bool valid = g >= 0 && gt(3, g) > eval_.min_gt_score;
        if (valid) {
          s.gt.col(static_cast<long>(j)) = gt.col(g).head<3>();
        } else {
          s.gt.col(static_cast<long>(j)).setConstant(std::numeric_limits<double>::quiet_NaN());
        }
      }
      if (s.fit->Add(frame.persons->Person(pair.pred_idx), s.gt, s.frame_joints)) {
        ++s.matched;
      } else {
        ++s.without_frame;
      }
    }
  }

  void EndSequence(int) override {}

  // The adapter of all sequences (they must share their output joints).
  JointAdapter Finish(const JointAdapterFitOptions& options) const {
    JointAdapter adapter;
    adapter.statistic = options.statistic;
    std::optional<JointOffsetFit> all;
    for (const State& s : sequences_) {
      if (!s.fit) continue;
      if (!all) {
        adapter.joints = s.output_joints;
        all.emplace(static_cast<int>(s.output_joints.size()));
      } else if (s.output_joints != adapter.joints) {
        throw ConfigError("sequences " + QuoteName(sequences_.front().name) + " and " + QuoteName(s.name) +
                          " have different prediction joints: fit an adapter per sequence");
      }
      all->Merge(*s.fit);
      adapter.fit.sequences.push_back(s.name);
      adapter.fit.frame_ids.insert(adapter.fit.frame_ids.end(), s.frame_ids.begin(), s.frame_ids.end());
      adapter.fit.matched_persons += s.matched;
      adapter.fit.persons_without_body_frame += s.without_frame;
    }
    if (!all) throw ConfigError("no sequence to fit the adapter on");
    const JointOffsetFit::Result result = all->Finish(options.statistic, options.min_samples);
    adapter.offset_m = result.offset_m;
    adapter.samples = result.samples;
    adapter.spread_m = result.spread_m;
    adapter.fit.frames = static_cast<long>(adapter.fit.frame_ids.size());
    adapter.fit.min_samples = options.min_samples;
    adapter.Index();
    return adapter;
  }

 private:
  struct State {
    std::string name;
    JointNames gt_joints, output_joints;
    BodyFrameJoints frame_joints;
    std::vector<int> gt_of_output;  // per output joint, its GT joint (-1 = none)
    std::optional<metrics::MetricsAccumulator> metrics;
    std::optional<JointOffsetFit> fit;
    Eigen::Matrix3Xd gt;            // the matched GT person per output joint (NaN = none)
    std::vector<std::string> frame_ids;
    long matched = 0, without_frame = 0;
  };

  metrics::EvalOptions eval_;
  std::vector<State> sequences_;
};

RunOptions FitRunOptions(const RunOptions& options) {
  if (options.adapter) throw ConfigError("an adapter is fitted on the triangulator's own predictions: give none");
  if (!options.eval) throw ConfigError("fitting an adapter needs the ground truth (metrics)");
  RunOptions run = options;
  run.eval.reset();  // the sink matches the frames itself
  run.loss_table = false;
  return run;
}

}  // namespace

JointAdapter FitJointAdapter(Input& input, const RunOptions& options, const JointAdapterFitOptions& fit) {
  const RunOptions run = FitRunOptions(options);
  std::vector<const SequenceHeader*> headers;
  for (int i = 0; i < input.size(); ++i) headers.push_back(&input.header(i));
  AdapterFitSink sink(input.size(), EvalOptionsFor(*options.eval, headers));
  Run(input, run, &sink);
  return sink.Finish(fit);
}

JointAdapter FitJointAdapter(std::span<const Sequence> sequences, const RunOptions& options,
                             const JointAdapterFitOptions& fit) {
  const RunOptions run = FitRunOptions(options);
  std::vector<const SequenceHeader*> headers;
  for (const Sequence& sequence : sequences) headers.push_back(&sequence);
  AdapterFitSink sink(static_cast<int>(sequences.size()), EvalOptionsFor(*options.eval, headers));
  Run(sequences, run, &sink);
  return sink.Finish(fit);
}

}  // namespace rpt::engine
