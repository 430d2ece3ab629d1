// SPDX-License-Identifier: MIT
#include "datasets/readers/detection_lines.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <unordered_map>
#include <utility>

#include "core/closest_name.h"
#include "core/errors.h"
#include "core/printable_text.h"
#include "core/text.h"
#include "core/utf8.h"
#include "core/pipeline/frame_size.h"
#include "datasets/detections.h"
#include "datasets/image_range_check.h"
#include "datasets/io/input_limits.h"
#include "datasets/io/json_pull.h"
#include "datasets/io/json_string_scanner.h"
#include "datasets/readers/generic_common.h"

namespace rpt {
namespace {

using Kind = io::JsonPull::Kind;

// Whether `c`, the next character of JSON text `strings` walks, counts: the blanks between tokens
// say nothing (those inside strings do).
bool Counts(io::JsonStringScanner* strings, char c) {
  return strings->InString(c) || (c != ' ' && c != '\t' && c != '\r' && c != '\n');
}

// `line` without the blanks JSON allows between tokens: how a writer happened to space it does
// not change what it says.
std::string WithoutJsonBlanks(std::string_view line) {
  std::string out;
  io::JsonStringScanner strings;
  for (const char c : line) {
    if (Counts(&strings, c)) out.push_back(c);
  }
  return out;
}

// Whether WithoutJsonBlanks(line) == `expected`, stopping at the first difference (a frame line
// differs from the joints line at its first key): no allocation.
bool EqualWithoutJsonBlanks(std::string_view line, std::string_view expected) {
  size_t k = 0;
  io::JsonStringScanner strings;
  for (const char c : line) {
    if (Counts(&strings, c) && (k >= expected.size() || expected[k++] != c)) return false;
  }
  return k == expected.size();
}

// Keys of the frame lines (or of their views) that are not read, counted per key like the generic
// readers' (a misspelt "Time" would otherwise drop its value silently): the first kMaxShownKeys
// keys by name, the others together. Allocates only for a key not seen before.
class KeyCounts {
 public:
  static constexpr std::size_t kMaxShownKeys = 5;
  static constexpr std::size_t kMaxKeyBytes = 40;

  explicit KeyCounts(std::vector<std::string> known) : known_(std::move(known)) {}

  // Returns true for the first unknown key (said as it happens by the live input).
  bool Count(std::string_view key) {
    for (auto& [name, count] : counts_) {
      if (name == key) {
        ++count;
        return false;
      }
    }
    const bool first = counts_.empty() && others_ == 0;
    if (counts_.size() < kMaxShownKeys) {
      counts_.emplace_back(std::string(key), 1);
    } else {
      ++others_;
    }
    return first;
  }

  // "<objects> with the unknown key 'k' (did you mean 'x'?), not read"
  std::string What(std::string_view key, const std::string& objects) const {
    return objects + " with the unknown key " + QuoteName(Utf8Excerpt(key, kMaxKeyBytes)) + DidYouMeanKey(key, known_) +
           ", not read";
  }

  void Report(const std::string& source, const std::string& objects, InputWarnings* warnings) const {
    for (const auto& [name, count] : counts_) warnings->AddUnused(source, What(name, objects), count);
    warnings->AddUnused(source, "other unknown keys in " + objects + " (not read)", others_);
  }

 private:
  std::vector<std::string> known_;
  std::vector<std::pair<std::string, long>> counts_;
  long others_ = 0;
};

// Camera names to calibration indices, looked up by a view of the line's text.
struct NameHash {
  using is_transparent = void;
  std::size_t operator()(std::string_view name) const { return std::hash<std::string_view>{}(name); }
};
using CameraIndex = std::unordered_map<std::string, int, NameHash, std::equal_to<>>;

class DetectionLineSource final : public FrameSource {
 public:
  DetectionLineSource(std::vector<Camera> cameras, std::unique_ptr<io::LineReader> lines,
                      const DetectionLinesOptions& options, const std::filesystem::path& calibration_file,
                      DetectionLinesCounts* counts)
      : lines_(std::move(lines)),
        source_(lines_->source()),
        calibration_file_(calibration_file.string()),
        skip_bad_lines_(options.skip_bad_lines),
        on_first_bad_line_(options.on_first_bad_line),
        on_early_warning_(options.on_early_warning),
        max_persons_per_view_(options.max_persons_per_view),
        max_pairs_per_frame_(options.max_pairs_per_frame),
        counts_(counts != nullptr ? counts : &own_counts_),
        frame_keys_({"id", "time", "views"}),
        view_keys_({"camera", "poses"}) {
    header_.name = options.name;
    header_.fps = options.fps;
    for (size_t c = 0; c < cameras.size(); ++c) {
      camera_idx_.emplace(cameras[c].name, static_cast<int>(c));
      camera_names_.push_back(cameras[c].name);
    }
    header_.cameras = std::move(cameras);
    image_range_.emplace(header_.cameras);
    ReadJointsLine();
    num_joints_ = static_cast<int>(header_.detection_joints.size());
    camera_seen_.assign(header_.cameras.size(), false);
    camera_named_.assign(header_.cameras.size(), 0);
  }

