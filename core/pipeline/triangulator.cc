// SPDX-License-Identifier: MIT
#include "core/pipeline/triangulator.h"

#include <chrono>
#include <string>

#include "core/errors.h"
#include "core/pipeline/clip_speed.h"
#include "core/pipeline/filter.h"
#include "core/pipeline/frame_buffers.h"
#include "core/pipeline/make_pairs.h"
#include "core/pipeline/model.h"
#include "core/pipeline/postprocess.h"
#include "core/pipeline/remember.h"
#include "core/pipeline/room_check.h"
#include "core/pipeline/score.h"
#include "core/pipeline/temporal_state.h"
#include "core/pipeline/triangulate_core.h"
#include "core/pipeline/triangulate_full.h"

namespace rpt {
namespace {

using Clock = std::chrono::steady_clock;

// Accumulates each step's time into its FrameStats slot. Done() closes a step that ran; Skip()
// one that did not run, whose time and count stay 0 (the skipped moment still counts in total_us).
class StepTimer {
 public:
  explicit StepTimer(FrameStats* stats) : stats_(stats), start_(Clock::now()), last_(start_) {}
  void Done(Step step) {
    const Clock::time_point now = Clock::now();
    stats_->time_us[static_cast<int>(step)] += std::chrono::duration<double, std::micro>(now - last_).count();
    last_ = now;
  }
  void Skip() { last_ = Clock::now(); }
  void Finish() { stats_->total_us = std::chrono::duration<double, std::micro>(last_ - start_).count(); }

