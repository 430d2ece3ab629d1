// SPDX-License-Identifier: MIT
// rpt.Triangulator (core/pipeline/triangulator.h) and rpt.Predictions. process() triangulates one
// frame from numpy views; process_sequence() a whole sequence in C++ (an rpt.datasets.Sequence is
// read in place; a list of frames is converted up front), the GIL released while C++ works. Every
// frame from Python passes the CLI's validation (ValidateFrame: joint counts, finite values,
// scores in [0, 1]) before the triangulator sees it.
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <array>
#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <span>
#include <string>

#include "core/errors.h"
#include "core/pipeline/offline_smoother.h"
#include "core/pipeline/triangulator.h"
#include "core/printable_text.h"
#include "datasets/detections.h"
#include "datasets/input_warnings.h"
#include "datasets/readers/generic_common.h"
#include "engine/camera_agreement.h"
#include "engine/camera_sync_check.h"
#include "engine/config.h"
#include "engine/frame_time_check.h"
#include "engine/input.h"
#include "engine/run.h"
#include "engine/upright_check.h"
#include "metrics/step_counts.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/datasets_types.h"

namespace rpt::python {
namespace {

// Frame i of n as Python indexes a sequence (negative from the end); IndexError outside.
size_t FrameIndex(long i, size_t n) {
  const long count = static_cast<long>(n);
  if (i < 0) i += count;
  if (i < 0 || i >= count) throw py::index_error("frame index out of range");
  return static_cast<size_t>(i);
}

double TimeOf(py::handle timestamp) {
  if (timestamp.is_none()) return kUnknownTime;
  // True has __float__ (1.0): a flag passed where the time goes was taken as second 1.
  if (!py::hasattr(timestamp, "__float__") || py::isinstance<py::bool_>(timestamp) ||
      py::isinstance(timestamp, py::module_::import("numpy").attr("bool_"))) {  // numbers, numpy scalars
    throw py::type_error("timestamp: expected seconds (a number) or None, got " +
                         py::str(py::type::of(timestamp).attr("__name__")).cast<std::string>());
  }
  const double t = timestamp.attr("__float__")().cast<double>();
  // NaN too: a clock that fails now and then (a division by a zero frame rate) would turn tracking
  // off on those frames unseen; "unknown" is said with None.
  if (!std::isfinite(t)) {
    throw py::value_error("timestamp: must be finite seconds, or None (unknown); got " + std::string(std::isnan(t) ? "nan" : "inf"));
  }
  return t;
}

// (views, timestamp): a pair whose second item is a time (a number or None), not a second view.
// A pair whose first item is a list of views and whose second is no view (a string, a bool: a bad
// time) is one too, for TimeOf to name: it was read as a frame of two views ("2 views for 4 cameras").
bool IsViewsAndTime(py::handle item) {
  if (!py::isinstance<py::tuple>(item) || py::len(item) != 2) return false;
  const py::tuple pair = py::reinterpret_borrow<py::tuple>(item);
  const py::handle second = pair[1];
  if (second.is_none() || py::isinstance<py::float_>(second) || py::isinstance<py::int_>(second)) return true;
  const bool second_is_view =
      py::isinstance<py::array>(second) || py::isinstance<py::list>(second) || py::isinstance<py::tuple>(second);
  return !second_is_view && (py::isinstance<py::list>(pair[0]) || py::isinstance<py::tuple>(pair[0]));
}

// Scores a little above 1 (a detector's 1.02) are clamped to 1 and counted under `source`, as the
// file readers and the live input do (AcceptScore); other scores outside [0, 1] are left for
// ValidateFrame to refuse.
// Joints at exactly pixel (0, 0) with a score above 0 (what detectors write for a joint they did
// not find) are read as missing and counted, as the file readers and the live input do.
void CorrectDetectorOutput(const std::string& source, std::vector<Poses2D>* views, InputWarnings* warnings) {
  long origin = 0;
  for (Poses2D& view : *views) {
    for (size_t i = 2; i < view.data.size(); i += 3) {
      double& score = view.data[i];
      if (score > 1.0 && score <= kMaxScoreOvershoot) score = AcceptScoreSlow(score, source, warnings, source);
    }
    origin += ReadOriginJointsAsMissing(&view);
  }
  if (origin > 0) warnings->Add(source, kOriginJointsRead, "", 0, origin);
}

// predictions[i]: (persons, a read-only view kept alive by `owner`; track ids).
py::tuple FrameTuple(const Poses3D& persons, py::handle owner) {
  return py::make_tuple(PersonsView(persons, owner), TrackIdsArray(persons));
}

py::dict StatsDict(const FrameStats& stats) {
  py::dict steps;
  for (int s = 0; s < kNumSteps; ++s) {
    py::dict step;
    step["time_us"] = stats.time_us[static_cast<size_t>(s)];
    step["count"] = stats.count[static_cast<size_t>(s)];
    steps[py::str(std::string(kSteps[static_cast<size_t>(s)].key))] = step;
  }
  py::dict d;
  d["total_us"] = stats.total_us;
  d["steps"] = steps;
  // The extra counters under their names (the FrameStats members), from the one list of them.
  const std::array<int, metrics::kNumCounters> counters = metrics::Counters(stats);
  for (int c = 0; c < metrics::kNumCounters; ++c) d[py::str(std::string(metrics::kCounterNames[c]))] = counters[c];
  d["noise_m"] = stats.noise_m;
  return d;
}

// process_sequence looks for Ctrl-C every this many frames (a few milliseconds of work).
inline constexpr long kSignalCheckFrames = 32;

class PyTriangulator {
 public:
  PyTriangulator(std::vector<Camera> cameras, JointNames joints, const TriangulatorOptions& options, std::string name,
                 double fps)
      : triangulator_(cameras, joints, options), process_times_(options.track.max_gap_s) {
    header_.name = std::move(name);
    header_.cameras = std::move(cameras);
    header_.detection_joints = std::move(joints);
    header_.fps = fps;
  }