  const SequenceHeader& header() const override { return header_; }
  long num_frames() const override { return -1; }
  const InputWarnings& warnings() const override { return warnings_; }

  bool Pull(SequenceFrame* frame) override {
    if (ended_) return false;
    std::string_view line;
    while (true) {
      const io::LineReader::Result result = lines_->Next(&line);
      if (result == io::LineReader::Result::kEnd || result == io::LineReader::Result::kStopped) break;
      ++counts_->lines;
      try {
        if (result == io::LineReader::Result::kTooLong) {
          throw InputError("line longer than " + std::to_string(io::MaxInputBytes() >> 20) +
                           " MB (the limit of --max-input-mb)");
        }
        if (IsBlank(line)) continue;
        // The joints line again, as written the first time: the detector restarted (a supervisor's
        // loop). Its frame ids may start over: the window of recent ids starts anew; its times going
        // back end the tracks, as any step back does.
        if (EqualWithoutJsonBlanks(line, joints_line_)) {
          ++restarts_;
          num_recent_ = 0;
          continue;
        }
        ParseFrame(line, frame);
        if (const std::string problem =
                FrameSizeProblem(frame->views, header_.cameras, max_persons_per_view_, max_pairs_per_frame_);
            !problem.empty()) {
          throw InputError(problem);
        }
      } catch (const InputError& e) {
        const std::string message = source_ + ":" + std::to_string(lines_->line_number()) + ": " + e.what();
        if (!skip_bad_lines_) throw InputError(message);
        if (counts_->bad_lines++ == 0) {
          counts_->first_bad_line = message;
          if (on_first_bad_line_) on_first_bad_line_(message);
        }
        continue;
      }
      ++counts_->frames;
      counts_->frame_line_time = lines_->line_time();
      CheckImageRange(*frame);
      return true;
    }
    Finish();
    return false;
  }

 private:
  static bool IsBlank(std::string_view line) { return line.find_first_not_of(" \t\r") == std::string_view::npos; }

  // Line 1: {"joints": [names]}.
  void ReadJointsLine() {
    std::string_view line;
    io::LineReader::Result result = io::LineReader::Result::kEnd;
    do {
      result = lines_->Next(&line);
      if (result != io::LineReader::Result::kEnd && result != io::LineReader::Result::kStopped) ++counts_->lines;
    } while (result == io::LineReader::Result::kLine && IsBlank(line));
    const std::string where = source_ + ":" + std::to_string(std::max(1L, lines_->line_number()));
    if (result == io::LineReader::Result::kEnd || result == io::LineReader::Result::kStopped) {
      throw InputError(where + ": no joints line: the stream must start with {\"joints\": [names]}");
    }
    if (result == io::LineReader::Result::kTooLong) throw InputError(where + ": the joints line is too long");
    joints_line_ = WithoutJsonBlanks(line);
    try {
      json_.Reset(line);
      json_.BeginObject();
      std::string_view key;
      bool has_joints = false;
      while (json_.NextKey(&key)) {
        if (key != "joints") {
          if (key == "views" || key == "id" || key == "time") {
            json_.Fail("a frame before the joints line: the first line is {\"joints\": [names]}");
          }
          header_keys_.Count(key);
          json_.Skip();
          continue;
        }
        if (has_joints) json_.Fail("\"joints\" given twice");
        has_joints = true;
        if (json_.Peek() != Kind::kArray) throw InputError("/joints: expected a list of joint names");
        json_.BeginArray();
        while (json_.NextElement()) {
          if (json_.Peek() != Kind::kString) {
            throw InputError("/joints/" + std::to_string(header_.detection_joints.size()) +
                             ": expected a joint name (string)");
          }
          header_.detection_joints.emplace_back(json_.String());
        }
      }
      json_.End();
      if (!has_joints) throw InputError("/joints: missing: the first line is {\"joints\": [names]}");
      CheckJointNames(header_.detection_joints, "/joints");
    } catch (const InputError& e) {
      throw InputError(where + ": " + e.what());
    }
    header_keys_.Report(source_, "joints lines", &warnings_);
  }

