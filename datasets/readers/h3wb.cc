// SPDX-License-Identifier: MIT
#include "datasets/readers/h3wb.h"

#include <Eigen/Core>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <tuple>
#include <utility>

#include "core/errors.h"
#include "datasets/io/number_text.h"
#include "datasets/input_warnings.h"
#include "datasets/io/json_file.h"
#include "datasets/io/npy.h"
#include "datasets/readers/h36m_ego_common.h"
#include "datasets/readers/h3wb_internal.h"
#include "datasets/readers/human36m.h"
#include "datasets/readers/human36m_internal.h"
#include "core/printable_text.h"

namespace rpt {
namespace h3wb {

bool ActionMatches(const std::string& action, const std::vector<std::string>& filters) {
  if (filters.empty()) return true;
  for (const std::string& f : filters) {
    const std::string s = h36m_ego::SanitizeName(f);
    if (action == s) return true;
    // "Directions" selects "Directions-1" / "Directions 1" style sub-actions too.
    if (action.size() > s.size() + 1 && action.compare(0, s.size(), s) == 0 && action[s.size()] == '-' &&
        std::all_of(action.begin() + static_cast<std::ptrdiff_t>(s.size()) + 1, action.end(), [](char c) { return c >= '0' && c <= '9'; })) {
      return true;
    }
  }
  return false;
}

}  // namespace h3wb

namespace {

using h36m_ego::PathName;

using namespace h3wb;  // NOLINT: the reader's own internal namespace


std::optional<fs::path> FindAnnotationFile(const fs::path& root, const std::string& format, std::vector<fs::path>* tried) {
  if (fs::is_regular_file(root)) return root;
  const std::vector<fs::path> dirs = {root, root / "annotation_body3d", root / "datasets" / "json", root / "json"};
  std::vector<std::string> names;
  if (format != "json") names.push_back("h3wb_train.npz");
  if (format != "npz") {
    names.push_back("RGBto3D_train.json");
    names.push_back("2Dto3D_train.json");
  }
  for (const std::string& name : names) {
    for (const fs::path& dir : dirs) {
      tried->push_back(dir / name);
      if (fs::is_regular_file(dir / name)) return dir / name;
    }
  }
  return std::nullopt;
}

Options ParseH3wbOptions(const DatasetRequest& request) {
  const H3wbParams params = ParseDatasetParams<H3wbParams>("h3wb", request);
  Options o;
  o.root = request.root;
  const std::string format(EnumName(params.format));
  const std::string& file = params.file;
  if (file == "auto") {
    std::vector<fs::path> tried;
    const auto found = FindAnnotationFile(o.root, format, &tried);
    if (!found) {
      std::string list;
      for (const auto& p : tried) list += (list.empty() ? "" : ", ") + p.string();
      throw InputError(PathName(o.root) + ": no H3WB annotation file found (looked for " + list + "; or pass --param file=PATH)");
    }
    o.file = *found;
  } else {
    o.file = h36m_ego::ResolveUnder(o.root, file);
  }
  if (params.format == H3wbFormat::kAuto) {
    const std::string ext = o.file.extension().string();
    if (ext != ".npz" && ext != ".json") throw ConfigError("h3wb: cannot tell the format of " + QuoteName(o.file.string()) + " (pass --param format=json|npz)");
    o.npz = ext == ".npz";
  } else {
    o.npz = params.format == H3wbFormat::kNpz;
  }
  o.subjects = params.subjects;
  o.actions = params.actions;
  o.cameras_file = params.cameras_file;
  o.model = ToDistortionModel(params.distortion);
  o.global_units = std::string(EnumName(params.global_units));
  o.global_to_m = params.global_units == H3wbGlobalUnits::kMm ? 0.001 : 1.0;
  o.every = params.every;
  o.max_frames = params.max_frames;
  o.detections = params.detections == H3wbDetections::kAnnotations;
  return o;
}

std::string H3wbFrameId(const Clip& clip, long long number) {
  if (clip.sample_ids) return "h3wb_" + clip.subject + "_sample_" + h36m_ego::Padded(number, 6);
  return "h3wb_" + clip.subject + "_" + clip.action + "_" + h36m_ego::Padded(number, 6);
}

// ---------------------------------------------------------------------------------------
// npz "new format"

// Largest |frame_id| taken: 2^53 (up to it a double holds every integer exactly).
constexpr double kMaxFrameId = 9007199254740992.0;

// The numbers of a pose array shaped (N, [1, ...,] 133, dims), row-major, read one at a time from
// the array as the file stores it (a nested list is copied once).
class PoseValues {
 public:
  PoseValues() = default;
  explicit PoseValues(const io::PyView& view) : view_(view) {
    if (view.IsArray() && view.AsArray().dtype.IsRealNumeric()) {
      array_ = &view.AsArray();
    } else {
      copy_ = view.ToDoubles();
    }
  }
  bool empty() const { return array_ == nullptr && copy_.empty(); }
  const io::PyView& view() const { return view_; }
  double operator[](std::size_t index) const {
    return array_ != nullptr ? array_->ElementAsDouble(array_->StorageIndex(index)) : copy_[index];
  }