 private:
  FrameStats* stats_;
  Clock::time_point start_, last_;
};

}  // namespace

Triangulator::Triangulator(std::vector<Camera> cameras, JointNames input_joints, TriangulatorOptions options)
    : model_(std::make_unique<const TriangulatorModel>(
          BuildModel(std::move(cameras), std::move(input_joints), std::move(options)))),
      frame_(std::make_unique<FrameBuffers>()),
      temporal_(std::make_unique<TemporalState>()) {
  temporal_->Reset(model_->num_core_joints(), model_->resolved.score.noise_prior_m);
}

Triangulator::~Triangulator() = default;
Triangulator::Triangulator(Triangulator&&) noexcept = default;
Triangulator& Triangulator::operator=(Triangulator&&) noexcept = default;

const JointNames& Triangulator::input_joints() const { return model_->input_joints; }
const JointNames& Triangulator::output_joints() const { return model_->output_joints; }
const std::vector<Camera>& Triangulator::cameras() const { return model_->cameras; }
const TriangulatorOptions& Triangulator::options() const { return model_->options; }

void Triangulator::Reset() { temporal_->Reset(model_->num_core_joints(), model_->resolved.score.noise_prior_m); }

void Triangulator::Process(std::span<const Poses2D> views, double timestamp_s, Poses3D* persons, FrameStats* stats) {
  const TriangulatorModel& m = *model_;
  const TriangulatorOptions& opt = m.resolved;
  FrameBuffers& buf = *frame_;
  TemporalState& state = *temporal_;
  const int num_inputs = static_cast<int>(m.input_joints.size());
  const int num_joints = m.num_output_joints();
  if (views.size() != m.cameras.size()) {
    throw InputError("frame has " + std::to_string(views.size()) + " views but the triangulator has " +
                     std::to_string(m.cameras.size()) + " cameras");
  }
  for (size_t v = 0; v < views.size(); ++v) {
    if (views[v].num_persons() > 0 && views[v].num_joints != num_inputs) {
      throw InputError("view " + std::to_string(v) + " has poses with " + std::to_string(views[v].num_joints) +
                       " joints, expected " + std::to_string(num_inputs));
    }
    // Association cost grows with the square of the persons per view: refuse before any work.
    if (views[v].num_persons() > opt.triangulate.max_persons_per_view) {
      throw InputError("view " + std::to_string(v) + " (camera '" + m.cameras[v].name + "') has " +
                       std::to_string(views[v].num_persons()) + " 2D poses, above triangulate.max_persons_per_view (" +
                       std::to_string(opt.triangulate.max_persons_per_view) +
                       "); raise it with --set triangulate.max_persons_per_view=N if this is a real scene");
    }
  }
  stats->Reset();
  StepTimer timer(stats);
  // Is this frame continuous with the last one? Unknown times and large gaps break continuity.
  const double elapsed_s = timestamp_s - state.last_timestamp_s;  // NaN when either is unknown
  const bool continuous = elapsed_s > 0 && elapsed_s <= opt.track.max_gap_s;
  state.last_timestamp_s = timestamp_s;
  if (!continuous) state.StartAfresh(m.num_core_joints());
  auto count = [stats](Step s) -> int& { return stats->count[static_cast<int>(s)]; };

  count(Step::kUndistort) = steps::Undistort(views, m.cameras, m.geometry, m.derived, m.core_joints,
                                             opt.triangulate.min_core_joints, num_joints, opt.undistort, &buf.prepared);
  timer.Done(Step::kUndistort);

  count(Step::kMakePairs) = steps::MakePairs(buf.prepared, &buf.pairs);
  timer.Done(Step::kMakePairs);

  count(Step::kPrefilter) = steps::Prefilter(buf.prepared, m.geometry, m.core_joints, state.previous, timestamp_s,
                                             opt.prefilter, &buf.prefilter, &buf.pairs);
  timer.Done(Step::kPrefilter);

  count(Step::kTriangulateCore) = steps::TriangulateCore(buf.prepared, m.geometry, buf.pairs, m.core_joints,
                                                         opt.triangulate.method, opt.triangulate.min_core_joints,
                                                         &buf.core);
  timer.Done(Step::kTriangulateCore);

  count(Step::kRoomCheck) = steps::RoomCheck(opt.room_check, &buf.core);
  timer.Done(Step::kRoomCheck);

  count(Step::kScore) = steps::Score(buf.prepared, m.geometry, m.core_joints, m.core_limbs, opt.score, &state.noise,
                                     &buf.score_scratch, &buf.core, stats);
  timer.Done(Step::kScore);

  count(Step::kFilter) = steps::Filter(opt.filter, &buf.core);
  timer.Done(Step::kFilter);

  count(Step::kGroup) = steps::Group(opt.group, buf.prepared.num_poses(), m.core_mirror, &buf.core, &buf.groups,
                                     &buf.group_scratch, stats);
  timer.Done(Step::kGroup);

  count(Step::kTriangulateFull) =
      steps::TriangulateFull(buf.prepared, m.geometry, buf.core, buf.groups.members, m.core_joints, m.all_joints,
                             m.all_limbs, opt.triangulate.method, opt.score, state.noise, &buf.score_scratch,
                             &buf.full, stats);
  timer.Done(Step::kTriangulateFull);

  persons->Clear(num_joints);
  count(Step::kMerge) = steps::Merge(opt.merge, buf.full, buf.groups, &buf.merge_scratch, persons);
  timer.Done(Step::kMerge);

  const double kernel_scale_m = KernelScaleM(opt.score, state.noise.Estimate());
  count(Step::kVerify) = steps::Verify(opt.verify, buf.prepared, m.geometry, m.core_joints, buf.full, buf.groups,
                                       kernel_scale_m, &buf.verify_scratch, persons, stats);
  timer.Done(Step::kVerify);

  count(Step::kPostprocess) =
      steps::Postprocess(opt.postprocess, opt.room_check, m.neighbour, m.all_limbs, persons, stats);
  timer.Done(Step::kPostprocess);

  // Step 12b: persons seen by one view only, post-processed like the others and appended. They
  // stay out of the pre-filter's memory: their depth is a guess.
  int num_lifted = steps::SingleView(opt.single_view, opt.verify, buf.prepared, m.geometry, m.core_joints,
                                     m.typical_limbs, buf.full, buf.groups, kernel_scale_m, *persons,
                                     &buf.verify_scratch, &buf.single_view_scratch, &buf.lifted, stats);
  if (num_lifted > 0) {
    num_lifted = steps::Postprocess(opt.postprocess, opt.room_check, m.neighbour, m.all_limbs, &buf.lifted, stats);
    for (int p = 0; p < num_lifted; ++p) persons->AddPerson() = buf.lifted.Person(p);
  }
  const int first_lifted = persons->num_persons() - num_lifted;
  count(Step::kSingleView) = persons->num_persons();
  timer.Done(Step::kSingleView);

  // The temporal steps need track ids: without tracking they do not run (zero time and count).
  // Joints at or below the filled score are not observations.
  const bool tracking = opt.track.enabled;
  int num_detected = persons->num_persons();
  if (tracking) {
    num_detected = state.tracker.Assign(opt.track, m.core_joints, persons, stats);
    count(Step::kTrack) = persons->num_persons();
    timer.Done(Step::kTrack);
  }
  if (tracking && opt.clip_speed.enabled) {
    count(Step::kClipSpeed) = steps::ClipSpeed(opt.clip_speed, state.tracker, timestamp_s, num_detected, persons);
    timer.Done(Step::kClipSpeed);
  }
  const double filled_score = opt.UnobservedScore();
  if (tracking && opt.bone_lengths.enabled) {
    count(Step::kBoneLengths) = state.bone_lengths.Apply(opt.bone_lengths, m.all_limbs, m.neighbour, filled_score,
                                                         num_detected, persons, stats);
    timer.Done(Step::kBoneLengths);
  }
  if (tracking && opt.smooth.mode == SmoothMode::kCausal) {
    count(Step::kSmooth) =
        state.smoother.Apply(opt.smooth, opt.track.max_gap_s, filled_score, timestamp_s, num_detected, persons);
    timer.Done(Step::kSmooth);
  }
  timer.Skip();  // nothing between the last step that ran and remember is any step's time

  count(Step::kRemember) = steps::Remember(m.core_joints, *persons, first_lifted, num_lifted, num_detected,
                                           timestamp_s, &state.previous, tracking ? &state.tracker : nullptr);
  timer.Done(Step::kRemember);
  timer.Finish();
}

}  // namespace rpt