  [[noreturn]] static void Fail(const std::string& pointer, const std::string& what) {
    throw InputError(pointer + ": " + what);
  }

  void ParseFrame(std::string_view line, SequenceFrame* frame) {
    frame->id.clear();
    frame->gt.Clear(0);
    frame->labels_2d.clear();
    frame->views.resize(header_.cameras.size());
    for (Poses2D& view : frame->views) view.Clear(num_joints_);
    std::fill(camera_seen_.begin(), camera_seen_.end(), false);
    bool has_id = false, has_time = false, has_views = false;
    double time_s = kUnknownTime;
    json_.Reset(line);
    json_.BeginObject();
    std::string_view key;
    while (json_.NextKey(&key)) {
      if (key == "id") {
        if (has_id) Fail("/id", "given twice");
        has_id = true;
        ParseId(frame);
      } else if (key == "time") {
        if (has_time) Fail("/time", "given twice");
        has_time = true;
        if (!json_.Null()) {
          if (json_.Peek() != Kind::kNumber) Fail("/time", "expected the time in seconds (a number) or null");
          time_s = json_.Number();
        }
      } else if (key == "views") {
        if (has_views) Fail("/views", "given twice");
        has_views = true;
        ParseViews(frame);
      } else if (key == "joints") {
        Fail("/joints", "a joints line after the first line that is not the first line again (a restarted writer "
                        "repeats it as it was): the joints are given once, on the first line");
      } else {
        if (frame_keys_.Count(key) && on_early_warning_) {
          on_early_warning_(source_ + ":" + std::to_string(lines_->line_number()) + ": " +
                            frame_keys_.What(key, "frame lines"));
        }
        json_.Skip();
      }
    }
    json_.End();
    if (!has_views) Fail("/views", "missing (write [] for a frame without detections)");
    // "views" lists the cameras processed for this frame: the others have no data (they neither
    // support nor contradict a person the listed ones see).
    for (size_t c = 0; c < frame->views.size(); ++c) frame->views[c].unavailable = !camera_seen_[c];
    if (!has_id) {
      char digits[24];
      const auto end = std::to_chars(digits, digits + sizeof(digits), lines_->line_number()).ptr;
      frame->id.assign(digits, end);
    }
    CheckRepeatedId(frame->id);
    if (!has_time && header_.fps > 0) time_s = static_cast<double>(counts_->frames) / header_.fps;
    if (std::isnan(time_s) && frames_without_time_++ == 0 && header_.fps <= 0 && on_early_warning_) {
      on_early_warning_(source_ + ":" + std::to_string(lines_->line_number()) +
                        ": a frame without a time, and no --fps: its time is unknown, so nothing is carried from "
                        "the frame before (no tracking, no smoothing); give each line a \"time\" (seconds) or "
                        "--fps");
    }
    frame->timestamp_s = time_s;
  }

  void ParseId(SequenceFrame* frame) {
    const Kind kind = json_.Peek();
    if (kind == Kind::kString) {
      const std::string_view id = json_.String();
      if (id.empty()) Fail("/id", "empty id");
      frame->id.assign(id);
      return;
    }
    if (kind == Kind::kNumber) {
      const std::string_view digits = json_.IntegerText();
      std::int64_t value = 0;
      if (!digits.empty() &&
          std::from_chars(digits.data(), digits.data() + digits.size(), value).ptr == digits.data() + digits.size()) {
        frame->id.assign(digits);
        return;
      }
    }
    Fail("/id", "expected a string or an integer id");
  }

  // A frame id also used by one of the last kRecentIds frames is an error (hashes in a ring).
  void CheckRepeatedId(const std::string& id) {
    const std::uint64_t hash = std::hash<std::string>{}(id);
    const std::size_t kept = std::min(num_recent_, kRecentIds);
    for (std::size_t i = 0; i < kept; ++i) {
      if (recent_ids_[i] == hash)
        Fail("/id", "frame id " + QuoteName(id) + " repeats one of the last " + std::to_string(kRecentIds) + " frames");
    }
    recent_ids_[num_recent_++ % kRecentIds] = hash;
  }

  static std::string ViewPointer(size_t v) { return "/views/" + std::to_string(v); }

