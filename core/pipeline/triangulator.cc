// SPDX-License-Identifier: MIT
#include "core/pipeline/triangulator.h"

#include <algorithm>
#include <cmath>
#include <chrono>
#include <string>
#include <utility>

#include "core/errors.h"
#include "core/pipeline/frame_buffers.h"
#include "core/pipeline/frame_size.h"
#include "core/pipeline/model.h"
#include "core/pipeline/step_functions.h"
#include "core/pipeline/temporal_state.h"

namespace rpt {
namespace {

using Clock = std::chrono::steady_clock;

// Runs the steps bound in step_functions.h: Run<S> calls step S's function with its options
// section and records what it returns as its count and the time since the last step as its time,
// in S's slot of FrameStats. Done() closes a step the Triangulator assembles itself (single_view);
// Skip() passes a moment that is no step's time (the skipped moment still counts in total_us); a
// step that does not run keeps time and count 0.
class StepRunner {
 public:
  StepRunner(const TriangulatorOptions& options, FrameStats* stats)
      : options_(options), stats_(stats), start_(Clock::now()), last_(start_) {}
  template <Step S, class... Args>
  void Run(Args&&... args) {
    stats_->count[static_cast<int>(S)] = Call<S>(std::forward<Args>(args)...);
    Done(S);
  }
  // Step S's function alone: its result goes to the caller, which closes the step with Done(S).
  template <Step S, class... Args>
  int Call(Args&&... args) {
    return RunStep<S>(options_, std::forward<Args>(args)...);
  }
  void Done(Step step) {
    const Clock::time_point now = Clock::now();
    stats_->time_us[static_cast<int>(step)] += std::chrono::duration<double, std::micro>(now - last_).count();
    last_ = now;
  }
  void Skip() { last_ = Clock::now(); }
  void Finish() { stats_->total_us = std::chrono::duration<double, std::micro>(last_ - start_).count(); }

 private:
  const TriangulatorOptions& options_;
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

namespace {

// The pairs of `pairs` as pose-index pairs, for a FrameTrace.
void TracePairs(std::span<const PosePair> pairs, std::vector<std::array<int, 2>>* out) {
  out->clear();
  for (const PosePair& pair : pairs) out->push_back({pair.a, pair.b});
}

}  // namespace

void Triangulator::Process(std::span<const Poses2D> views, double timestamp_s, Poses3D* persons, FrameStats* stats,
                           FrameTrace* trace) {
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
    // A Poses2D filled by hand: data whose length is not whole persons of num_joints (or a negative
    // count) was dropped unseen or ended in std::length_error.
    const long long values = static_cast<long long>(views[v].data.size());
    if (views[v].num_joints < 0 || (views[v].num_joints == 0 && values > 0) ||
        (views[v].num_joints > 0 && values % (3LL * views[v].num_joints) != 0)) {
      throw InputError("view " + std::to_string(v) + ": " + std::to_string(values) + " values for poses of " +
                       std::to_string(views[v].num_joints) + " joints (3 per joint and person)");
    }
    if (views[v].unavailable && views[v].num_persons() > 0) {
      throw InputError("view " + std::to_string(v) + " is marked unavailable (no data this frame) but has " +
                       std::to_string(views[v].num_persons()) + " poses");
    }
    if (views[v].num_persons() > 0 && views[v].num_joints != num_inputs) {
      throw InputError("view " + std::to_string(v) + " has poses with " + std::to_string(views[v].num_joints) +
                       " joints, expected " + std::to_string(num_inputs));
    }
  }
  // Association grows with the square of the poses: refuse a frame too large before any work.
  if (const std::string problem = FrameSizeProblem(views, m.cameras, opt.triangulate.max_persons_per_view,
                                                   opt.triangulate.max_pairs_per_frame);
      !problem.empty()) {
    throw InputError(problem);
  }
  stats->Reset();
  StepRunner run(opt, stats);
  // Is this frame continuous with the last one? Unknown times and large gaps break continuity.
  const double elapsed_s = timestamp_s - state.last_timestamp_s;  // NaN when either is unknown
  const bool continuous = elapsed_s > 0 && elapsed_s <= m.max_gap_s;
  state.last_timestamp_s = timestamp_s;
  if (!continuous) state.StartAfresh(m.num_core_joints());