 private:
  io::PyView view_;
  const io::NdArray* array_ = nullptr;  // in view_
  std::vector<double> copy_;
};

// The pose array `view` after checking its shape (N, [1, ...,] 133, dims) and N = expected_rows
// (when >= 0); *rows = N.
PoseValues PoseArray(const io::PyView& view, std::int64_t expected_rows, std::int64_t dims, std::int64_t* rows) {
  const auto shape = view.Shape();
  bool ok = shape.size() >= 3 && shape[shape.size() - 2] == kJoints && shape.back() == dims;
  for (std::size_t i = 1; ok && i + 2 < shape.size(); ++i) ok = shape[i] == 1;
  if (!ok) view.Fail("expected shape (N, 133, " + std::to_string(dims) + ")");
  if (expected_rows >= 0 && shape[0] != expected_rows) {
    view.Fail("has " + std::to_string(shape[0]) + " rows, global_3d has " + std::to_string(expected_rows));
  }
  *rows = shape[0];
  return PoseValues(view);
}

Camera NpzCamera(const io::PyView& entry, const std::string& id, DistortionModel model, InputWarnings* warnings) {
  // File convention: K divided by 1000, R world->camera (float32), T = -R C in metres, Distortion
  // k1 k2 p1 p2 k3 (VERIFIED against metadata.xml for S5/60457274, datasets.md §7).
  const auto K = h36m_ego::FiniteNumbers(entry.Key("K"), 9);
  const auto R = h36m_ego::FiniteNumbers(entry.Key("R"), 9);
  const auto T = h36m_ego::FiniteNumbers(entry.Key("T"), 3);
  const auto d = h36m_ego::FiniteNumbers(entry.Key("Distortion"), 5);
  const Eigen::Matrix3d R_cw = AcceptRotation(Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(R.data()),
                                              entry.source(), entry.Key("R").Where(), warnings);
  const Eigen::Vector3d center_m = -R_cw.transpose() * Eigen::Vector3d(T[0], T[1], T[2]);
  Camera camera = h36m_ego::MakeH36mCamera(id, R_cw, center_m, K[0] * 1000.0, K[4] * 1000.0, K[2] * 1000.0, K[5] * 1000.0, d[0],
                                           d[1], d[4], d[2], d[3], model);
  h36m_ego::CheckCamera(camera, entry.Where());
  return camera;
}

std::string SubjectList(const io::PyView& dict) {
  std::string out;
  for (const auto& [k, v] : dict.Items()) out += (out.empty() ? "" : ", ") + (k.IsStr() ? k.AsStr() : io::Repr(k.value()));
  return out.empty() ? "none" : out;
}

std::vector<Clip> ReadNpzClips(const Options& options, bool want_2d) {
  const std::string source = PathName(options.file);
  const auto members = io::ReadNpz(options.file, {"train_data", "metadata"});
  auto member = [&](const std::string& name) -> io::PyView {
    const auto it = members.find(name);
    if (it == members.end()) throw InputError(source + ": no member '" + name + ".npy' (expected the H3WB npz format)");
    return it->second;
  };
  const io::PyView train = member("train_data");
  const io::PyView metadata = member("metadata");
  std::vector<Clip> out;
  for (const std::string& subject : options.subjects) {
    const auto actions = train.Find(subject);
    if (!actions) train.Fail("unknown subject " + QuoteName(subject) + " (file has " + SubjectList(train) + ")");
    const auto subject_meta = metadata.Find(subject);
    if (!subject_meta) metadata.Fail("unknown subject " + QuoteName(subject) + " (file has " + SubjectList(metadata) + ")");
    std::vector<Camera> cameras;
    InputWarnings camera_warnings;  // taken over by the subject's first clip
    for (const std::string& id : Human36mCameraIds()) {
      if (const auto entry = subject_meta->Find(id)) cameras.push_back(NpzCamera(*entry, id, options.model, &camera_warnings));
    }
    if (cameras.empty()) subject_meta->Fail("no camera entries (expected keys " + Human36mCameraIds().front() + ", ...)");
    bool any = false;
    for (const auto& [key, act] : actions->Items()) {
      const std::string action = h36m_ego::SanitizeName(key.AsStr());
      if (!ActionMatches(action, options.actions)) continue;
      any = true;
      Clip clip;
      clip.subject = subject;
      clip.action = action;
      clip.cameras = cameras;
      clip.source = source;
      clip.warnings = std::exchange(camera_warnings, InputWarnings{});
      std::int64_t n = 0;
      PoseValues global = PoseArray(act.Key("global_3d"), -1, 3, &n);
      const auto frame_ids = h36m_ego::FiniteNumbers(act.Key("frame_id"), static_cast<std::size_t>(n));
      std::vector<PoseValues> camera_3d(cameras.size()), pose_2d(cameras.size());
      for (std::size_t c = 0; c < cameras.size(); ++c) {
        const auto entry = act.Find(cameras[c].name);
        if (!entry) continue;
        std::int64_t rows = 0;
        camera_3d[c] = PoseArray(entry->Key("camera_3d"), n, 3, &rows);
        if (want_2d && entry->Has("pose_2d")) pose_2d[c] = PoseArray(entry->Key("pose_2d"), n, 2, &rows);
      }
      std::vector<std::size_t> order(static_cast<std::size_t>(n));
      for (std::size_t i = 0; i < order.size(); ++i) {
        if (frame_ids[i] != std::floor(frame_ids[i])) {
          act.Key("frame_id").Fail("element " + std::to_string(i) + " is not an integer");
        }
        // Beyond 2^53 a double no longer holds every integer, and converting one beyond the range of
        // long long (e.g. an int64 9223372036854775807 read as a double) is undefined behaviour.
        if (std::abs(frame_ids[i]) > kMaxFrameId) {
          std::ostringstream value;
          value << std::setprecision(17) << frame_ids[i];
          act.Key("frame_id").Fail("element " + std::to_string(i) + " is " + value.str() + ", out of range (|frame_id| <= 2^53)");
        }
        order[i] = i;
      }
      std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return frame_ids[a] < frame_ids[b]; });
      std::vector<std::size_t> selected_rows;
      for (const std::size_t k : h36m_ego::SelectFrames(order.size(), options.every, options.max_frames)) {
        selected_rows.push_back(order[k]);
        clip.numbers.push_back(static_cast<long long>(frame_ids[order[k]]));
      }
      clip.convert = [global = std::move(global), camera_3d = std::move(camera_3d), pose_2d = std::move(pose_2d),
                      selected_rows, numbers = clip.numbers, cameras, source, subject, key = key.AsStr(),
                      global_to_m = options.global_to_m, global_units = options.global_units,
                      want_2d](std::size_t i, Eigen::Matrix3Xd* world_m,
                               std::vector<std::optional<Eigen::Matrix2Xd>>* views_2d) {
        const std::size_t row = selected_rows[i];
        world_m->resize(3, kJoints);
        for (int j = 0; j < kJoints; ++j) {
          for (int d = 0; d < 3; ++d)
            (*world_m)(d, j) = global[(row * kJoints + static_cast<std::size_t>(j)) * 3 + static_cast<std::size_t>(d)];
        }
        if (!world_m->allFinite()) global.view().Fail("row " + std::to_string(row) + ": NaN or infinite coordinate");
        const Eigen::Matrix3Xd global_raw = *world_m;
        *world_m *= global_to_m;
        views_2d->assign(cameras.size(), std::nullopt);
        for (std::size_t c = 0; c < cameras.size(); ++c) {
          if (camera_3d[c].empty()) continue;
          // global_3d and camera_3d must describe the same pose: R X + t = camera_3d / 1000.
          double deviation = 0, deviation_other_units = 0;
          for (int j = 0; j < kJoints; ++j) {
            const std::size_t at = (row * kJoints + static_cast<std::size_t>(j)) * 3;
            const Eigen::Vector3d x_cam_m(camera_3d[c][at] / 1000.0, camera_3d[c][at + 1] / 1000.0,
                                          camera_3d[c][at + 2] / 1000.0);
            if (!x_cam_m.allFinite())
              camera_3d[c].view().Fail("row " + std::to_string(row) + ": NaN or infinite coordinate");
            const Camera& cam = cameras[c];
            deviation = std::max(deviation, (cam.R * world_m->col(j) + cam.t - x_cam_m).norm());
            const double other_scale = global_to_m == 1.0 ? 0.001 : 1.0;
            deviation_other_units = std::max(deviation_other_units, (cam.R * global_raw.col(j) * other_scale + cam.t - x_cam_m).norm());
          }
          if (!(deviation <= h36m_ego::kViewAgreementToleranceM)) {
            std::ostringstream msg;
            msg << source << ": " << subject << "/" << key << " frame_id " << numbers[i] << ": global_3d (read as "
                << global_units << ") and camera " << cameras[c].name << "'s camera_3d differ by " << deviation * 1000.0
                << " mm";
            if (deviation_other_units <= h36m_ego::kViewAgreementToleranceM) {
              msg << "; global_3d looks like "
                  << (global_units == "mm" ? "metres: pass --param global_units=m"
                                           : "millimetres: pass --param global_units=mm");
            }
            throw InputError(msg.str());
          }
          if (want_2d && !pose_2d[c].empty()) {
            Eigen::Matrix2Xd uv(2, kJoints);
            for (int j = 0; j < kJoints; ++j) {
              const std::size_t at = (row * kJoints + static_cast<std::size_t>(j)) * 2;
              uv.col(j) << pose_2d[c][at], pose_2d[c][at + 1];
            }
            (*views_2d)[c] = uv;
          }
        }
      };
      out.push_back(std::move(clip));
    }
    if (!any) actions->Fail("no action selected for subject " + subject);
  }
  return out;
}