  void ParseViews(SequenceFrame* frame) {
    if (json_.Peek() != Kind::kArray) Fail("/views", "expected a list of views");
    json_.BeginArray();
    size_t v = 0;
    for (; json_.NextElement(); ++v) {
      if (json_.Peek() != Kind::kObject) Fail(ViewPointer(v), "expected {\"camera\": ..., \"poses\": [...]}");
      json_.BeginObject();
      int camera = -1;
      bool has_poses = false;
      scratch_.Clear(num_joints_);
      std::string_view key;
      while (json_.NextKey(&key)) {
        if (key == "camera") {
          if (camera >= 0) Fail(ViewPointer(v) + "/camera", "given twice");
          if (json_.Peek() != Kind::kString) Fail(ViewPointer(v) + "/camera", "expected the camera's name (a string)");
          const std::string_view name = json_.String();
          const auto it = camera_idx_.find(name);
          if (it == camera_idx_.end()) {
            Fail(ViewPointer(v) + "/camera", "camera " + QuoteName(std::string(name)) + " is not in the calibration " +
                                                 calibration_file_ + " (cameras: " + Join(camera_names_, ", ") + ")");
          }
          camera = it->second;
          if (camera_seen_[camera])
            Fail(ViewPointer(v) + "/camera", "camera " + QuoteName(std::string(name)) + " appears twice in this frame");
          camera_seen_[camera] = true;
          camera_named_[camera] = 1;
        } else if (key == "poses") {
          if (has_poses) Fail(ViewPointer(v) + "/poses", "given twice");
          has_poses = true;
          ParsePoses(v);
        } else {
          view_keys_.Count(key);
          json_.Skip();
        }
      }
      if (camera < 0) Fail(ViewPointer(v) + "/camera", "missing");
      if (!has_poses) Fail(ViewPointer(v) + "/poses", "missing (write [] for no detections)");
      std::swap(frame->views[camera].data, scratch_.data);  // buffers rotate between views, none is freed
      origin_joints_ += ReadOriginJointsAsMissing(&frame->views[camera]);
    }
  }

  // One view's persons into scratch_: each exactly num_joints_ joints, [u, v, score] or null.
  void ParsePoses(size_t v) {
    const auto pointer = [&](size_t p) { return ViewPointer(v) + "/poses/" + std::to_string(p); };
    if (json_.Null()) return;
    if (json_.Peek() != Kind::kArray) Fail(ViewPointer(v) + "/poses", "expected a list of persons");
    json_.BeginArray();
    for (size_t p = 0; json_.NextElement(); ++p) {
      if (json_.Peek() != Kind::kArray)
        Fail(pointer(p), "expected a list of " + std::to_string(num_joints_) + " joints");
      json_.BeginArray();
      auto joints = scratch_.AddPerson();
      int j = 0;
      for (; json_.NextElement(); ++j) {
        if (j >= num_joints_) {
          Fail(pointer(p), "more than " + std::to_string(num_joints_) + " joints (as many as the joints line names)");
        }
        if (json_.Null()) continue;  // missing joint: score 0
        const auto joint_pointer = [&] { return pointer(p) + "/" + std::to_string(j); };
        if (json_.Peek() != Kind::kArray) Fail(joint_pointer(), "expected [x, y, score] or null");
        json_.BeginArray();
        int null_coordinates = 0;  // [null, null, 0]: a writer's NaN position of a missing joint
        for (int row = 0; row < 3; ++row) {
          if (!json_.NextElement()) Fail(joint_pointer(), "expected [x, y, score] or null");
          if (row < 2 && null_coordinates == row && json_.Null()) {
            ++null_coordinates;
            joints(row, j) = 0;
            continue;
          }
          if (json_.Peek() != Kind::kNumber) Fail(joint_pointer(), "expected [x, y, score] or null");
          joints(row, j) = json_.Number();
        }
        if (null_coordinates == 1 || (null_coordinates == 2 && joints(2, j) != 0))
          Fail(joint_pointer(), "expected [x, y, score] or null ([null, null, 0] for a missing joint)");
        if (json_.NextElement()) Fail(joint_pointer(), "expected [x, y, score] or null");
        joints(2, j) = AcceptScore(joints(2, j), source_, &warnings_, [&] { return joint_pointer(); });
      }
      if (j != num_joints_) {
        Fail(pointer(p), std::to_string(j) + " joints, expected " + std::to_string(num_joints_) +
                             " (as many as the joints line names)");
      }
    }
  }

