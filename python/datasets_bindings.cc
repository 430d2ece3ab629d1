// SPDX-License-Identifier: MIT
// rpt.datasets: the CLI's inputs (engine/input.h: a dataset reader, generic labels, or a calibration
// with a detections file; detections attached or simulated; every frame validated) as an iterator of
// frames, or loaded into rpt.Sequence objects; and rpt.synthetic: the generated scenes with the
// simulated detector's profiles (datasets/synthetic/).
#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/synthetic/detector_options.h"
#include "datasets/synthetic/simulate_detections.h"
#include "datasets/synthetic/synthetic_dataset.h"
#include "engine/dataset_registry.h"
#include "engine/input.h"
#include "python/arrays.h"
#include "python/bindings.h"
#include "python/datasets_types.h"
#include "python/option_values.h"

namespace rpt::python {
namespace {

py::object TimeObject(double timestamp_s) { return std::isnan(timestamp_s) ? py::none() : py::cast(timestamp_s); }

// Read-only views of the frame's detections, kept alive by `owner` (the rpt.datasets.Frame).
py::list ViewsList(const SequenceFrame& frame, const SequenceHeader& header, py::handle owner) {
  py::list views;
  const int joints = static_cast<int>(header.detection_joints.size());
  for (size_t c = 0; c < header.cameras.size(); ++c) {
    if (c < frame.views.size() && frame.views[c].unavailable) {
      views.append(py::none());  // no data from this camera in this frame
    } else {
      views.append(c < frame.views.size() ? ViewOf(frame.views[c], joints, owner) : ViewArray(Poses2D{}, joints));
    }
  }
  return views;
}

// The streaming input of datasets.open: frames of every sequence in order, one in memory at a time.
class Dataset {
 public:
  explicit Dataset(engine::Input input) : input_(std::move(input)) {
    for (int i = 0; i < input_.size(); ++i) headers_.push_back(std::make_shared<SequenceHeader>(input_.header(i)));
  }

  std::vector<SequenceHeader> Headers() const {
    std::vector<SequenceHeader> headers;
    for (int i = 0; i < input_.size(); ++i) headers.push_back(input_.header(i));
    return headers;
  }

  Frame Next() {
    while (current_ < input_.size()) {
      Frame out;
      bool pulled = false;
      {
        py::gil_scoped_release release;
        pulled = input_.source(current_).Next(&out.frame);
      }
      if (pulled) {
        started_ = true;
        out.sequence = headers_[static_cast<size_t>(current_)];
        return out;
      }
      input_.Finished(current_++);
    }
    input_.CheckStrict();
    throw py::stop_iteration();
  }

  // A second loop over the frames found none, silently (a notebook cell run twice).
  Dataset& Iterate() {
    if (started_) {
      throw py::value_error("Dataset: its frames were already pulled (a Dataset is read once, frame by frame); "
                            "open the dataset again, or load() its sequences to go over them many times");
    }
    return *this;
  }

  std::vector<std::shared_ptr<Sequence>> Load() {
    if (started_) throw py::value_error("Dataset.load: frames were already pulled; open the dataset again");
    started_ = true;
    std::vector<Sequence> sequences;
    {
      py::gil_scoped_release release;
      sequences = input_.Materialize();
      input_.CheckStrict();
    }
    std::vector<std::shared_ptr<Sequence>> out;
    for (Sequence& s : sequences) out.push_back(std::make_shared<Sequence>(std::move(s)));
    return out;
  }

  std::vector<std::string> Warnings() const { return engine::InputWarningLines(input_.Warnings()); }
  bool Started() const { return started_; }

