// SPDX-License-Identifier: MIT
#include "datasets/synthetic/scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "core/errors.h"
#include "core/option_codec.h"
#include "core/options_check.h"
#include "datasets/synthetic/person_motion.h"
#include "datasets/synthetic/random.h"

namespace rpt::synthetic {
// Not an anonymous namespace: SceneStream::State, a class with linkage, holds a Walkers and an Animator.
namespace scene_internal {

using Eigen::Vector2d;

// Distance of the hip centre from the walls: keeps swinging feet and hands inside the room.
constexpr double kWallMargin = 0.65;
// Waypoints keep this distance from the walls.
constexpr double kWaypointMargin = 1.0;
// Steering keeps this much more than the minimum separation when it can.
constexpr double kComfortExtra = 0.35;
constexpr double kLookahead = 1.0;        // m, free path wanted ahead
constexpr int kSteerSteps = 16;           // candidate directions per half turn
constexpr double kWaitProbability = 0.2;  // chance of standing still at a waypoint
constexpr double kTurnRate = 3.0;         // rad/s
constexpr double kAcceleration = 1.5;     // m/s^2
constexpr double kDeceleration = 3.0;     // m/s^2
constexpr double kArrivalRadius = 0.3;    // m
constexpr double kBlockedTimeout = 2.0;   // s, then a new waypoint

struct Box2 {
  Vector2d lo, hi;
  bool Contains(const Vector2d& p) const { return (p.array() >= lo.array()).all() && (p.array() <= hi.array()).all(); }
  Vector2d Sample(Rng& rng) const {
    const double y = rng.Uniform(lo.y(), hi.y()), x = rng.Uniform(lo.x(), hi.x());  // in this order (random.h)
    return Vector2d(x, y);
  }
};

Box2 ShrunkRoom(const Eigen::Vector3d& center, const Eigen::Vector3d& size, double margin) {
  const Vector2d half = 0.5 * size.head<2>() - Vector2d::Constant(margin);
  return {center.head<2>() - half, center.head<2>() + half};
}

// Ground path of one person: position and facing per frame.
struct Path {
  std::vector<Vector2d> position;
  std::vector<double> heading;
};

struct Agent {
  Vector2d position;
  double heading = 0.0;
  double speed = 0.0;
  double preferred_speed = 1.0;
  Vector2d waypoint;
  double wait_s = 0.0;
  double blocked_s = 0.0;
};

double DistanceToSegment(const Vector2d& q, const Vector2d& a, const Vector2d& b) {
  const Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((q - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - q).norm();
}

// A waypoint at least 1.5 m away, preferably not behind the walker (avoids turning on the spot).
Vector2d SampleWaypoint(Rng& rng, const Box2& area, const Vector2d& from, double heading) {
  const Vector2d forward(std::cos(heading), std::sin(heading));
  Vector2d fallback = area.Sample(rng);
  for (int attempt = 0; attempt < 30; ++attempt) {
    const Vector2d candidate = area.Sample(rng);
    const Vector2d offset = candidate - from;
    if (offset.norm() < 1.5) continue;
    if (offset.normalized().dot(forward) > -0.2) return candidate;
    fallback = candidate;
  }
  return fallback;
}

Vector2d Direction(double angle) { return Vector2d(std::cos(angle), std::sin(angle)); }

// Multi-agent walk: waypoints, steering around others, waiting, standing still. The agents'
// positions and headings are the path of the current frame; Step() advances them by one frame.
// Memory does not depend on the number of frames (the scene streams; SceneStream).
class Walkers {
 public:
  Walkers(const SceneOptions& options, uint64_t seed)
      : rng(seed),
        n(options.num_people),
        dt(1.0 / options.fps),
        walk(ShrunkRoom(options.room_center_m, options.room_size_m, kWallMargin)),
        waypoints(ShrunkRoom(
            options.room_center_m, options.room_size_m,
            std::min(kWaypointMargin,
                     std::max(kWallMargin, std::min(options.room_size_m.x(), options.room_size_m.y()) * 0.5 - 0.5)))),
        min_sep(options.min_separation_m),
        comfort(options.min_separation_m + kComfortExtra),
        agents(options.num_people) {
    // Initial placement: rejection sampling, generous spacing first.
    for (double spacing : {min_sep + 0.5, min_sep + 1e-3}) {
      bool placed_all = true;
      for (int i = 0; i < n && placed_all; ++i) {
        bool placed = false;
        for (int attempt = 0; attempt < 5000 && !placed; ++attempt) {
          agents[i].position = walk.Sample(rng);
          placed = std::all_of(agents.begin(), agents.begin() + i, [&](const Agent& other) {
            return (other.position - agents[i].position).norm() >= spacing;
          });
        }
        placed_all = placed;
      }
      if (placed_all) break;
      if (spacing < min_sep + 0.1) {
        throw ConfigError("synthetic scene: cannot place " + std::to_string(n) + " people " + std::to_string(min_sep) +
                          " m apart in the room");
      }
    }
    for (Agent& agent : agents) {
      agent.preferred_speed = rng.Uniform(0.6, 1.5);
      agent.heading = rng.Uniform(-std::numbers::pi, std::numbers::pi);
      agent.waypoint = SampleWaypoint(rng, waypoints, agent.position, agent.heading);
      agent.heading = std::atan2(agent.waypoint.y() - agent.position.y(), agent.waypoint.x() - agent.position.x()) +
                      rng.Normal(0.0, 0.2);
      if (rng.Bernoulli(0.2)) {
        agent.wait_s = rng.Uniform(0.5, 3.0);
      } else {
        agent.speed = agent.preferred_speed;
      }
    }
  }

  const std::vector<Agent>& Agents() const { return agents; }

  void Step() {
    for (int i = 0; i < n; ++i) {
      Agent& agent = agents[i];
      double target_speed = 0.0;
      double desired_heading = agent.heading;
      if (agent.wait_s > 0.0) {
        agent.wait_s -= dt;
      } else {
        const Vector2d to_waypoint = agent.waypoint - agent.position;
        const double distance = to_waypoint.norm();
        if (distance < kArrivalRadius) {
          if (rng.Bernoulli(kWaitProbability)) agent.wait_s = rng.Uniform(0.8, 3.0);
          agent.waypoint = SampleWaypoint(rng, waypoints, agent.position, agent.heading);
        }
        const Vector2d goal = agent.waypoint - agent.position;
        const double goal_heading = std::atan2(goal.y(), goal.x());
        const double lookahead = std::min(kLookahead, goal.norm());
        // Steering: the smallest deviation from the goal direction, penalising intrusion into
        // the others' comfort zones; right turns win ties (people pass on the right).
        double best_cost = std::numeric_limits<double>::infinity();
        double best_steer = 0.0, best_intrusion = 0.0;
        for (int k = 0; k <= 2 * kSteerSteps; ++k) {
          const double steer = (k % 2 == 1 ? -1.0 : 1.0) * ((k + 1) / 2) * (std::numbers::pi / kSteerSteps);
          const double crowding = intrusion(i, Direction(goal_heading + steer), lookahead);
          if (crowding < 0.0) continue;
          const double cost = std::abs(steer) + 4.0 * crowding + (steer > 0.0 ? 1e-3 : 0.0);
          if (cost < best_cost) {
            best_cost = cost;
            best_steer = steer;
            best_intrusion = crowding;
          }
        }
        if (std::isfinite(best_cost)) {
          agent.blocked_s = 0.0;
          desired_heading = goal_heading + best_steer;
          target_speed = agent.preferred_speed * (1.0 - 0.3 * std::abs(best_steer) / std::numbers::pi) *
                         (best_intrusion > 0.0 ? 0.75 : 1.0);
        } else {
          desired_heading = goal_heading;
          agent.blocked_s += dt;
          if (agent.blocked_s > kBlockedTimeout) {
            agent.blocked_s = 0.0;
            agent.waypoint = SampleWaypoint(rng, waypoints, agent.position, agent.heading);
          }
        }
      }
      // Turn with a limited rate; walk slower while the heading is off.
      const double turn = std::remainder(desired_heading - agent.heading, 2.0 * std::numbers::pi);
      agent.heading =
          std::remainder(agent.heading + std::clamp(turn, -kTurnRate * dt, kTurnRate * dt), 2.0 * std::numbers::pi);
      const double remaining = std::remainder(desired_heading - agent.heading, 2.0 * std::numbers::pi);
      target_speed *= std::max(0.0, std::cos(remaining));
      agent.speed = std::clamp(target_speed, agent.speed - kDeceleration * dt, agent.speed + kAcceleration * dt);
      // Hard constraints: inside the room, minimum separation to everybody's current position.
      const Vector2d next = agent.position + agent.speed * dt * Direction(agent.heading);
      bool allowed = walk.Contains(next);
      for (int j = 0; j < n && allowed; ++j) {
        if (j != i && (agents[j].position - next).norm() < min_sep) allowed = false;
      }
      if (allowed) {
        agent.position = next;
      } else {
        agent.speed = 0.0;
      }
    }
  }

 private:
  // Scores walking `lookahead` metres towards `direction`, treating the others as static: -1 when
  // infeasible (leaves the walkable area or comes closer than min_sep + 5 cm to somebody it is not
  // already moving away from), otherwise the summed intrusion into the others' comfort zones (m).
  double intrusion(int i, const Vector2d& direction, double lookahead) const {
    const Vector2d& start = agents[i].position;
    const Vector2d end = start + lookahead * direction;
    if (!walk.Contains(end)) return -1.0;
    double total = 0.0;
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const double current = (agents[j].position - start).norm();
      const double closest = DistanceToSegment(agents[j].position, start, end);
      if (closest < std::min(min_sep + 0.05, current - 1e-9)) return -1.0;
      total += std::max(0.0, comfort - closest);
    }
    return total;
  }

  Rng rng;
  const int n;
  const double dt;
  const Box2 walk;
  const Box2 waypoints;
  const double min_sep;
  const double comfort;
  std::vector<Agent> agents;
};

// Poses the people along their ground paths into ground truth, one frame after the other.
class Animator {
 public:
  // Draws each person's gait phase from `rng` (in person order).
  Animator(std::vector<BodyShape> shapes, bool whole_body, double fps, double floor_z, Rng& rng)
      : shapes_(std::move(shapes)), whole_body_(whole_body), fps_(fps), floor_z_(floor_z), gaits_(shapes_.size()) {
    for (GaitState& gait : gaits_) gait.phase_rad = rng.Uniform(-std::numbers::pi, std::numbers::pi);
  }