  // The joints against each camera's image (ImageRangeCheck), as a file's are checked; what the
  // first kImageRangeFrames frames show is said at once (a stream in normalised coordinates or of
  // a resized image gives no persons or wrong ones, for hours), the counts again at the end.
  static constexpr long kImageRangeFrames = 100;
  void CheckImageRange(const SequenceFrame& frame) {
    for (size_t c = 0; c < frame.views.size(); ++c) image_range_->Add(static_cast<int>(c), frame.views[c]);
    if (counts_->frames != kImageRangeFrames || !on_early_warning_) return;
    InputWarnings early;
    image_range_->AddWarnings(source_ + " (the first " + std::to_string(kImageRangeFrames) + " frames)", &early);
    AddCamerasNeverNamed(source_ + " (the first " + std::to_string(kImageRangeFrames) + " frames)", &early);
    for (const InputWarning& warning : early.items()) on_early_warning_(warning.Line());
  }

  // The calibration's cameras no view line has named yet: nothing of theirs in any frame (a
  // detector that never started for one, a camera unplugged), as a file's reader says it.
  void AddCamerasNeverNamed(const std::string& source, InputWarnings* warnings) const {
    std::vector<std::string> never;
    for (size_t c = 0; c < camera_named_.size(); ++c) {
      if (!camera_named_[c]) never.push_back(header_.cameras[c].name);
    }
    if (counts_->frames == 0 || never.empty()) return;
    warnings->AddMissing(source,
                         "cameras of the calibration the detections never name, so nothing of theirs in any frame "
                         "(cameras " + Join(never, ", ") + "): triangulated from the others",
                         static_cast<long>(never.size()));
  }

  // The stream ended (or was stopped): what was skipped or not read goes into the warnings.
  void Finish() {
    ended_ = true;
    image_range_->AddWarnings(source_, &warnings_);
    if (counts_->bad_lines > 0) {
      warnings_.AddUnused(source_, "bad lines skipped (the first: " + counts_->first_bad_line + ")",
                          counts_->bad_lines);
    }
    if (restarts_ > 0) {
      warnings_.Add(source_,
                    "restarts of the writer (its joints line again): frame ids counted anew after each, tracks "
                    "ended at a time step back",
                    "", 0, restarts_);
    }
    AddCamerasNeverNamed(source_, &warnings_);
    frame_keys_.Report(source_, "frame lines", &warnings_);
    view_keys_.Report(source_, "views", &warnings_);
    warnings_.Add(source_, kOriginJointsRead, "", 0, origin_joints_);
    if (frames_without_time_ > 0) {
      warnings_.AddMissing(source_,
                           "frames without times: nothing is carried between them (no tracking, no smoothing); "
                           "give \"time\" in the lines or the rate with --fps",
                           frames_without_time_);
    }
  }

  std::unique_ptr<io::LineReader> lines_;
  std::string source_;
  std::string calibration_file_;
  bool skip_bad_lines_;
  std::function<void(const std::string&)> on_first_bad_line_;
  std::function<void(const std::string&)> on_early_warning_;
  int max_persons_per_view_;
  long long max_pairs_per_frame_;
  DetectionLinesCounts own_counts_;
  DetectionLinesCounts* counts_;
  SequenceHeader header_;
  InputWarnings warnings_;
  CameraIndex camera_idx_;
  std::vector<std::string> camera_names_;
  int num_joints_ = 0;
  io::JsonPull json_;
  Poses2D scratch_;
  std::vector<bool> camera_seen_;
  std::vector<char> camera_named_;  // per camera: named by a view of some frame so far
  std::array<std::uint64_t, kRecentIds> recent_ids_{};
  std::string joints_line_;  // the first line without JSON blanks: seen again, the writer restarted
  long restarts_ = 0;
  std::size_t num_recent_ = 0;
  long frames_without_time_ = 0;
  long origin_joints_ = 0;  // joints at pixel (0, 0) read as missing (ReadOriginJointsAsMissing)
  std::optional<ImageRangeCheck> image_range_;  // made once the cameras are in header_
  KeyCounts header_keys_{{"joints"}};
  KeyCounts frame_keys_;
  KeyCounts view_keys_;
  bool ended_ = false;
};

}  // namespace

std::unique_ptr<FrameSource> OpenDetectionLines(std::vector<Camera> cameras, std::unique_ptr<io::LineReader> lines,
                                                const DetectionLinesOptions& options,
                                                const std::filesystem::path& calibration_file,
                                                DetectionLinesCounts* counts) {
  return std::make_unique<DetectionLineSource>(std::move(cameras), std::move(lines), options, calibration_file, counts);
}

}  // namespace rpt