  py::tuple Process(py::handle views, py::handle timestamp) {
    std::unique_lock lock = Lock();
    if (triangulator_.options().smooth.mode == SmoothMode::kOffline && triangulator_.options().track.enabled) {
      throw ConfigError("smooth.mode=offline smooths whole sequences: use process_sequence, or smooth.mode=causal");
    }
    frame_.timestamp_s = TimeOf(timestamp);
    frame_.id = std::to_string(calls_);
    ViewsFromPython(views, num_cameras(), num_joints(), &frame_.views);
    InputWarnings clamped;  // allocates nothing unless a score is clamped
    CorrectDetectorOutput("Triangulator.process", &frame_.views, &clamped);
    if (!clamped.empty()) WarnInput(engine::InputWarningLines(clamped));
    ValidateFrame(header_, frame_, "Triangulator.process");
    {
      py::gil_scoped_release release;
      triangulator_.Process(frame_.views, frame_.timestamp_s, &persons_, &stats_);
    }
    WarnAboutProcessTimes();
    CheckCamerasOfProcess();
    ++calls_;
    return py::make_tuple(PersonsArray(persons_), TrackIdsArray(persons_));
  }

  // The frames of a loaded sequence, read in place.
  Predictions ProcessSequence(const Sequence& sequence, bool checks) {
    std::unique_lock lock = Lock();
    if (sequence.cameras.size() != header_.cameras.size() || sequence.detection_joints != header_.detection_joints) {
      throw InputError("process_sequence: sequence " + QuoteName(sequence.name) + " has " +
                       std::to_string(sequence.cameras.size()) + " cameras and " +
                       std::to_string(sequence.detection_joints.size()) +
                       " detection joints; the triangulator was made for " + std::to_string(header_.cameras.size()) +
                       " and " + std::to_string(header_.detection_joints.size()));
    }
    Predictions out = Begin(sequence.name, sequence.fps);
    InputWarnings warnings;
    std::vector<std::string> check_lines;
    {
      py::gil_scoped_release release;
      Run(sequence.frames, checks, &out, &warnings, &check_lines);
    }
    WarnInput(engine::InputWarningLines(warnings));
    WarnInput(check_lines);
    return out;
  }