  // The walking speed before the first frame: the step from frame 0 to frame 1 (sequences of
  // more than one frame).
  void SetInitialSpeeds(const std::vector<Vector2d>& frame0, const std::vector<Vector2d>& frame1) {
    for (size_t i = 0; i < gaits_.size(); ++i) gaits_[i].speed_mps = (frame1[i] - frame0[i]).norm() * fps_;
  }

  // Frame `frame` (0, 1, 2, ... in order) with the people at `position` facing `heading`.
  void Pose(int frame, const std::vector<Vector2d>& position, const std::vector<double>& heading, Poses3D* poses) {
    const double dt = 1.0 / fps_;
    poses->Clear(NumPosedJoints(whole_body_));
    for (size_t i = 0; i < gaits_.size(); ++i) {
      GaitState& gait = gaits_[i];
      if (frame > 0) {
        const double speed = (position[i] - gait.position_m).norm() * fps_;
        gait.speed_mps += (speed - gait.speed_mps) * std::min(1.0, dt / 0.25);
        AdvanceGaitPhase(dt, &gait);
      }
      gait.position_m = position[i];
      gait.heading_rad = heading[i];
      PoseJoints(shapes_[i], gait, whole_body_, &joints_);
      auto person = poses->AddPerson(static_cast<int>(i));
      person.topRows<3>() = joints_;
      person.row(2).array() += floor_z_;
      person.row(3).setOnes();
    }
  }