  run.Run<Step::kUndistort>(steps::UndistortInput{.views = views,
                                                  .cameras = m.cameras,
                                                  .geometry = m.geometry,
                                                  .derived = m.derived,
                                                  .core_joints = m.core_joints,
                                                  .num_output_joints = num_joints},
                            &buf.prepared);
  // The pre-filter, when it acts, lists the pairs it keeps itself; a trace records them all.
  const PairListing listing = PrefilterActs(opt.prefilter, state.previous) && trace == nullptr ? PairListing::kCountOnly
                                                                                                 : PairListing::kAll;
  run.Run<Step::kMakePairs>(buf.prepared, listing, &buf.pairs);
  if (trace != nullptr) {
    trace->Clear();
    trace->pose_view = buf.prepared.view_of;
    trace->pose_person = buf.prepared.person_of;
    TracePairs(buf.pairs, &trace->pairs[FrameTrace::kMakePairs]);
    run.Skip();
  }
  run.Run<Step::kPrefilter>(steps::PrefilterInput{.views = buf.prepared,
                                                  .geometry = m.geometry,
                                                  .core_joints = m.core_joints,
                                                  .previous = state.previous,
                                                  .timestamp_s = timestamp_s},
                            &buf.prefilter, &buf.pairs);
  if (trace != nullptr) {
    TracePairs(buf.pairs, &trace->pairs[FrameTrace::kPrefilter]);
    run.Skip();
  }
  run.Run<Step::kTriangulateCore>(
      steps::TriangulateCoreInput{
          .views = buf.prepared, .geometry = m.geometry, .pairs = buf.pairs, .joints = m.core_joints},
      &buf.core);
  if (trace != nullptr) {
    TracePairs(buf.core.pairs, &trace->pairs[FrameTrace::kTriangulateCore]);
    run.Skip();
  }
  run.Run<Step::kRoomCheck>(m.room, &buf.core);
  if (trace != nullptr) {
    TracePairs(buf.core.pairs, &trace->pairs[FrameTrace::kRoomCheck]);
    run.Skip();
  }
  run.Run<Step::kScore>(
      steps::ScoreInput{
          .views = buf.prepared, .geometry = m.geometry, .core_joints = m.core_joints, .core_limbs = m.core_limbs,
          .core_limb_columns = &m.core_limb_columns},
      &state.noise, &buf.score_scratch, &buf.core, &buf.kernel, stats);
  run.Run<Step::kFilter>(&buf.core);
  if (trace != nullptr) {
    TracePairs(buf.core.pairs, &trace->pairs[FrameTrace::kFilter]);
    run.Skip();
  }
  run.Run<Step::kGroup>(steps::GroupInput{.num_poses = buf.prepared.num_poses(), .mirror = m.core_mirror},
                        &buf.group_scratch, &buf.core, &buf.groups, stats);
  if (trace != nullptr) {
    trace->group_of_pair = buf.core.group;  // grouping keeps the filtered proposals in their order
    run.Skip();
  }
  run.Run<Step::kTriangulateFull>(steps::TriangulateFullInput{.views = buf.prepared,
                                                              .geometry = m.geometry,
                                                              .core = buf.core,
                                                              .groups = buf.groups,
                                                              .core_joints = m.core_joints,
                                                              .all_joints = m.all_joints,
                                                              .limbs = m.all_limbs,
                                                              .limb_columns = &m.all_limb_columns,
                                                              .kernel = buf.kernel},
                                  &buf.triangulate_full_scratch, &buf.full, stats);
  persons->Clear(num_joints);
  run.Run<Step::kMerge>(steps::MergeInput{.proposals = buf.full, .groups = buf.groups}, &buf.merge_scratch, persons);
  run.Run<Step::kRefine>(steps::RefineInput{.views = buf.prepared,
                                            .geometry = m.geometry,
                                            .proposals = buf.full,
                                            .groups = buf.groups,
                                            .min_joint_score = opt.merge.min_joint_score,
                                            .kernel = buf.kernel,
                                            .neighbour = m.neighbour},
                         &buf.refine_scratch, persons, stats);
  if (trace != nullptr) {
    // Verify and postprocess keep persons in order and move their track ids with them (all -1
    // until tracking): each person carries its merged index through them, then -1 again.
    trace->merged = *persons;
    for (int p = 0; p < persons->num_persons(); ++p) persons->track_ids[p] = p;
    run.Skip();
  }
  run.Run<Step::kVerify>(steps::VerifyInput{.views = buf.prepared,
                                            .geometry = m.geometry,
                                            .core_joints = m.core_joints,
                                            .proposals = buf.full,
                                            .groups = buf.groups,
                                            .kernel = buf.kernel},
                         &buf.verify_scratch, persons, stats);
  if (trace != nullptr) {
    trace->after_verify = persons->track_ids;
    run.Skip();
  }
  const steps::PostprocessInput postprocess_input{.neighbour = m.neighbour, .limbs = m.all_limbs, .room = m.room};
  run.Run<Step::kPostprocess>(postprocess_input, persons, stats);
  if (trace != nullptr) {
    trace->after_postprocess = persons->track_ids;
    std::fill(persons->track_ids.begin(), persons->track_ids.end(), -1);
    run.Skip();
  }

