// SPDX-License-Identifier: MIT
#include "datasets/readers/generic_labels.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <new>
#include <memory>
#include <optional>
#include <unordered_map>
#include <unordered_set>

#include "core/errors.h"
#include "core/options_check.h"
#include "core/printable_text.h"
#include "datasets/calibration/camera_json.h"
#include "datasets/input_warnings.h"
#include "datasets/io/binary.h"
#include "datasets/io/json_file.h"
#include "datasets/io/json_output.h"
#include "datasets/io/text_file.h"
#include "datasets/readers/detections_file.h"
#include "datasets/readers/generic_common.h"
#include "datasets/readers/generic_internal.h"

namespace rpt {
namespace {

using generic_internal::Fail;
using generic_internal::IdString;
using generic_internal::Source;
using nlohmann::json;

// The one warning of a file whose labels have neither "timestamp" nor "fps" (count = the labels).
constexpr const char* kUnknownTimesWarning =
    "labels without \"timestamp\" or \"fps\": their times are unknown, so nothing is carried from one frame to the "
    "next (no tracking, no speed limits); give each label a \"timestamp\", each scene an \"fps\", or the frame rate "
    "as --param fps=N";

bool Near(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)}); }

template <typename M>
bool NearAll(const M& a, const M& b) {
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    if (!Near(a.data()[i], b.data()[i])) return false;
  }
  return true;
}

// Empty when equal, else what differs.
std::string CameraDifference(const std::vector<Camera>& a, const std::vector<Camera>& b) {
  if (a.size() != b.size()) return std::to_string(a.size()) + " vs " + std::to_string(b.size()) + " cameras";
  for (size_t c = 0; c < a.size(); ++c) {
    const Camera& x = a[c];
    const Camera& y = b[c];
    const std::string where = "camera " + std::to_string(c) + " (" + QuoteName(x.name) + ")";
    if (x.name != y.name) return "camera " + std::to_string(c) + " is " + QuoteName(x.name) + " vs " + QuoteName(y.name);
    if (x.width != y.width || x.height != y.height) return where + ": image size differs";
    if (x.model != y.model) return where + ": distortion model differs";
    if (!NearAll(x.K, y.K)) return where + ": K differs";
    if (!NearAll(x.R, y.R)) return where + ": R differs";
    if (!NearAll(x.t, y.t)) return where + ": T differs";
    for (size_t i = 0; i < 5; ++i) {
      if (!Near(x.dist[i], y.dist[i])) return where + ": DC differs";
    }
  }
  return "";
}

JointNames ParseJointNames(const json& root, const std::string& pointer, const std::string& source) {
  const json& j = io::JsonAt(root, pointer, source);
  if (!j.is_array()) Fail(source, pointer, "expected a list of joint names, got " + std::string(j.type_name()));
  JointNames names;
  for (size_t i = 0; i < j.size(); ++i) {
    if (!j[i].is_string()) Fail(source, io::JsonPointerJoin(pointer, i), "expected a joint name (string)");
    names.push_back(j[i].get<std::string>());
  }
  CheckJointNames(names, source + ": " + pointer);
  return names;
}

// bodies3D: persons x joints x [x, y, z, visibility] (or [x, y, z]: visibility 1).
void ParseBodies(const json& root, const std::string& pointer, const std::string& source, int num_joints,
                 Poses3D* poses) {
  poses->Clear(num_joints);
  const json* bodies = io::JsonFind(root, pointer);
  if (!bodies || bodies->is_null()) return;
  if (!bodies->is_array()) Fail(source, pointer, "expected a list of persons, got " + std::string(bodies->type_name()));
  for (size_t p = 0; p < bodies->size(); ++p) {
    const json& person = (*bodies)[p];
    const std::string person_pointer = io::JsonPointerJoin(pointer, p);
    if (!person.is_array() || static_cast<int>(person.size()) != num_joints) {
      Fail(source, person_pointer,
           "expected " + std::to_string(num_joints) + " joints (as many as \"joints\" names), got " +
               (person.is_array() ? std::to_string(person.size()) : std::string(person.type_name())));
    }
    auto joints = poses->AddPerson();
    for (int j = 0; j < num_joints; ++j) {
      const json& joint = person[j];
      const size_t n = joint.is_array() ? joint.size() : 0;
      if (n != 4 && n != 3) {
        Fail(source, io::JsonPointerJoin(person_pointer, j), "expected [x, y, z, visibility]");
      }
      for (size_t k = 0; k < n; ++k) {
        if (!joint[k].is_number()) Fail(source, io::JsonPointerJoin(person_pointer, j), "expected numbers");
        const double v = joint[k].get<double>();
        if (!std::isfinite(v)) Fail(source, io::JsonPointerJoin(person_pointer, j), "value is not finite");
        joints(static_cast<Eigen::Index>(k), j) = v;
      }
      if (n == 3) joints(3, j) = 1.0;
    }
  }
}