 private:
  engine::Input input_;
  std::vector<std::shared_ptr<const SequenceHeader>> headers_;  // shared by the frames handed out
  int current_ = 0;
  bool started_ = false;
};

// A list or tuple is the comma list the CLI takes (days=[1, 2] is --param days=1,2).
std::string ParamText(py::handle value, const std::string& key) {
  // A numpy array as the list it holds (its str() was "[1 2]": "'[1' is not a day").
  if (py::isinstance<py::array>(value)) return ParamText(value.attr("tolist")(), key);
  if (!py::isinstance<py::list>(value) && !py::isinstance<py::tuple>(value)) return OptionText(value, "datasets.open", key);
  std::string text;
  for (py::handle item : value) {
    if (!text.empty()) text += ",";
    text += OptionText(item, "datasets.open", key);
  }
  return text;
}

// The input options every opening shares (named so that no reader parameter shadows them: readers
// have parameters called detections, cameras, fps, seed and labels).
struct InputArgs {
  std::string detections_file;
  bool simulate = false;
  std::string detector;
  std::uint64_t simulate_seed = 1;
  bool strict = false;
  bool ground_truth = true;
};

Dataset OpenSpec(engine::InputSpec spec, const InputArgs& args, const py::kwargs& params) {
  spec.detections = args.detections_file;
  spec.simulate = args.simulate;
  spec.detector = args.detector;
  spec.seed = args.simulate_seed;
  spec.strict = args.strict;
  spec.ground_truth = args.ground_truth;
  for (const auto& [key, value] : params) {
    const std::string k = py::str(key).cast<std::string>();
    spec.params.push_back(k + "=" + ParamText(value, k));
  }
  const std::string named = !spec.labels.empty() ? spec.labels : spec.root;
  try {
    py::gil_scoped_release release;
    return Dataset(engine::OpenInput(spec, {.python_names = true}));
  } catch (const ConfigError& e) {
    // The CLI's words name its flag ("--param dayz=1: ..."); here the argument was a keyword.
    const std::string what = e.what();
    if (what.rfind("--param ", 0) == 0) throw ConfigError("datasets: keyword argument " + what.substr(8));
    throw;
  } catch (const InputError& e) {
    std::error_code ec;
    if (!named.empty() && !std::filesystem::exists(named, ec)) throw MissingInputError(e.what());
    throw;
  }
}

// Paths are str or os.PathLike (pathlib.Path), as cameras.load and export.write take them.
Dataset Open(const std::string& name, const std::filesystem::path& root, const std::filesystem::path& detections_file,
             bool simulate,
             const std::string& detector, std::uint64_t simulate_seed, bool strict, bool ground_truth,
             const py::kwargs& params) {
  engine::InputSpec spec;
  spec.dataset = name;
  spec.root = root.string();
  return OpenSpec(spec, {detections_file.string(), simulate, detector, simulate_seed, strict, ground_truth}, params);
}

Dataset OpenLabels(const std::filesystem::path& path, const std::filesystem::path& detections_file, bool simulate,
                   const std::string& detector, std::uint64_t simulate_seed, bool strict, bool ground_truth,
                   const py::kwargs& params) {
  engine::InputSpec spec;
  spec.labels = path.string();
  return OpenSpec(spec, {detections_file.string(), simulate, detector, simulate_seed, strict, ground_truth}, params);
}

// The CLI's options of `rpt triangulate --cameras FILE --detections FILE` with '_' for '-': how the
// calibration is read (cameras_format, cameras_units, cameras_image_width, cameras_image_height)
// and how the detections map onto its cameras and frames (map_pattern, ..., rename_camera).
void SetCameraInputOptions(const py::kwargs& options, engine::InputSpec* spec) {
  static constexpr std::string_view kWhere = "datasets.open_cameras";
  py::dict camera_read;
  engine::DetectionMapping& m = spec->mapping;
  const std::vector<std::pair<std::string, std::string*>> texts = {
      {"map_pattern", &m.pattern},         {"map_frame_id", &m.frame_id},     {"map_camera", &m.camera},
      {"openpose_joints", &m.openpose_joints}, {"coco_images", &m.coco_images}, {"coco_image_ids", &m.coco_image_ids},
      {"coco_keypoints", &m.coco_keypoints}, {"voxelpose_prefix", &m.voxelpose_prefix}};
  for (const auto& [key_object, value] : options) {
    const std::string key = py::str(key_object).cast<std::string>();
    if (key.rfind("cameras_", 0) == 0) {
      camera_read[py::str(key.substr(8))] = value;
      continue;
    }
    const auto text = std::find_if(texts.begin(), texts.end(), [&](const auto& t) { return t.first == key; });
    if (text != texts.end()) {
      *text->second = OptionText(value, kWhere, key);
    } else if (key == "coco_min_score") {
      if (!PyNumber_Check(value.ptr()) || py::isinstance<py::bool_>(value)) {
        throw py::type_error(std::string(kWhere) + ": coco_min_score: expected a number, got " +
                             py::str(py::type::of(value)).cast<std::string>());
      }
      m.coco_min_score = py::reinterpret_borrow<py::object>(value).cast<double>();
    } else if (key == "rename_camera") {  // {"FROM": "TO"} or ["FROM=TO", ...], as --rename-camera
      if (py::isinstance<py::dict>(value)) {
        for (const auto& [from, to] : py::reinterpret_borrow<py::dict>(value)) {
          m.rename_cameras.push_back(OptionText(from, kWhere, key) + "=" + OptionText(to, kWhere, key));
        }
      } else if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
        for (py::handle item : value) m.rename_cameras.push_back(OptionText(item, kWhere, key));
      } else {
        m.rename_cameras.push_back(OptionText(value, kWhere, key));
      }
    } else {
      std::string known = "cameras_format, cameras_units, cameras_image_width, cameras_image_height";
      for (const auto& t : texts) known += ", " + t.first;
      throw ConfigError(std::string(kWhere) + ": unknown option " + QuoteName(key) + " (known: " + known +
                        ", coco_min_score, rename_camera)");
    }
  }
  SetOptionFields(camera_read, kWhere, "cameras_", &spec->camera_read);
}

Dataset OpenCameras(const std::filesystem::path& cameras, const std::filesystem::path& detections, double fps,
                    bool strict,
                    const py::kwargs& options) {
  engine::InputSpec spec;
  spec.cameras = cameras.string();
  spec.fps = fps;
  SetCameraInputOptions(options, &spec);
  InputArgs args;
  args.detections_file = detections.string();
  args.strict = strict;
  args.ground_truth = false;
  return OpenSpec(spec, args, py::kwargs());
}

std::shared_ptr<Sequence> SyntheticScene(const py::kwargs& params) {
  SyntheticParams p;
  SetOptionFields(params, "synthetic.scene", "synthetic.", &p);
  ThrowIfInvalid(p);
  py::gil_scoped_release release;
  std::vector<Sequence> sequences = MakeSyntheticDataset(p);
  return std::make_shared<Sequence>(std::move(sequences.front()));
}

std::shared_ptr<Sequence> Simulate(const Sequence& sequence, const std::string& detector, std::uint64_t seed) {
  SimulationOptions options;
  options.detector = detector;
  options.seed = seed;
  auto out = std::make_shared<Sequence>(sequence);
  py::gil_scoped_release release;
  SimulateDetections(options, out.get());
  return out;
}

}  // namespace