  // Frames from Python: rpt.datasets.Frame objects, (views, timestamp) tuples or views alone,
  // converted and validated first, then triangulated in one go.
  Predictions ProcessFrames(const py::iterable& frames, bool checks) {
    std::unique_lock lock = Lock();
    std::vector<SequenceFrame> converted;
    InputWarnings clamped;
    for (py::handle item : frames) {
      SequenceFrame& frame = converted.emplace_back();
      const std::string where = "frames[" + std::to_string(converted.size() - 1) + "]";
      frame.id = std::to_string(converted.size() - 1);
      frame.timestamp_s = kUnknownTime;
      // The frame's errors of shape, type and time say which frame (only the value checks did).
      try {
        if (py::isinstance<Frame>(item)) {
          const Frame& f = item.cast<const Frame&>();
          frame.id = f.frame.id;
          frame.timestamp_s = f.frame.timestamp_s;
          frame.views = f.frame.views;
          if (frame.views.empty()) frame.views.resize(header_.cameras.size());
        } else if (IsViewsAndTime(item)) {
          const py::tuple pair = py::reinterpret_borrow<py::tuple>(item);
          frame.timestamp_s = TimeOf(pair[1]);
          ViewsFromPython(pair[0], num_cameras(), num_joints(), &frame.views);
        } else {
          ViewsFromPython(item, num_cameras(), num_joints(), &frame.views);
        }
      } catch (const py::value_error& e) {
        throw py::value_error("process_sequence: " + where + ": " + e.what());
      } catch (const py::type_error& e) {
        throw py::type_error("process_sequence: " + where + ": " + e.what());
      }
      CorrectDetectorOutput("process_sequence", &frame.views, &clamped);
      ValidateFrame(header_, frame, "process_sequence: " + where);
    }
    if (converted.empty()) throw py::value_error("process_sequence: no frames");
    Predictions out = Begin(header_.name, header_.fps);
    InputWarnings warnings = std::move(clamped);
    std::vector<std::string> check_lines;
    {
      py::gil_scoped_release release;
      Run(converted, checks, &out, &warnings, &check_lines);
    }
    WarnInput(engine::InputWarningLines(warnings));
    WarnInput(check_lines);
    return out;
  }

  void Reset() {
    std::unique_lock lock = Lock();
    triangulator_.Reset();
    calls_ = 0;
    process_times_ = engine::FrameTimeCheck(triangulator_.options().track.max_gap_s);
    process_agreement_.reset();
    warned_cameras_ = false;
  }

  const Triangulator& triangulator() const { return triangulator_; }
  // The last frame's statistics and provenance, read under the same one-call-at-a-time guard: a
  // second thread read them half-written while a run went on.
  py::dict StatsOfLastFrame() {
    std::unique_lock lock = Lock();
    return StatsDict(stats_);
  }
  py::array LastProvenance() {
    std::unique_lock lock = Lock();
    return ProvenanceArray(persons_);
  }

 private:
  int num_cameras() const { return static_cast<int>(header_.cameras.size()); }
  int num_joints() const { return static_cast<int>(header_.detection_joints.size()); }

  // One call at a time: a second thread gets an error instead of a data race (the GIL is released
  // while C++ works).
  std::unique_lock<std::mutex> Lock() {
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock.owns_lock()) throw py::value_error("Triangulator: in use by another thread (one call at a time)");
    return lock;
  }

  Predictions Begin(const std::string& name, double fps) const {
    Predictions out;
    out.sequence = name;
    out.fps = fps;
    out.cameras = num_cameras();
    out.joints = triangulator_.output_joints();
    return out;
  }

  // process(): the times seen so far, each of the two warnings given once as it happens
  // (rpt.InputWarning; until reset(): FrameTimeCheck::AddEarlyWarnings).
  void WarnAboutProcessTimes() {
    process_times_.Add(frame_.timestamp_s);
    InputWarnings warnings;  // empty: allocates nothing unless a warning is given
    process_times_.AddEarlyWarnings("Triangulator.process", header_.fps, &warnings);
    if (!warnings.empty()) WarnInput(engine::InputWarningLines(warnings));
  }

  // process(): the CLI's checks of the persons against each camera's detections (a camera whose
  // views were passed in another camera's place, engine/camera_agreement.h) and of which way is up
  // (engine/upright_check.h), over the calls so far; said once, after kCheckCalls calls (and again
  // at 10x that when nothing was said), until reset().
  static constexpr long kCheckCalls = 300;
  void CheckCamerasOfProcess() {
    if (warned_cameras_) return;
    if (!process_agreement_) {
      process_agreement_.emplace(header_, triangulator_.output_joints(), -1);
      process_upright_.emplace(triangulator_.output_joints());
    }
    process_agreement_->Add(calls_, frame_, persons_);
    process_upright_->Add(persons_);
    if (calls_ + 1 != kCheckCalls && calls_ + 1 != 10 * kCheckCalls) return;
    std::vector<std::string> lines = CheckLines("Triangulator.process", process_agreement_->cameras(),
                                                process_upright_->count());
    warned_cameras_ = !lines.empty();
    WarnInput(lines);
  }