std::string GroupKey(const json& label) {
  for (const char* key : {"scene", "seq"}) {
    const auto it = label.find(key);
    if (it == label.end() || it->is_null()) continue;
    return it->is_string() ? it->get<std::string>() : it->dump();
  }
  return "";
}

bool InSplit(const json& root, const std::string& pointer, const std::string& source, const std::string& split) {
  const json* splits = io::JsonFind(root, pointer + "/splits");
  if (!splits || splits->is_null()) return false;
  // A bare string ("splits": "test") is refused rather than guessed at: a list is what the format
  // documents, and a typo elsewhere in the type would otherwise drop labels silently.
  if (!splits->is_array()) {
    Fail(source, pointer + "/splits", "expected a list of split names (e.g. [\"test\"]), got " + std::string(splits->type_name()));
  }
  for (size_t k = 0; k < splits->size(); ++k) {
    if (!(*splits)[k].is_string()) {
      Fail(source, io::JsonPointerJoin(pointer + "/splits", k), "expected a split name, got " + std::string((*splits)[k].type_name()));
    }
  }
  return std::any_of(splits->begin(), splits->end(), [&](const json& s) { return s.get<std::string>() == split; });
}

// Every key a label may hold: what the reader reads, and what the skelda format holds that it does not need.
std::vector<std::string> KnownLabelKeys() {
  return {"id", "cameras", "joints", "bodies3D", "scene", "seq", "timestamp", "fps", "bodyids", "splits",
          "room_center", "room_size", "imgpaths", "subject", "action"};
}

// One label of a sequence: where it is in the file's text and its time (when known at opening).
struct LabelRef {
  std::size_t begin = 0;  // byte range of the label in the text
  std::size_t end = 0;
  std::size_t index = 0;  // position in the file's list (its JSON pointer "/<index>")
  double timestamp_s = 0;
};

// What the opening pass learns about one sequence ("scene"/"seq" group).
struct SequenceBuild {
  SequenceHeader header;
  InputWarnings warnings;
  std::string first_label_id;
  json first_cameras;  // raw JSON of the first label's cameras (fast equality check)
  json first_joints;
  int label_count = 0;                 // labels of this group seen so far (incl. other splits)
  std::vector<LabelRef> labels;        // the kept labels
  std::vector<int> frame_index;        // per kept label: its index among all labels of the group
  std::vector<bool> has_timestamp;
  std::optional<double> fps;
  bool room_set = false;
  generic_internal::UnknownKeys unknown_keys{KnownLabelKeys()};
};

// The file's text, which every sequence of the file converts its labels from.
struct LabelsText {
  std::string source;
  std::vector<std::uint8_t> bytes;
  std::string_view text() const { return {reinterpret_cast<const char*>(bytes.data()), bytes.size()}; }
  // Label `ref` as the document {"<index>": label}, so that the JSON pointers of messages are
  // those of the whole file ("/<index>/bodies3D/...").
  json Parse(const LabelRef& ref) const {
    json root = json::object();
    root[std::to_string(ref.index)] = io::ParseJsonText(text().substr(ref.begin, ref.end - ref.begin), source);
    return root;
  }
};

// The ground truth (and track ids) of one label.
void ConvertLabel(const json& root, const std::string& pointer, const std::string& source, int num_joints,
                  Poses3D* gt) {
  ParseBodies(root, pointer + "/bodies3D", source, num_joints, gt);
  if (const json* ids = io::JsonFind(root, pointer + "/bodyids"); ids && !ids->is_null()) {
    if (!ids->is_array() || static_cast<int>(ids->size()) != gt->num_persons()) {
      Fail(source, pointer + "/bodyids",
           "expected one id per person of bodies3D (" + std::to_string(gt->num_persons()) + ")");
    }
    for (size_t p = 0; p < ids->size(); ++p) {
      const std::string id_pointer = io::JsonPointerJoin(pointer + "/bodyids", p);
      const int body_id =
          static_cast<int>(io::JsonIntIn(root, id_pointer, source, -1, std::numeric_limits<int>::max()));
      // Ids name persons across frames (tracking metrics): two persons of one frame cannot share one.
      for (size_t q = 0; q < p && body_id >= 0; ++q) {
        if (gt->track_ids[q] == body_id) {
          Fail(source, id_pointer,
               "body id " + std::to_string(body_id) + " is also the id of person " + std::to_string(q));
        }
      }
      gt->track_ids[p] = body_id;
    }
  }
}

}  // namespace

