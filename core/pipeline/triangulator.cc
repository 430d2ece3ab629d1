// SPDX-License-Identifier: MIT
#include "core/pipeline/triangulator.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <set>
#include <string>

#include "core/errors.h"
#include "core/pipeline/clip_speed.h"
#include "core/pipeline/filter_proposals.h"
#include "core/pipeline/lift_single_views.h"
#include "core/pipeline/make_pairs.h"
#include "core/pipeline/postprocess_persons.h"
#include "core/pipeline/room_check.h"
#include "core/pipeline/score_proposals.h"
#include "core/pipeline/triangulate_pairs.h"
#include "core/pipeline/verify_persons.h"
#include "core/pipeline/workspace.h"

namespace rpt {
namespace {

using Clock = std::chrono::steady_clock;

// Accumulates the time since the last lap into one step's slot.
class StepTimer {
 public:
  explicit StepTimer(FrameStats* stats) : stats_(stats), start_(Clock::now()), last_(start_) {}
  void Lap(Step step) {
    const Clock::time_point now = Clock::now();
    stats_->time_us[static_cast<int>(step)] += std::chrono::duration<double, std::micro>(now - last_).count();
    last_ = now;
  }
  void Finish() { stats_->total_us = std::chrono::duration<double, std::micro>(last_ - start_).count(); }