  static std::vector<std::string> CheckLines(const std::string& source,
                                             const std::vector<engine::CameraAgreement>& cameras,
                                             const engine::UprightCount& upright) {
    std::vector<std::string> lines = engine::CameraAgreementWarnings(source, cameras);
    if (std::string line = engine::UprightWarning(source, upright); !line.empty()) lines.push_back(std::move(line));
    if (std::string line = engine::MirroredWarning(source, upright); !line.empty()) lines.push_back(std::move(line));
    if (std::string line = engine::SwappedHandsWarning(source, upright); !line.empty())
      lines.push_back(std::move(line));
    return lines;
  }

  // The loop of engine::Run's sequences (engine/run.cc, RunSequence): each frame triangulated in
  // order, through the offline smoother when smooth.mode = offline; the frame times' warnings
  // (engine::FrameTimeCheck) into *warnings; the lines of the CLI's checks of the persons against
  // the cameras (CheckLines) into *check_lines. Without `checks` those checks do not run: on a
  // shelf-like sequence they cost more than the triangulation (59.7 -> 153 us per frame of wall
  // time, python/benchmarks/process_overhead.py).
  void Run(std::span<const SequenceFrame> frames, bool checks, Predictions* out, InputWarnings* warnings,
           std::vector<std::string>* check_lines) {
    engine::FrameTimeCheck times(triangulator_.options().track.max_gap_s);
    engine::CameraAgreementCheck agreement(header_, triangulator_.output_joints(), static_cast<long>(frames.size()));
    engine::UprightCheck upright(triangulator_.output_joints());
    engine::CameraSyncCheck sync(header_, static_cast<long>(frames.size()), triangulator_.options().track.max_gap_s);
    long frames_with_time = 0;
    const auto start = std::chrono::steady_clock::now();
    const TriangulatorOptions& options = triangulator_.options();
    const bool offline = options.track.enabled && options.smooth.mode == SmoothMode::kOffline;
    OfflineSmoother smoother(options.smooth, options.track.max_gap_s, options.UnobservedScore());
    const std::vector<Poses2D> no_views(header_.cameras.size());
    out->frame_ids.reserve(frames.size());
    out->timestamps_s.reserve(frames.size());
    out->persons.reserve(frames.size());
    out->stats.reserve(frames.size());
    Poses3D smoothed;
    FrameStats smoothed_stats;
    long done = 0;
    for (const SequenceFrame& frame : frames) {
      // Ctrl-C (Jupyter's "interrupt kernel") waited for the whole sequence: Python's signal
      // handlers run every kSignalCheckFrames frames (the GIL is taken for it), and a
      // KeyboardInterrupt they raise ends the call.
      if (++done % kSignalCheckFrames == 0) {
        py::gil_scoped_acquire acquire;
        if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      }
      times.Add(frame.timestamp_s);
      frames_with_time += std::isfinite(frame.timestamp_s) ? 1 : 0;
      try {
        triangulator_.Process(frame.views.empty() ? no_views : frame.views, frame.timestamp_s, &persons_, &stats_);
      } catch (const InputError& e) {
        throw InputError(out->sequence + ": frame " + QuoteName(frame.id) + ": " + e.what());
      }
      if (checks) {
        agreement.Add(done - 1, frame, persons_);
        upright.Add(persons_);
        if (!frame.views.empty()) sync.Add(frame);
      }
      out->frame_ids.push_back(frame.id);
      out->timestamps_s.push_back(frame.timestamp_s);
      if (offline) {
        smoother.Push(frame.timestamp_s, persons_, persons_.num_persons() - stats_.coasting_tracks, stats_);
        while (smoother.Pop(&smoothed, &smoothed_stats)) {
          out->persons.push_back(smoothed);
          out->stats.push_back(smoothed_stats);
        }
      } else {
        out->persons.push_back(persons_);
        out->stats.push_back(stats_);
      }
      ++calls_;
    }
    if (offline) {
      smoother.Flush();
      while (smoother.Pop(&smoothed, &smoothed_stats)) {
        out->persons.push_back(smoothed);
        out->stats.push_back(smoothed_stats);
      }
    }
    out->wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    times.AddWarnings(out->sequence, out->fps, warnings);
    if (frames_with_time == 0 && frames.size() > 1 && options.track.enabled) {
      warnings->AddMissing(out->sequence,
                           "frames without a timestamp: nothing is carried between frames (no tracking, no "
                           "smoothing); pass (views, seconds) pairs",
                           static_cast<long>(frames.size()));
    }
    if (!checks) return;
    *check_lines = CheckLines(out->sequence, agreement.cameras(), upright.count());
    for (std::string& line : engine::CameraSyncWarnings(out->sequence, header_.cameras, sync.pairs(), sync.frame_step_s())) {
      check_lines->push_back(std::move(line));
    }
  }