  // Step 12b: persons seen by one view only, post-processed like the others and appended. They
  // stay out of the pre-filter's memory: their depth is a guess.
  int num_lifted = run.Call<Step::kSingleView>(steps::SingleViewInput{.views = buf.prepared,
                                                                      .geometry = m.geometry,
                                                                      .core_joints = m.core_joints,
                                                                      .limbs = m.typical_limbs,
                                                                      .ground = m.ground_joints,
                                                                      .room = m.room,
                                                                      .tracks = opt.track.enabled ? &state.tracks : nullptr,
                                                                      .timestamp_s = timestamp_s,
                                                                      .proposals = buf.full,
                                                                      .groups = buf.groups,
                                                                      .kernel = buf.kernel,
                                                                      .found = *persons},
                                               &buf.single_view_scratch, &buf.lifted, stats);
  if (num_lifted > 0) {
    num_lifted = run.Call<Step::kPostprocess>(postprocess_input, &buf.lifted, stats);
    for (int p = 0; p < num_lifted; ++p) {
      persons->AddPerson() = buf.lifted.Person(p);
      // Lifted from one view, but filled joints stay filled.
      const std::span<uint8_t> source = persons->PersonProvenance(persons->num_persons() - 1);
      for (int j = 0; j < num_joints; ++j) {
        if (buf.lifted.Provenance(p, j) == JointProvenance::kTriangulated) {
          source[j] = static_cast<uint8_t>(JointProvenance::kLifted);
        }
      }
    }
  }
  const int first_lifted = persons->num_persons() - num_lifted;
  stats->count[static_cast<int>(Step::kSingleView)] = persons->num_persons();
  run.Done(Step::kSingleView);

  // The temporal steps need track ids: without tracking they do not run (zero time and count).
  // A frame without a time continues no track and starts none (its persons' track ids stay -1):
  // numbering them anew every frame looked like tracks.
  const bool tracking = opt.track.enabled && std::isfinite(timestamp_s);
  const int num_detected = persons->num_persons();  // track appends the coasting persons after them
  if (tracking) {
    run.Run<Step::kTrack>(steps::TrackInput{.match_joints = m.core_joints,
                                            .neighbour = m.neighbour,
                                            .unobserved_score = m.unobserved_score,
                                            .timestamp_s = timestamp_s},
                          &state.tracks, &buf.track_scratch, persons, stats);
  }
  if (tracking && opt.clip_speed.enabled) {
    run.Run<Step::kClipSpeed>(
        steps::ClipSpeedInput{.tracks = state.tracks, .timestamp_s = timestamp_s, .num_detected = num_detected},
        persons);
  }
  if (tracking && opt.bone_lengths.enabled) {
    run.Run<Step::kBoneLengths>(steps::BoneLengthsInput{.limbs = m.all_limbs,
                                                        .neighbour = m.neighbour,
                                                        .unobserved_score = m.unobserved_score,
                                                        .num_detected = num_detected,
                                                        .tracks = opt.track.hold_missing_joints ? &state.tracks : nullptr},
                                &state.bone_lengths, &buf.bone_lengths_scratch, persons, stats);
  }
  if (tracking && opt.smooth.mode == SmoothMode::kCausal) {
    run.Run<Step::kSmooth>(steps::SmoothInput{.timestamp_s = timestamp_s,
                                              .max_gap_s = m.max_gap_s,
                                              .unobserved_score = m.unobserved_score,
                                              .num_detected = num_detected},
                           &state.joint_filters, persons);
  }
  run.Skip();  // nothing between the last step that ran and remember is any step's time

  run.Run<Step::kRemember>(steps::RememberInput{.core_joints = m.core_joints,
                                                .persons = *persons,
                                                .first_lifted = first_lifted,
                                                .num_lifted = num_lifted,
                                                .num_detected = num_detected,
                                                .timestamp_s = timestamp_s},
                           &state.previous, tracking ? &state.tracks : nullptr);
  run.Finish();
}

}  // namespace rpt