std::vector<Clip> ReadClips(const Options& options, bool want_2d) {
  return options.npz ? ReadNpzClips(options, want_2d) : ReadJsonClips(options, want_2d);
}

// The stored 2D of camera c as one person with score 1 (no person when the view has none).
Poses2D View2D(const Clip& clip, const std::optional<Eigen::Matrix2Xd>& pose_2d, std::size_t c,
               const std::string& frame_id) {
  Poses2D view;
  view.Clear(kJoints);
  if (!pose_2d) return view;
  const Eigen::Matrix2Xd& uv = *pose_2d;
  if (!uv.allFinite()) throw InputError(clip.source + ": frame " + frame_id + " camera " + clip.cameras[c].name + ": NaN in the 2D pose");
  auto person = view.AddPerson();
  person.topRows<2>() = uv;
  person.row(2).setOnes();
  return view;
}

}  // namespace

std::string H3wbParams::Check() const {
  return subjects.empty() ? dataset_params::ParamKey("h3wb", "subjects") + ": no subject given" : std::string();
}

DatasetInfo H3wbInfo() {
  DatasetInfo info;
  info.name = "h3wb";
  info.description = "H3WB: Human3.6M 3D WholeBody (133 joints), npz new format or json with H36M cameras";
  info.layout =
      "<root>/h3wb_train.npz (or annotation_body3d/h3wb_train.npz)     npz new format (train_data, metadata)\n"
      "<root>/RGBto3D_train.json | 2Dto3D_train.json (or datasets/json/) json format, plus\n"
      "<root>/metadata.xml or <root>/cameras.pkl                          Human3.6M cameras for json\n"
      "root may also be the annotation file itself";
  info.params = DescribeDatasetParams<H3wbParams>();
  info.frame_id_prefix = "h3wb_";  // H3wbFrameId
  return info;
}