std::string LabelsOptions::Check() const { return CheckOptionRanges("generic", *this); }

std::vector<std::unique_ptr<FrameSource>> OpenLabels(const std::filesystem::path& path, const LabelsOptions& options,
                                                     bool ground_truth) {
  ThrowIfInvalid(options);
  auto file = std::make_shared<LabelsText>();
  file->source = Source(path);
  file->bytes = io::detail::ReadFileBytes(path);
  const std::string& source = file->source;
  io::CheckJsonText(file->text(), source);
  const auto elements = [&] {
    try {
      return io::JsonArrayElements(file->text());
    } catch (const std::bad_alloc&) {  // 16 bytes per element: a list of millions of numbers
      throw InputError(source + ": out of memory listing the labels of " + std::to_string(file->text().size() >> 20) +
                       " MB of JSON");
    }
  }();
  if (!elements)
    Fail(source, "/",
         "expected a list of labels, got " + std::string(io::ParseJsonText(file->text(), source).type_name()));

  // The opening pass: every label is parsed once for what the sequences' headers and times need
  // (groups, ids, cameras, joints, times, rooms); its persons are converted when it is pulled.
  std::vector<SequenceBuild> builds;
  std::map<std::string, size_t> build_of_key;
  std::unordered_map<std::string, size_t> label_of_id;
  for (size_t i = 0; i < elements->size(); ++i) {
    const LabelRef ref{(*elements)[i].first, (*elements)[i].second, i};
    const json root = file->Parse(ref);
    const std::string pointer = "/" + std::to_string(i);
    const json& label = root.begin().value();
    if (!label.is_object()) Fail(source, pointer, "expected a label object, got " + std::string(label.type_name()));
    const std::string key = GroupKey(label);
    auto [it, inserted] = build_of_key.emplace(key, builds.size());
    if (inserted) {
      builds.emplace_back();
      builds.back().header.name = key.empty() ? path.stem().string() : key;
    }
    SequenceBuild& build = builds[it->second];
    const int index_in_group = build.label_count++;
    build.unknown_keys.Count(label);
    if (!options.split.empty() && !InSplit(root, pointer, source, options.split)) continue;

    const std::string id = IdString(root, pointer + "/id", source);
    if (const auto [seen, fresh] = label_of_id.emplace(id, i); !fresh) {
      Fail(source, pointer + "/id", "id " + QuoteName(id) + " is also used by label " + std::to_string(seen->second));
    }
    SequenceHeader& header = build.header;
    const json& cameras = io::JsonAt(root, pointer + "/cameras", source);
    if (build.first_label_id.empty()) {
      build.first_label_id = id;
      header.cameras = camera_json::ParseCameras(root, pointer + "/cameras", source, &build.warnings);
      build.first_cameras = cameras;
      if (ground_truth) {
        header.gt_joints = ParseJointNames(root, pointer + "/joints", source);
        build.first_joints = io::JsonAt(root, pointer + "/joints", source);
      }
    } else {
      if (cameras != build.first_cameras) {
        // Only compared with the first label's cameras (which were counted), so not counted again.
        const std::string difference =
            CameraDifference(header.cameras, camera_json::ParseCameras(root, pointer + "/cameras", source, nullptr));
        if (!difference.empty()) {
          throw InputError(source + ": labels " + QuoteName(build.first_label_id) + " and " + QuoteName(id) + " (" + pointer +
                           ") of sequence " + QuoteName(header.name) + " have different cameras (" + difference +
                           "); give them different \"scene\" values");
        }
      }
      if (ground_truth) {
        const json& joints = io::JsonAt(root, pointer + "/joints", source);
        if (joints != build.first_joints && ParseJointNames(root, pointer + "/joints", source) != header.gt_joints) {
          throw InputError(source + ": labels " + QuoteName(build.first_label_id) + " and " + QuoteName(id) + " (" + pointer +
                           ") of sequence " + QuoteName(header.name) + " have different \"joints\"");
        }
      }
    }

    LabelRef& kept = build.labels.emplace_back(ref);
    const json* timestamp = io::JsonFind(root, pointer + "/timestamp");
    build.has_timestamp.push_back(timestamp && !timestamp->is_null());
    if (build.has_timestamp.back()) {
      kept.timestamp_s = io::JsonNumber(root, pointer + "/timestamp", source);
      if (!std::isfinite(kept.timestamp_s)) Fail(source, pointer + "/timestamp", "not finite");
      // Tracking and smoothing take the time between frames from here: it must move forward.
      if (build.labels.size() >= 2 && build.has_timestamp[build.has_timestamp.size() - 2]) {
        const LabelRef& previous = build.labels[build.labels.size() - 2];
        if (!(kept.timestamp_s > previous.timestamp_s)) {
          Fail(source, pointer + "/timestamp",
               "timestamp " + json(kept.timestamp_s).dump() + " does not increase (the previous label of sequence '" +
                   header.name + "', '" +
                   IdString(file->Parse(previous), "/" + std::to_string(previous.index) + "/id", source) + "', has " +
                   json(previous.timestamp_s).dump() + ")");
        }
      }
    }
    build.frame_index.push_back(index_in_group);
    if (const json* fps = io::JsonFind(root, pointer + "/fps"); fps && !fps->is_null() && !build.fps) {
      const double value = io::JsonNumber(root, pointer + "/fps", source);
      if (!(value > 0) || !std::isfinite(value)) Fail(source, pointer + "/fps", "must be positive");
      build.fps = value;
    }
    if (!build.room_set) {
      const json* size = io::JsonFind(root, pointer + "/room_size");
      const json* center = io::JsonFind(root, pointer + "/room_center");
      if (size && !size->is_null()) {
        const auto v = io::JsonMatrix(root, pointer + "/room_size", source, 3, 1);
        header.room.size_m = Eigen::Vector3d(v[0], v[1], v[2]);
        build.room_set = true;
      }
      if (center && !center->is_null()) {
        const auto v = io::JsonMatrix(root, pointer + "/room_center", source, 3, 1);
        header.room.center_m = Eigen::Vector3d(v[0], v[1], v[2]);
        build.room_set = true;
      }
    }
  }

  std::vector<std::unique_ptr<FrameSource>> sources;
  for (SequenceBuild& build : builds) {
    if (build.labels.empty()) continue;  // all its labels belong to other splits
    build.unknown_keys.Report(source, "labels", &build.warnings);
    SequenceHeader& header = build.header;
    const bool all = std::all_of(build.has_timestamp.begin(), build.has_timestamp.end(), [](bool b) { return b; });
    const bool none = std::none_of(build.has_timestamp.begin(), build.has_timestamp.end(), [](bool b) { return b; });
    if (!all && !none) {
      const size_t f = std::find(build.has_timestamp.begin(), build.has_timestamp.end(), false) - build.has_timestamp.begin();
      const LabelRef& label = build.labels[f];
      throw InputError(source + ": label '" +
                       IdString(file->Parse(label), "/" + std::to_string(label.index) + "/id", source) +
                       "' of sequence " + QuoteName(header.name) + " has no \"timestamp\" while others have one");
    }
    header.fps = build.fps.value_or(options.fps);
    if (none) {
      // Without "timestamp" the frame rate gives the times; without a rate they are unknown (NaN:
      // nothing is carried from one frame to the next), which one warning per file says.
      for (size_t f = 0; f < build.labels.size(); ++f) {
        build.labels[f].timestamp_s = header.fps > 0 ? build.frame_index[f] / header.fps : kUnknownTime;
      }
      if (!(header.fps > 0)) {
        build.warnings.AddMissing(source, kUnknownTimesWarning, static_cast<long>(build.labels.size()));
      }
    }
    const size_t count = build.labels.size();
    auto convert = [file, labels = std::move(build.labels), num_joints = static_cast<int>(header.gt_joints.size()),
                    ground_truth](size_t i, SequenceFrame* frame, InputWarnings*) {
      const LabelRef& ref = labels[i];
      const json root = file->Parse(ref);
      // Appended, not "/" + std::to_string(...): GCC 12 warns falsely (-Wstringop-overflow) on that form here.
      std::string pointer(1, '/');
      pointer += std::to_string(ref.index);
      frame->id = IdString(root, pointer + "/id", file->source);
      frame->timestamp_s = ref.timestamp_s;
      if (ground_truth) ConvertLabel(root, pointer, file->source, num_joints, &frame->gt);
    };
    sources.push_back(
        std::make_unique<IndexedFrameSource>(std::move(header), count, std::move(convert), std::move(build.warnings)));
  }
  if (sources.empty()) {
    throw InputError(source + ": no labels" + (options.split.empty() ? std::string() : " in split " + QuoteName(options.split)));
  }
  return sources;
}