 private:
  FrameStats* stats_;
  Clock::time_point start_, last_;
};

std::vector<ResolvedLimb> ResolveLimbs(const std::vector<LimbSpec>& limbs, const JointNames& names) {
  std::vector<ResolvedLimb> out;
  for (const LimbSpec& limb : limbs) {
    const int a = FindJoint(names, limb.a), b = FindJoint(names, limb.b);
    if (a >= 0 && b >= 0) out.push_back(ResolvedLimb{a, b, limb.min_length_m, limb.max_length_m});
  }
  return out;
}

}  // namespace

Triangulator::Triangulator(std::vector<Camera> cameras, JointNames input_joints, TriangulatorOptions options)
    : ws_(std::make_unique<Workspace>()) {
  Workspace& ws = *ws_;
  if (const std::string error = options.Check(); !error.empty()) throw ConfigError(error);
  if (cameras.size() < 2) throw ConfigError("the triangulator needs at least 2 cameras, got " + std::to_string(cameras.size()));
  for (const Camera& camera : cameras) {
    if (const std::string error = camera.Validate(); !error.empty()) throw ConfigError(error);
  }
  if (input_joints.empty()) throw ConfigError("the input joint list is empty");
  std::set<std::string> seen;
  for (const std::string& name : input_joints) {
    if (!seen.insert(name).second) throw ConfigError("duplicate input joint '" + name + "'");
  }

  ws.cameras = std::move(cameras);
  for (const Camera& camera : ws.cameras) ws.geometry.push_back(MakeViewGeometry(camera));
  ws.input_joints = std::move(input_joints);
  ws.output_joints = options.undistort.add_derived_joints ? AddDerivedJoints(ws.input_joints) : ws.input_joints;
  ws.options = std::move(options);
  if (ws.options.group.min_group_size == 0) {
    ws.options.group.min_group_size = ws.cameras.size() >= 10 ? 2 : 1;  // automatic, see GroupOptions
  }

  for (int j = static_cast<int>(ws.input_joints.size()); j < static_cast<int>(ws.output_joints.size()); ++j) {
    DerivedJointRule rule{j, {}};
    for (const JointNames& alternative : DerivedJointSources(ws.output_joints[j])) {
      std::vector<int> indices;
      for (const std::string& name : alternative) indices.push_back(FindJoint(ws.input_joints, name));
      if (std::find(indices.begin(), indices.end(), -1) == indices.end()) rule.alternatives.push_back(indices);
    }
    ws.derived.push_back(std::move(rule));
  }

  const JointNames& core_names =
      ws.options.triangulate.core_joints.empty() ? DefaultCoreJoints() : ws.options.triangulate.core_joints;
  JointNames core_list;
  for (const std::string& name : core_names) {
    const int j = FindJoint(ws.output_joints, name);
    if (j < 0) throw ConfigError("triangulate.core_joints: joint '" + name + "' is not among the input joints");
    ws.core_joints.push_back(j);
    core_list.push_back(name);
  }
  if (ws.options.triangulate.min_core_joints > static_cast<int>(ws.core_joints.size())) {
    throw ConfigError("triangulate.min_core_joints (" + std::to_string(ws.options.triangulate.min_core_joints) +
                      ") exceeds the number of core joints (" + std::to_string(ws.core_joints.size()) + ")");
  }
  for (int j = 0; j < static_cast<int>(ws.output_joints.size()); ++j) {
    ws.all_joints.push_back(j);
    ws.neighbour.push_back(FindJoint(ws.output_joints, NeighbourJoint(ws.output_joints[j])));
  }
  ws.core_limbs = ResolveLimbs(LimbsFor(core_list), core_list);
  ws.core_mirror = MirrorIndices(core_list);
  ws.all_limbs = ResolveLimbs(LimbsFor(ws.output_joints), ws.output_joints);
  ws.typical_limbs = ResolveTypicalLimbs(ws.output_joints);
  ws.previous.Clear(static_cast<int>(ws.core_joints.size()));
  ws.noise.Reset(ws.options.score.noise_prior_m);
}

Triangulator::~Triangulator() = default;
Triangulator::Triangulator(Triangulator&&) noexcept = default;
Triangulator& Triangulator::operator=(Triangulator&&) noexcept = default;

const JointNames& Triangulator::input_joints() const { return ws_->input_joints; }
const JointNames& Triangulator::output_joints() const { return ws_->output_joints; }
const std::vector<Camera>& Triangulator::cameras() const { return ws_->cameras; }
const TriangulatorOptions& Triangulator::options() const { return ws_->options; }

void Triangulator::Reset() {
  ws_->previous.Clear(static_cast<int>(ws_->core_joints.size()));
  ws_->tracker.Reset();
  ws_->bone_lengths.Reset();
  ws_->smoother.Reset();
  ws_->noise.Reset(ws_->options.score.noise_prior_m);
  ws_->last_timestamp_s = std::numeric_limits<double>::quiet_NaN();
}

void Triangulator::Process(std::span<const Poses2D> views, double timestamp_s, Poses3D* persons, FrameStats* stats) {
  Workspace& ws = *ws_;
  const TriangulatorOptions& opt = ws.options;
  const int num_inputs = static_cast<int>(ws.input_joints.size());
  const int num_joints = static_cast<int>(ws.output_joints.size());
  if (views.size() != ws.cameras.size()) {
    throw InputError("frame has " + std::to_string(views.size()) + " views but the triangulator has " +
                     std::to_string(ws.cameras.size()) + " cameras");
  }
  for (size_t v = 0; v < views.size(); ++v) {
    if (views[v].num_persons() > 0 && views[v].num_joints != num_inputs) {
      throw InputError("view " + std::to_string(v) + " has poses with " + std::to_string(views[v].num_joints) +
                       " joints, expected " + std::to_string(num_inputs));
    }
  }
  stats->Reset();
  StepTimer timer(stats);
  // Is this frame continuous with the last one? Unknown times and large gaps break continuity.
  const double elapsed_s = timestamp_s - ws.last_timestamp_s;  // NaN when either is unknown
  const bool continuous = elapsed_s > 0 && elapsed_s <= opt.track.max_gap_s;
  ws.last_timestamp_s = timestamp_s;
  if (!continuous) {
    ws.previous.Clear(static_cast<int>(ws.core_joints.size()));
    ws.tracker.EndTracks();
  }
  auto& count = stats->count;
  auto at = [](Step s) { return static_cast<int>(s); };

  count[at(Step::kUndistort)] =
      UndistortPoses(views, ws.cameras, ws.geometry, ws.derived, ws.core_joints, opt.triangulate.min_core_joints,
                     num_joints, opt.undistort, &ws.prepared);
  timer.Lap(Step::kUndistort);

  count[at(Step::kPairs)] = MakePairs(ws.prepared, &ws.pairs);
  timer.Lap(Step::kPairs);

  count[at(Step::kPrefilter)] =
      PrefilterPairs(ws.prepared, ws.geometry, ws.core_joints, ws.previous, timestamp_s, opt.prefilter, &ws.prefilter,
                     &ws.pairs);
  timer.Lap(Step::kPrefilter);

  count[at(Step::kTriangulateCore)] = TriangulatePairs(ws.prepared, ws.geometry, ws.pairs, ws.core_joints,
                                                       opt.triangulate.method, opt.triangulate.min_core_joints, &ws.core);
  timer.Lap(Step::kTriangulateCore);

  count[at(Step::kRoomCheck)] = RoomCheck(opt.room_check, &ws.core);
  timer.Lap(Step::kRoomCheck);

  stats->pruned_limbs += ScoreProposals(ws.prepared, ws.geometry, ws.core_joints, ws.core_limbs, opt.score, &ws.noise,
                                        &ws.score_scratch, &ws.core);
  stats->noise_m = opt.score.scale == ScoreScale::kAdaptive ? ws.noise.Estimate() : 0.0;
  count[at(Step::kScore)] = ws.core.size();
  timer.Lap(Step::kScore);

  count[at(Step::kFilter)] = FilterProposals(opt.filter, &ws.core);
  timer.Lap(Step::kFilter);

  GroupCounters group_counters;
  count[at(Step::kGroup)] = GroupProposals(opt.group, ws.prepared.num_poses(), ws.core_mirror, &ws.core, &ws.groups,
                                           &ws.group_scratch, &group_counters);
  stats->small_groups = group_counters.small_groups;
  stats->conflicting_proposals = group_counters.conflicting_proposals;
  stats->mirrored_groups = group_counters.mirrored_groups;
  timer.Lap(Step::kGroup);

  // Step 10: the grouped pairs again, now with all joints; proposal i = groups.members[i].
  count[at(Step::kTriangulateFull)] = TriangulateMembers(ws.prepared, ws.geometry, ws.core, ws.groups.members,
                                                         ws.core_joints, num_joints, opt.triangulate.method, &ws.full);
  stats->pruned_limbs +=
      ScoreProposals(ws.prepared, ws.geometry, ws.all_joints, ws.all_limbs, opt.score, &ws.noise, &ws.score_scratch,
                     &ws.full, /*pair_scores=*/false);
  timer.Lap(Step::kTriangulateFull);

  persons->Clear(num_joints);
  count[at(Step::kMerge)] = MergeGroups(opt.merge, ws.full, ws.groups, &ws.merge_scratch, persons);
  timer.Lap(Step::kMerge);

  count[at(Step::kVerify)] = VerifyPersons(opt.verify, ws.prepared, ws.geometry, ws.core_joints, ws.full, ws.groups,
                                           KernelScaleM(opt.score, ws.noise.Estimate()), &ws.verify_scratch, persons,
                                           stats);
  timer.Lap(Step::kVerify);

  count[at(Step::kPostprocess)] =
      PostprocessPersons(opt.postprocess, opt.room_check, ws.neighbour, ws.all_limbs, persons, stats);
  timer.Lap(Step::kPostprocess);

  // Step 12b: persons seen by one view only, post-processed like the others and appended. They
  // stay out of the pre-filter's memory: their depth is a guess.
  int num_lifted = LiftSingleViews(opt.single_view, opt.verify, ws.prepared, ws.geometry, ws.core_joints,
                                   ws.typical_limbs, ws.full, ws.groups, KernelScaleM(opt.score, ws.noise.Estimate()),
                                   *persons, &ws.verify_scratch, &ws.single_view_scratch, &ws.lifted, stats);
  if (num_lifted > 0) {
    num_lifted = PostprocessPersons(opt.postprocess, opt.room_check, ws.neighbour, ws.all_limbs, &ws.lifted, stats);
    for (int p = 0; p < num_lifted; ++p) persons->AddPerson() = ws.lifted.Person(p);
  }
  const int num_triangulated = persons->num_persons() - num_lifted;
  count[at(Step::kSingleView)] = persons->num_persons();
  timer.Lap(Step::kSingleView);

  int num_detected = persons->num_persons();
  if (opt.track.enabled) num_detected = ws.tracker.Assign(opt.track, ws.core_joints, persons, stats);
  count[at(Step::kTrack)] = persons->num_persons();
  timer.Lap(Step::kTrack);

  if (opt.track.enabled) {
    count[at(Step::kClipSpeed)] = ClipSpeed(opt.clip_speed, ws.tracker, timestamp_s, num_detected, persons);
  }
  timer.Lap(Step::kClipSpeed);

  // The temporal steps need track ids. Joints at or below the filled score are not observations.
  const double filled_score = opt.UnobservedScore();
  if (opt.track.enabled) {
    count[at(Step::kBoneLengths)] = ws.bone_lengths.Apply(opt.bone_lengths, ws.all_limbs, ws.neighbour, filled_score,
                                                          num_detected, persons, stats);
  }
  timer.Lap(Step::kBoneLengths);

  if (opt.track.enabled) {
    count[at(Step::kSmooth)] =
        ws.smoother.Apply(opt.smooth, opt.track.max_gap_s, filled_score, timestamp_s, num_detected, persons);
    // The tracks' last poses are the outputs (what speed clipping and coasting refer to).
    ws.tracker.Commit(*persons, num_detected, timestamp_s);
  }
  // Remember this frame's persons for the next frame's pre-filter.
  const int num_core = static_cast<int>(ws.core_joints.size());
  ws.previous.Clear(num_core);
  ws.previous.timestamp_s = timestamp_s;
  for (int p = 0; p < persons->num_persons(); ++p) {
    if (p >= num_triangulated && p < num_triangulated + num_lifted) continue;  // single-view persons
    const auto person = persons->Person(p);
    for (int c = 0; c < num_core; ++c) {
      ws.previous.xyz.push_back(person.col(ws.core_joints[c]).head<3>());
      ws.previous.score.push_back(person(3, ws.core_joints[c]));
    }
  }
  timer.Lap(Step::kSmooth);
  timer.Finish();
}

}  // namespace rpt