 private:
  std::vector<BodyShape> shapes_;
  bool whole_body_;
  double fps_;
  double floor_z_;
  std::vector<GaitState> gaits_;  // position_m: where the person was in the last posed frame
  Eigen::Matrix3Xd joints_;
};

// The checks SceneOptions and CrossingOptions share.
void CheckCommon(int num_people, int num_frames, double fps, const Eigen::Vector3d& room_size_m,
                 OptionsChecker* checker) {
  (*checker)("num_people", num_people, OptionSpec{.min = 0});
  (*checker)("num_frames", num_frames, OptionSpec{.min = 0});
  (*checker)("fps", fps, OptionSpec{.min = 0, .min_exclusive = true});
  constexpr double kMinWidth = 2.0 * kWallMargin + 0.2;
  if (!(room_size_m.x() > kMinWidth && room_size_m.y() > kMinWidth && room_size_m.z() >= 2.2)) {
    std::string problem = "'";
    problem.append(FormatOption(room_size_m)).append("' is too small (x and y must be above ");
    checker->Require(problem.append(FormatNumber(kMinWidth)).append(" m, z at least 2.2 m)"), "room_size_m");
  }
}

Scene MakeSceneShell(const RigOptions& rig, uint64_t seed, bool whole_body, const Eigen::Vector3d& center,
                     const Eigen::Vector3d& size, double fps) {
  Scene scene;
  scene.cameras = MakeCameraRig(rig, DeriveSeed(seed, 1));
  scene.joint_names = whole_body ? CocoWholeBodyJoints() : CocoBodyJoints();
  scene.room_center_m = center;
  scene.room_size_m = size;
  scene.fps = fps;
  return scene;
}

}  // namespace scene_internal

using namespace scene_internal;  // NOLINT(build/namespaces): this file's own helpers

struct SceneStream::State {
  State(const SceneOptions& options, std::vector<BodyShape> shapes, Rng& gait_rng)
      : walkers(options, DeriveSeed(options.seed, 3)),
        animator(std::move(shapes), options.whole_body, options.fps,
                 options.room_center_m.z() - 0.5 * options.room_size_m.z(), gait_rng) {}