std::vector<std::unique_ptr<FrameSource>> OpenH3wb(const DatasetRequest& request) {
  if (!request.ground_truth) {
    throw ConfigError(
        "h3wb: frames and views are assembled from the 3D annotations (the stored 2D is in the same "
        "file): the reader cannot run without its ground truth");
  }
  const Options options = ParseH3wbOptions(request);
  std::vector<std::unique_ptr<FrameSource>> out;
  for (Clip& clip : ReadClips(options, options.detections)) {
    SequenceHeader header;
    header.name = "h3wb/" + clip.subject + "/" + clip.action;
    header.cameras = clip.cameras;
    header.gt_joints = CocoWholeBodyJoints();
    if (options.detections) header.detection_joints = CocoWholeBodyJoints();
    // Frames grouped by sample id are samples of the videos in no known order: their times are
    // unknown (counted), not sample id / 4 / 50.
    header.fps = clip.sample_ids ? 0 : kFps;
    const std::size_t count = clip.numbers.size();
    InputWarnings warnings = std::move(clip.warnings);
    if (clip.sample_ids) {
      warnings.AddMissing(clip.source,
                          "frames grouped by sample id (no image paths): their times are unknown, so nothing is "
                          "carried from one frame to the next",
                          static_cast<long>(count));
    }
    auto shared_clip = std::make_shared<const Clip>(std::move(clip));
    auto convert = [shared_clip, detections = options.detections](std::size_t i, SequenceFrame* frame, InputWarnings*) {
      const Clip& clip = *shared_clip;
      Eigen::Matrix3Xd world_m;
      std::vector<std::optional<Eigen::Matrix2Xd>> pose_2d;
      clip.convert(i, &world_m, &pose_2d);
      const long long number = clip.numbers[i];
      frame->id = H3wbFrameId(clip, number);
      if (detections) {
        for (std::size_t c = 0; c < clip.cameras.size(); ++c)
          frame->views.push_back(View2D(clip, pose_2d[c], c, frame->id));
      }
      frame->timestamp_s = clip.sample_ids ? kUnknownTime : static_cast<double>(number) / kFps;
      frame->gt.Clear(kJoints);
      auto person = frame->gt.AddPerson(0);
      person.topRows<3>() = world_m;
      person.row(3).setOnes();
    };
    out.push_back(
        std::make_unique<IndexedFrameSource>(std::move(header), count, std::move(convert), std::move(warnings)));
  }
  return out;
}

}  // namespace rpt