  Triangulator triangulator_;
  SequenceHeader header_;  // cameras and joints, to validate frames as the CLI does
  std::mutex mutex_;
  SequenceFrame frame_;  // process(): the views of the frame, reused
  Poses3D persons_;
  FrameStats stats_;
  long calls_ = 0;
  engine::FrameTimeCheck process_times_;  // process()'s frames (WarnAboutProcessTimes)
  std::optional<engine::CameraAgreementCheck> process_agreement_;  // process()'s (CheckCamerasOfProcess)
  std::optional<engine::UprightCheck> process_upright_;
  bool warned_cameras_ = false;
};

std::vector<Camera> CamerasOf(py::handle cameras) {
  if (!py::isinstance<py::list>(cameras) && !py::isinstance<py::tuple>(cameras)) {
    throw py::type_error("cameras: expected a list of rpt.Camera");
  }
  std::vector<Camera> out;
  for (py::handle camera : cameras) {
    if (!py::isinstance<Camera>(camera)) throw py::type_error("cameras: expected a list of rpt.Camera");
    out.push_back(camera.cast<Camera>());
  }
  if (out.empty()) throw py::value_error("cameras: empty list");
  // As every calibration reader and cameras.save: a camera appended twice gave no persons, unsaid.
  for (size_t i = 0; i < out.size(); ++i) {
    for (size_t k = 0; k < i; ++k) {
      if (out[i].name != out[k].name) continue;
      throw InputError("cameras: camera name " + QuoteName(out[i].name) + " appears twice (cameras[" +
                       std::to_string(k) + "] and cameras[" + std::to_string(i) + "])");
    }
  }
  return out;
}

}  // namespace