  // The ground path of frame `next_frame` (positions, headings), and of the frame after it.
  void Load(std::vector<Vector2d>* position, std::vector<double>* heading) const {
    position->clear();
    heading->clear();
    for (const Agent& agent : walkers.Agents()) {
      position->push_back(agent.position);
      heading->push_back(agent.heading);
    }
  }

  Walkers walkers;
  Animator animator;
  std::vector<Vector2d> position, next_position;
  std::vector<double> heading, next_heading;
};

std::string SceneOptions::Check() const {
  OptionsChecker checker("scene");
  CheckCommon(num_people, num_frames, fps, room_size_m, &checker);
  checker("min_separation_m", min_separation_m, OptionSpec{.min = 0});
  return checker.error().empty() ? rig.Check() : checker.error();
}

std::string CrossingOptions::Check() const {
  OptionsChecker checker("crossing");
  CheckCommon(num_people, num_frames, fps, room_size_m, &checker);
  checker("lane_spacing_m", lane_spacing_m, OptionSpec{.min = 0});
  checker("speed_mps", speed_mps, OptionSpec{.min = 0, .min_exclusive = true});
  return checker.error().empty() ? rig.Check() : checker.error();
}

SceneStream::SceneStream(const SceneOptions& options) : num_frames_(options.num_frames) {
  ThrowIfInvalid(options);
  shell_ = MakeSceneShell(options.rig, options.seed, options.whole_body, options.room_center_m, options.room_size_m,
                          options.fps);
  Rng body_rng(DeriveSeed(options.seed, 2));
  std::vector<BodyShape> shapes;
  for (int i = 0; i < options.num_people; ++i) shapes.push_back(RandomBodyShape(body_rng));
  Rng gait_rng(DeriveSeed(options.seed, 4));
  state_ = std::make_unique<State>(options, std::move(shapes), gait_rng);
  state_->Load(&state_->position, &state_->heading);
  if (num_frames_ > 1) {
    state_->walkers.Step();
    state_->Load(&state_->next_position, &state_->next_heading);
    state_->animator.SetInitialSpeeds(state_->position, state_->next_position);
  }
}

SceneStream::~SceneStream() = default;
SceneStream::SceneStream(SceneStream&&) noexcept = default;
SceneStream& SceneStream::operator=(SceneStream&&) noexcept = default;

bool SceneStream::Next(Poses3D* gt) {
  if (next_frame_ >= num_frames_) return false;
  State& state = *state_;
  state.animator.Pose(next_frame_, state.position, state.heading, gt);
  ++next_frame_;
  if (next_frame_ < num_frames_) {
    std::swap(state.position, state.next_position);
    std::swap(state.heading, state.next_heading);
    if (next_frame_ + 1 < num_frames_) {
      state.walkers.Step();
      state.Load(&state.next_position, &state.next_heading);
    }
  }
  return true;
}

Scene GenerateScene(const SceneOptions& options) {
  SceneStream stream(options);
  Scene scene = stream.shell();
  scene.gt.resize(options.num_frames);
  for (Poses3D& gt : scene.gt) stream.Next(&gt);
  return scene;
}

Scene MakeCrossingScene(const CrossingOptions& options) {
  ThrowIfInvalid(options);
  Scene scene = MakeSceneShell(options.rig, options.seed, options.whole_body, options.room_center_m,
                               options.room_size_m, options.fps);
  Rng rng(DeriveSeed(options.seed, 5));
  std::vector<BodyShape> shapes;
  for (int i = 0; i < options.num_people; ++i) shapes.push_back(RandomBodyShape(rng));

  const Box2 walk = ShrunkRoom(options.room_center_m, options.room_size_m, kWallMargin);
  const double lane_angle = rng.Uniform(0.0, 2.0 * std::numbers::pi);
  const Vector2d along = Direction(lane_angle);
  const Vector2d across = Direction(lane_angle + 0.5 * std::numbers::pi);
  const Vector2d center = options.room_center_m.head<2>();
  const double meet_time = 0.5 * (options.num_frames - 1) / options.fps;
  std::vector<Path> paths(options.num_people);
  for (int i = 0; i < options.num_people; ++i) {
    const double direction = i % 2 == 0 ? 1.0 : -1.0;
    const double offset = (i - 0.5 * (options.num_people - 1)) * options.lane_spacing_m;
    const double speed = options.speed_mps * rng.Uniform(0.9, 1.1);
    const Vector2d lane_origin = center + offset * across;
    // Along-lane interval inside the walkable area.
    double s_lo = -1e9, s_hi = 1e9;
    for (int axis = 0; axis < 2; ++axis) {
      if (std::abs(along[axis]) < 1e-12) continue;
      double a = (walk.lo[axis] - lane_origin[axis]) / along[axis];
      double b = (walk.hi[axis] - lane_origin[axis]) / along[axis];
      if (a > b) std::swap(a, b);
      s_lo = std::max(s_lo, a);
      s_hi = std::min(s_hi, b);
    }
    if (!(s_lo <= 0.0 && s_hi >= 0.0)) throw ConfigError("crossing scene: lanes do not fit into the room");
    const double heading = lane_angle + (direction > 0 ? 0.0 : std::numbers::pi);
    for (int frame = 0; frame < options.num_frames; ++frame) {
      const double s = std::clamp(direction * speed * (frame / options.fps - meet_time), s_lo, s_hi);
      paths[i].position.push_back(lane_origin + s * along);
      paths[i].heading.push_back(heading);
    }
  }
  const double floor_z = options.room_center_m.z() - 0.5 * options.room_size_m.z();
  Animator animator(std::move(shapes), options.whole_body, options.fps, floor_z, rng);
  std::vector<Vector2d> position(options.num_people);
  std::vector<double> heading(options.num_people);
  const auto load = [&](int frame) {
    for (int i = 0; i < options.num_people; ++i) {
      position[i] = paths[i].position[frame];
      heading[i] = paths[i].heading[frame];
    }
  };
  if (options.num_frames > 1) {
    load(1);
    const std::vector<Vector2d> frame1 = position;
    load(0);
    animator.SetInitialSpeeds(position, frame1);
  }
  scene.gt.resize(options.num_frames);
  for (int frame = 0; frame < options.num_frames; ++frame) {
    load(frame);
    animator.Pose(frame, position, heading, &scene.gt[frame]);
  }
  return scene;
}

}  // namespace rpt::synthetic