namespace {

using OrderedJson = nlohmann::ordered_json;

}  // namespace

int WriteLabels(const std::filesystem::path& path, const std::vector<Sequence>& sequences) {
  const std::string source = Source(path);
  std::vector<OrderedJson> labels;
  std::unordered_set<std::string> ids;
  for (const Sequence& sequence : sequences) {
    CheckJointNames(sequence.gt_joints, source + ": cannot write sequence " + QuoteName(sequence.name));
    OrderedJson cameras = OrderedJson::array();
    for (const Camera& camera : sequence.cameras)
      cameras.push_back(
          camera_json::CameraJson(camera, source, "sequence " + QuoteName(sequence.name) + ", camera " + QuoteName(camera.name)));
    const OrderedJson joints = sequence.gt_joints;
    const int num_joints = static_cast<int>(sequence.gt_joints.size());
    for (const SequenceFrame& frame : sequence.frames) {
      const std::string where = "sequence " + QuoteName(sequence.name) + ", frame " + QuoteName(frame.id);
      if (!ids.insert(frame.id).second) throw InputError(source + ": cannot write " + where + ": duplicate frame id");
      if (frame.gt.num_persons() > 0 && frame.gt.num_joints != num_joints) {
        throw InputError(source + ": cannot write " + where + ": " + std::to_string(frame.gt.num_joints) +
                         " joints, expected " + std::to_string(num_joints));
      }
      OrderedJson label;
      label["id"] = frame.id;
      label["scene"] = sequence.name;
      if (std::isnan(frame.timestamp_s)) {
        label["timestamp"] = nullptr;  // unknown (read back as a label without time)
      } else {
        io::CheckFiniteToWrite(frame.timestamp_s, source, where);
        label["timestamp"] = frame.timestamp_s;
      }
      if (sequence.fps > 0) label["fps"] = sequence.fps;
      label["joints"] = joints;
      label["cameras"] = cameras;
      OrderedJson bodies = OrderedJson::array();
      bool tracked = false;
      for (int p = 0; p < frame.gt.num_persons(); ++p) {
        const auto person = frame.gt.Person(p);
        OrderedJson body = OrderedJson::array();
        for (int j = 0; j < num_joints; ++j) {
          for (int k = 0; k < 4; ++k) io::CheckFiniteToWrite(person(k, j), source, where);
          body.push_back({person(0, j), person(1, j), person(2, j), person(3, j)});
        }
        bodies.push_back(std::move(body));
        tracked |= frame.gt.track_ids[p] >= 0;
      }
      label["bodies3D"] = std::move(bodies);
      if (tracked) label["bodyids"] = frame.gt.track_ids;
      const Room& room = sequence.room;
      for (int i = 0; i < 3; ++i) {
        io::CheckFiniteToWrite(room.center_m[i], source, where);
        io::CheckFiniteToWrite(room.size_m[i], source, where);
      }
      label["room_center"] = {room.center_m.x(), room.center_m.y(), room.center_m.z()};
      label["room_size"] = {room.size_m.x(), room.size_m.y(), room.size_m.z()};
      labels.push_back(std::move(label));
    }
  }
  int replaced = 0;
  io::WriteTextFile(path, io::NamedBy::kUser, generic_internal::DumpListOnePerLine(labels, &replaced));
  return replaced;
}

DatasetInfo GenericInfo() {
  DatasetInfo info;
  info.name = "generic";
  info.description = "Labels in the generic (skelda) JSON format: cameras and 3D ground truth per multi-view frame";
  info.layout =
      "--root is the label file: a JSON list of labels {id, cameras, bodies3D, joints, ...}\n"
      "(schema: docs/datasets/generic_formats.md); labels are grouped into sequences by \"scene\"/\"seq\".";
  info.params = DescribeDatasetParams<LabelsOptions>();
  return info;
}

std::vector<std::unique_ptr<FrameSource>> OpenGeneric(const DatasetRequest& request) {
  // JSON labels or the HDF5 cache.
  return OpenLabelsFile(request.root, ParseDatasetParams<LabelsOptions>("generic", request), request.ground_truth);
}

}  // namespace rpt