void RegisterTriangulator(py::module_& m) {
  py::class_<Predictions>(m, "Predictions",
                          "3D persons of a sequence (Triangulator.process_sequence): per frame persons (P, J, 4), "
                          "track ids, provenance and step statistics")
      .def("__len__", [](const Predictions& p) { return p.persons.size(); })
      .def(
          "__getitem__",
          [](py::object self, long i) {
            const Predictions& p = self.cast<const Predictions&>();
            const Poses3D& persons = p.persons[FrameIndex(i, p.persons.size())];
            return FrameTuple(persons, self);
          },
          "(persons (P, J, 4), track ids (P,)) of frame i; persons is a read-only view of the stored result "
          "(no copy; .copy() to change it)")
      .def(
          "__getitem__",
          [](py::object self, const py::slice& slice) {
            const Predictions& p = self.cast<const Predictions&>();
            size_t start = 0, stop = 0, step = 0, length = 0;
            if (!slice.compute(p.persons.size(), &start, &stop, &step, &length)) throw py::error_already_set();
            py::list frames;
            for (size_t k = 0; k < length; ++k) {
              const Poses3D& persons = p.persons[start + k * step];
              frames.append(FrameTuple(persons, self));
            }
            return frames;
          },
          "predictions[a:b]: a list of the (persons, track ids) of those frames")
      .def_readwrite("sequence", &Predictions::sequence,
                     "the sequence's name (the detections file's for open_cameras): set it to tell takes apart in "
                     "export.write")
      .def_readonly("joint_names", &Predictions::joints)
      .def_readonly("frame_ids", &Predictions::frame_ids)
      .def_readonly("wall_seconds", &Predictions::wall_seconds, "the whole process_sequence call")
      .def_property_readonly(
          "timestamps",
          [](const Predictions& p) {
            py::array_t<double> a(static_cast<py::ssize_t>(p.timestamps_s.size()));
            std::copy(p.timestamps_s.begin(), p.timestamps_s.end(), a.mutable_data());
            return a;
          },
          "seconds per frame, NaN when unknown")
      .def(
          "provenance",
          [](py::object self, long i) {
            const Predictions& p = self.cast<const Predictions&>();
            return ProvenanceView(p.persons[FrameIndex(i, p.persons.size())], self);
          },
          py::arg("frame"),
          "(P, J) provenance codes of frame i (0 triangulated, 1 filled, 2 smoothed, 3 lifted, 4 predicted)")
      .def(
          "stats", [](const Predictions& p, long i) { return StatsDict(p.stats[FrameIndex(i, p.stats.size())]); },
          py::arg("frame"))
      .def_property_readonly(
          "frame_time_us",
          [](const Predictions& p) {
            py::array_t<double> a(static_cast<py::ssize_t>(p.stats.size()));
            for (size_t i = 0; i < p.stats.size(); ++i) a.mutable_at(static_cast<py::ssize_t>(i)) = p.stats[i].total_us;
            return a;
          },
          "the triangulator's time per frame (steady clock, microseconds)")
      .def("__repr__", [](const Predictions& p) {
        return "Predictions(" + QuoteName(p.sequence) + ", " + std::to_string(p.persons.size()) + " frames)";
      });

  py::class_<PyTriangulator>(m, "Triangulator",
                             "The triangulator (docs/algorithm.md): 2D detections of calibrated cameras in, 3D persons "
                             "with track ids out")
      .def(py::init([](py::handle cameras, const JointNames& joint_names, py::handle options) {
             const engine::Config config = ConfigOf(options);
             std::vector<Camera> list = CamerasOf(cameras);
             // As every file's joint names: an unknown name ('left_ear' for 'ear_left') would be
             // carried along unused, and the joints derived from it computed without it.
             CheckJointNames(joint_names, "rpt.Triangulator: joint_names");
             WarnInput(engine::ConfigWarnings(config));  // settings without effect, as the CLI says them
             py::gil_scoped_release release;
             return std::make_unique<PyTriangulator>(std::move(list), joint_names, config.triangulator, "python", 0.0);
           }),
           py::arg("cameras"), py::arg("joint_names"), py::arg("options") = py::none(),
           "cameras: list of rpt.Camera; joint_names: the joints of the detections, in order; options: None, a dict "
           "or rpt.Options")
      .def_static(
          "for_sequence",
          [](const SequenceHeader& sequence, py::handle options) {
            const engine::Config config = ConfigOf(options);
            py::gil_scoped_release release;
            return std::make_unique<PyTriangulator>(sequence.cameras, sequence.detection_joints,
                                                    engine::TriangulatorOptionsFor(config.triangulator, sequence),
                                                    sequence.name, sequence.fps);
          },
          py::arg("sequence"), py::arg("options") = py::none(),
          "The triangulator `rpt eval` runs on this sequence: its cameras and joints, its room unless "
          "room_check.size_m is set")
      .def("process", &PyTriangulator::Process, py::arg("views"), py::arg("timestamp") = py::none(),
           "views: per camera an array (persons, joints, 3) of u_px, v_px, score (or one array (cameras, persons, "
           "joints, 3)); timestamp: seconds, None = unknown. Returns (persons (P, J, 4): x, y, z in metres and "
           "score, track ids (P,))")
      .def("process_sequence", &PyTriangulator::ProcessSequence, py::arg("frames"), py::kw_only(),
           py::arg("checks") = true,
           "Every frame of an rpt.datasets.Sequence, in C++; returns rpt.Predictions. checks=False skips the "
           "checks of the persons against the cameras (agreement, upright, mirror, hands, camera sync), which "
           "cost more than the triangulation on small rigs")
      .def("process_sequence", &PyTriangulator::ProcessFrames, py::arg("frames"), py::kw_only(),
           py::arg("checks") = true,
           "Every frame of a list (rpt.datasets.Frame objects, (views, timestamp) tuples or views), converted first, "
           "then triangulated in C++; returns rpt.Predictions. checks=False as above")
      .def("reset", &PyTriangulator::Reset, "Forgets the previous frames (tracks, pre-filter, noise estimate)")
      .def_property_readonly("stats", &PyTriangulator::StatsOfLastFrame,
                             "the last frame's time and count per step, and the counters")
      .def_property_readonly("last_provenance", &PyTriangulator::LastProvenance,
                             "(P, J) provenance codes of the last process() call")
      .def_property_readonly("joint_names", [](const PyTriangulator& t) { return t.triangulator().input_joints(); })
      .def_property_readonly(
          "output_joint_names", [](const PyTriangulator& t) { return t.triangulator().output_joints(); },
          "the joints of the persons: the input joints, then the derived ones")
      .def_property_readonly("cameras", [](const PyTriangulator& t) { return t.triangulator().cameras(); })
      .def("__repr__", [](const PyTriangulator& t) {
        return "Triangulator(" + std::to_string(t.triangulator().cameras().size()) + " cameras, " +
               std::to_string(t.triangulator().input_joints().size()) + " joints)";
      });
}

}  // namespace rpt::python