py::tuple RoomTuple(const SequenceHeader& h) {
  return py::make_tuple(py::make_tuple(h.room.center_m.x(), h.room.center_m.y(), h.room.center_m.z()),
                        py::make_tuple(h.room.size_m.x(), h.room.size_m.y(), h.room.size_m.z()));
}

void RegisterDatasets(py::module_& datasets, py::module_& synthetic) {
  py::class_<SequenceHeader, std::shared_ptr<SequenceHeader>>(datasets, "SequenceInfo",
                                                              "What a sequence is: name, cameras, joints, room, fps")
      .def_readonly("name", &SequenceHeader::name)
      .def_readonly("cameras", &SequenceHeader::cameras)
      .def_readonly("joint_names", &SequenceHeader::detection_joints, "joints of the 2D detections (views)")
      .def_readonly("gt_joint_names", &SequenceHeader::gt_joints, "joints of the ground truth")
      .def_readonly("evaluated_joints", &SequenceHeader::evaluated_joints, "the dataset's (empty: the paper's 13)")
      .def_property_readonly("room", &RoomTuple, "((centre x, y, z), (size x, y, z)) in metres")
      .def_property_readonly("fps", [](const SequenceHeader& h) { return h.fps > 0 ? py::cast(h.fps) : py::none(); })
      .def("__repr__", [](const SequenceHeader& h) {
        return "SequenceInfo(" + QuoteName(h.name) + ", " + std::to_string(h.cameras.size()) + " cameras)";
      });

  py::class_<Sequence, SequenceHeader, std::shared_ptr<Sequence>>(
      datasets, "Sequence", "A sequence in memory (Dataset.load, synthetic.scene): indexable and iterable frames")
      .def("__len__", [](const Sequence& s) { return s.frames.size(); })
      .def("__getitem__",
           [](const std::shared_ptr<Sequence>& s, long i) {
             const long n = static_cast<long>(s->frames.size());
             if (i < 0) i += n;
             if (i < 0 || i >= n) throw py::index_error("frame index out of range");
             return Frame{s, s->frames[static_cast<size_t>(i)]};
           })
      // sequence[a:b]: those frames as a list of Frame (process_sequence takes it).
      .def("__getitem__",
           [](const std::shared_ptr<Sequence>& s, const py::slice& slice) {
             size_t start = 0, stop = 0, step = 0, length = 0;
             if (!slice.compute(s->frames.size(), &start, &stop, &step, &length)) throw py::error_already_set();
             py::list frames;
             for (size_t k = 0; k < length; ++k) frames.append(Frame{s, s->frames[start + k * step]});
             return frames;
           })
      // for frame in sequence: Python's own lazy iterator over __getitem__ (what iter() made of it
      // before), declared so that type checkers (python/rpt/datasets.pyi) know it is iterable.
      .def("__iter__",
           [](const py::object& self) {
             PyObject* iterator = PySeqIter_New(self.ptr());
             if (iterator == nullptr) throw py::error_already_set();
             return py::reinterpret_steal<py::object>(iterator);
           })
      .def_property_readonly("warnings", [](const Sequence& s) { return engine::InputWarningLines(s.warnings); })
      .def("__repr__", [](const Sequence& s) {
        return "Sequence(" + QuoteName(s.name) + ", " + std::to_string(s.cameras.size()) + " cameras, " +
               std::to_string(s.frames.size()) + " frames)";
      });

  py::class_<Frame>(datasets, "Frame", "One frame: id, time, 2D detections per camera, ground truth")
      .def_property_readonly("sequence", [](const Frame& f) { return f.sequence->name; })
      .def_property_readonly("id", [](const Frame& f) { return f.frame.id; })
      .def_property_readonly(
          "timestamp", [](const Frame& f) { return TimeObject(f.frame.timestamp_s); }, "seconds; None when unknown")
      .def_property_readonly(
          "views",
          [](py::object self) {
            const Frame& f = self.cast<const Frame&>();
            return ViewsList(f.frame, *f.sequence, self);
          },
          "per camera an array (persons, joints, 3): u_px, v_px, score (read-only views, no copy)")
      .def_property_readonly(
          "gt", [](py::object self) { return PersonsView(self.cast<const Frame&>().frame.gt, self); },
          "ground truth (persons, gt joints, 4): x, y, z (m), score (a read-only view, no copy)")
      .def_property_readonly(
          "gt_ids", [](const Frame& f) { return TrackIdsArray(f.frame.gt); },
          "the dataset's person ids of the ground truth (-1: none)")
      .def_property_readonly("cameras", [](const Frame& f) { return f.sequence->cameras; })
      .def("__repr__", [](const Frame& f) { return "Frame(" + QuoteName(f.frame.id) + ")"; });

  py::class_<Dataset>(datasets, "Dataset", "An opened input: iterate for its frames, or load() its sequences")
      .def_property_readonly("sequences", &Dataset::Headers, "one SequenceInfo per sequence")
      .def(
          "__iter__", [](Dataset& d) -> Dataset& { return d.Iterate(); }, py::return_value_policy::reference_internal)
      .def("__next__", &Dataset::Next)
      .def("load", &Dataset::Load, "every sequence in memory (validated), as rpt.datasets.Sequence objects")
      .def_property_readonly("warnings", &Dataset::Warnings, "the readers' corrections and unused input")
      .def("__repr__", [](const Dataset& d) {
        const std::vector<SequenceHeader> headers = d.Headers();
        std::string names;
        for (size_t i = 0; i < headers.size() && i < 3; ++i) names += (i ? ", " : "") + QuoteName(headers[i].name);
        if (headers.size() > 3) names += ", ...";
        return "Dataset(" + std::to_string(headers.size()) + " sequence(s): " + names +
               (d.Started() ? "; frames pulled)" : ")");
      });

  datasets.def("open", &Open, py::arg("name"), py::arg("root") = "", py::kw_only(), py::arg("detections_file") = "",
               py::arg("simulate") = false, py::arg("detector") = "", py::arg("simulate_seed") = 1,
               py::arg("strict") = false, py::arg("ground_truth") = true,
               "A dataset as the CLI opens it (--dataset NAME --root DIR): detections_file (--detections FILE), "
               "simulate (--simulate), detector (--detector PROFILE), simulate_seed (--seed), strict (--strict), "
               "ground_truth=False (frames without GT, as rpt triangulate reads them); other keyword arguments are the "
               "reader's --param key=value (`rpt datasets`).");
  datasets.def("open_labels", &OpenLabels, py::arg("path"), py::kw_only(), py::arg("detections_file") = "",
               py::arg("simulate") = false, py::arg("detector") = "", py::arg("simulate_seed") = 1,
               py::arg("strict") = false, py::arg("ground_truth") = true,
               "Generic labels (--labels FILE: JSON or HDF5 cache) with their detections or detections_file; other "
               "keyword arguments are the labels reader's --param key=value.");
  datasets.def("open_cameras", &OpenCameras, py::arg("cameras"), py::arg("detections"), py::kw_only(),
               py::arg("fps") = 0.0, py::arg("strict") = false,
               "Your own recording as rpt triangulate reads it (--cameras FILE --detections FILE --fps HZ): the "
               "frames of the detections file, without ground truth. Other keyword arguments are that command's "
               "reading options with '_' for '-': cameras_format, cameras_units, cameras_image_width, "
               "cameras_image_height, map_pattern, map_frame_id, map_camera, openpose_joints, coco_images, "
               "coco_image_ids, coco_min_score, coco_keypoints, voxelpose_prefix, rename_camera ({'FROM': 'TO'} "
               "or ['FROM=TO', ...]).");
  datasets.def("names", [] {
    std::vector<std::string> names;
    for (const engine::DatasetEntry& entry : engine::DatasetRegistry()) names.push_back(entry.info.name);
    return names;
  });
  datasets.def(
      "describe",
      [](const std::string& name) {
        for (const engine::DatasetEntry& entry : engine::DatasetRegistry()) {
          if (entry.info.name != name) continue;
          py::dict d;
          d["name"] = entry.info.name;
          d["description"] = entry.info.description;
          d["layout"] = entry.info.layout;
          py::list params;
          for (const DatasetParam& p : entry.info.params) {
            py::dict item;
            item["name"] = p.name;
            item["default"] = p.default_value;
            item["type"] = p.type;
            item["help"] = p.help;
            params.append(item);
          }
          d["params"] = params;
          return d;
        }
        throw ConfigError("unknown dataset " + QuoteName(name));
      },
      py::arg("name"), "description, on-disk layout and parameters of a reader");

  synthetic.def("scene", &SyntheticScene,
                "A generated scene with simulated detections, the dataset 'synthetic' (`rpt demo`): cameras=5, "
                "people=4, frames=300, fps=25, joints='body' | 'wholebody', layout='ring' | 'random', "
                "distortion='none' | 'opencv' | 'fisheye', noise=detector profile, seed=1.");
  synthetic.def("detector_profiles", &synthetic::DetectorProfileNames,
                "The simulated detector's profiles (docs/detector_model.md)");
  synthetic.def("simulate", &Simulate, py::arg("sequence"), py::arg("detector") = "realistic", py::arg("seed") = 1,
                "A copy of the sequence with simulated detections of its ground truth (`--simulate`)");
}

}  // namespace rpt::python
