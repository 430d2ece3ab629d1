// SPDX-License-Identifier: MIT
// rpt.export.write: the CLI's exports of 3D persons (--export json,csv,trc,npz,h5; engine/outputs/) from
// rpt.Predictions, written by the same writers (FrameSinks fed frame by frame as engine::Run feeds
// them). The formats are dispatched in one place, ExportSinks below: a new export format is one more
// case there.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/printable_text.h"
#include "engine/frame_sink.h"
#include "engine/outputs/array_frames.h"
#include "engine/outputs/csv_export.h"
#include "engine/outputs/export_options.h"
#include "engine/outputs/h5_export.h"
#include "engine/outputs/npz_export.h"
#include "engine/outputs/predictions_writer.h"
#include "engine/outputs/trc_export.h"
#include "python/bindings.h"

namespace rpt::python {
namespace {

// The writers of `options.formats` into `dir`, and how each finishes.
struct ExportSinks {
  std::unique_ptr<engine::PredictionsWriter> json;
  std::unique_ptr<engine::CsvExport> csv;
  std::unique_ptr<engine::TrcExport> trc;
  std::unique_ptr<engine::ArrayFrames> arrays;  // the frames of the npz and h5 exports
  std::filesystem::path npz, h5;
  std::vector<engine::FrameSink*> all;
  std::vector<std::filesystem::path> written;

  ExportSinks(const std::filesystem::path& dir, const std::string& run_id, int num_sequences,
              const engine::ExportOptions& options) {
    for (const engine::ExportFormat format : options.formats) {
      switch (format) {
        case engine::ExportFormat::kJson:
          json = std::make_unique<engine::PredictionsWriter>(dir / "predictions.json", run_id, num_sequences, options);
          all.push_back(json.get());
          written.push_back(dir / "predictions.json");
          break;
        case engine::ExportFormat::kCsv:
          csv = std::make_unique<engine::CsvExport>(dir / "predictions.csv", num_sequences, options);
          all.push_back(csv.get());
          written.push_back(dir / "predictions.csv");
          break;
        case engine::ExportFormat::kTrc:
          trc = std::make_unique<engine::TrcExport>(dir / "trc", num_sequences, options);
          all.push_back(trc.get());
          written.push_back(dir / "trc");
          break;
        case engine::ExportFormat::kNpz:
        case engine::ExportFormat::kH5: {
          const std::filesystem::path path = dir / std::string(engine::ExportFileName(format));
          (format == engine::ExportFormat::kNpz ? npz : h5) = path;
          if (!arrays) {
            arrays = std::make_unique<engine::ArrayFrames>(path, run_id, num_sequences, options);
            all.push_back(arrays.get());
          }
          written.push_back(path);
          break;
        }
      }
    }
  }

  void Finish() {
    if (json) json->Finish();
    if (csv) csv->Finish();
    if (!npz.empty()) engine::WriteNpzExport(npz, *arrays);
    if (!h5.empty()) engine::WriteH5Export(h5, *arrays);
    arrays.reset();  // its scratch files go
  }
};

// The TRC files an earlier write left in `trc_dir` (links too, never what they point to): a
// second write of a notebook cell kept the first run's det_track0.trc beside this run's tracks.
// Only rpt's *.trc files go; a `trc_dir` that is a link is left to the writer (it replaces it).
void RemoveEarlierTrcFiles(const std::filesystem::path& trc_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(trc_dir, ec))) return;
  std::vector<fs::path> earlier;
  for (const fs::directory_entry& entry : fs::directory_iterator(trc_dir, ec)) {
    const fs::file_status status = entry.symlink_status(ec);
    if (entry.path().extension() == ".trc" && (fs::is_regular_file(status) || fs::is_symlink(status))) {
      earlier.push_back(entry.path());
    }
  }
  if (ec) throw InputError(trc_dir.string() + ": cannot list the earlier TRC files (" + ec.message() + ")");
  for (const fs::path& path : earlier) {
    if (!fs::remove(path, ec) && ec) {
      throw InputError(path.string() + ": cannot remove the earlier run's TRC file (" + ec.message() + ")");
    }
  }
}

std::vector<std::filesystem::path> Write(const std::filesystem::path& dir, py::handle predictions, py::handle formats,
                                         bool filled_joints, bool predicted_joints, const std::string& trc_axes,
                                         const std::string& trc_units, const std::string& run_id) {
  std::vector<Predictions> runs;
  const auto refuse = [](py::handle given) {
    throw py::type_error("export.write: predictions must be rpt.Predictions (what process_sequence returns) or a list "
                         "of them, one per sequence, got " +
                         py::str(py::type::of(given).attr("__name__")).cast<std::string>() +
                         " (the (persons, track_ids) of process() calls are not a sequence: give the frames to "
                         "process_sequence instead)");
  };
  if (py::isinstance<Predictions>(predictions)) {
    runs.push_back(predictions.cast<Predictions>());
  } else if (py::isinstance<py::list>(predictions) || py::isinstance<py::tuple>(predictions)) {
    for (py::handle item : predictions) {
      if (!py::isinstance<Predictions>(item)) refuse(item);
      runs.push_back(item.cast<Predictions>());
    }
  } else {
    refuse(predictions);
  }
  engine::ExportOptions options;
  std::string format_text;
  if (py::isinstance<py::str>(formats)) {
    format_text = formats.cast<std::string>();
  } else {
    for (const std::string& f : formats.cast<std::vector<std::string>>())
      format_text += (format_text.empty() ? "" : ",") + f;
  }
  try {
    options.formats = engine::ParseExportFormats(format_text);
  } catch (const ConfigError& e) {  // the CLI's words name its flag ("--export xlsx: ...")
    const std::string what = e.what();
    throw ConfigError(what.rfind("--export ", 0) == 0 ? "export.write: formats " + what.substr(9) : what);
  }
  options.filled_joints = filled_joints;
  options.predicted_joints = predicted_joints;
  if (trc_axes != "z-up" && trc_axes != "y-up")
    throw ConfigError("export.write: trc_axes: " + QuoteName(trc_axes) + " is not z-up | y-up");
  if (trc_units != "m" && trc_units != "mm")
    throw ConfigError("export.write: trc_units: " + QuoteName(trc_units) + " is not m | mm");
  options.trc_axes = trc_axes == "y-up" ? engine::TrcAxes::kYUp : engine::TrcAxes::kZUp;
  options.trc_millimetres = trc_units == "mm";

  // Checked before anything is written, as the CLI writes a run whole or not at all: one joint list
  // (JSON, NPZ and HDF5 hold one; a mixed list wrote a JSON whose persons did not match its
  // joints), and distinct sequence names (two takes named 'detections' were one sequence in the CSV
  // and looked like a track coming back in TRC).
  for (size_t s = 1; s < runs.size(); ++s) {
    if (runs[s].joints != runs[0].joints) {
      throw ConfigError("export.write: sequence " + std::to_string(s) + " (" + QuoteName(runs[s].sequence) +
                        ") has other output joints than sequence 0 (" + QuoteName(runs[0].sequence) +
                        "): one write holds one joint list; write them in separate calls");
    }
    for (size_t t = 0; t < s; ++t) {
      if (runs[s].sequence == runs[t].sequence) {
        throw ConfigError("export.write: sequences " + std::to_string(t) + " and " + std::to_string(s) +
                          " are both named " + QuoteName(runs[s].sequence) +
                          ": set each Predictions' .sequence to a name of its own (e.g. the take's folder)");
      }
    }
  }
  py::gil_scoped_release release;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir.string() + ": cannot create the folder (" + ec.message() + ")");
  // An earlier write's files this one does not replace go (links too, never what they point to):
  // the folder holds one write, as the CLI's run folder holds one run.
  RemoveEarlierTrcFiles(dir / "trc");
  for (const engine::ExportFormat format : {engine::ExportFormat::kJson, engine::ExportFormat::kCsv,
                                            engine::ExportFormat::kNpz, engine::ExportFormat::kH5}) {
    if (std::find(options.formats.begin(), options.formats.end(), format) != options.formats.end()) continue;
    const std::filesystem::path earlier = dir / std::string(engine::ExportFileName(format));
    const std::filesystem::file_status status = std::filesystem::symlink_status(earlier, ec);
    if (std::filesystem::is_regular_file(status) || std::filesystem::is_symlink(status)) {
      if (!std::filesystem::remove(earlier, ec) && ec) {
        throw InputError(earlier.string() + ": cannot remove the earlier write's file (" + ec.message() + ")");
      }
    }
  }
  ExportSinks sinks(dir, run_id, static_cast<int>(runs.size()), options);
  engine::SinkList sink(sinks.all);
  for (size_t s = 0; s < runs.size(); ++s) {
    const Predictions& run = runs[s];
    SequenceHeader header;
    header.name = run.sequence;
    header.fps = run.fps;
    sink.BeginSequence(static_cast<int>(s), header, run.joints);
    SequenceFrame frame;
    for (size_t f = 0; f < run.persons.size(); ++f) {
      frame.id = run.frame_ids[f];
      frame.timestamp_s = run.timestamps_s[f];
      sink.Frame(engine::FrameOutput{static_cast<int>(s), &frame, &run.persons[f], &run.stats[f]});
    }
    sink.EndSequence(static_cast<int>(s));
  }
  sinks.Finish();
  if (sinks.trc) {
    long persons = 0;
    for (const Predictions& run : runs) {
      for (const Poses3D& frame : run.persons) persons += frame.num_persons();
    }
    const std::string warning = engine::NoTrcFileWarning(*sinks.trc, dir / "trc", persons,
                                                         "give process_sequence the frames' timestamps");
    if (!warning.empty()) {
      py::gil_scoped_acquire acquire;
      WarnInput({warning});
    }
  }
  return sinks.written;
}

}  // namespace

void RegisterExport(py::module_& exports) {
  exports.def("write", &Write, py::arg("out_dir"), py::arg("predictions"), py::arg("formats") = "json", py::kw_only(),
              py::arg("filled_joints") = true, py::arg("predicted_joints") = true, py::arg("trc_axes") = "z-up",
              py::arg("trc_units") = "m", py::arg("run_id") = "python",
              "Writes rpt.Predictions (or a list, one per sequence) as the CLI's --export does: formats 'json' "
              "(predictions.json), 'csv' (predictions.csv), 'trc' (trc/, one file per track), 'npz' "
              "(predictions.npz), 'h5' (predictions.h5), a comma text or a list; filled_joints=False writes "
              "filled joints as missing, predicted_joints=False those of persons tracking holds while unseen; trc_axes "
              "'z-up' | 'y-up' (OpenSim); "
              "trc_units 'm' | 'mm'. Returns the paths written. Schemas: docs/own_data.md.");
  exports.def(
      "formats",
      [] {
        std::vector<std::string> names;
        for (const engine::ExportFormat f : engine::kExportFormats) names.emplace_back(engine::ExportFormatName(f));
        return names;
      },
      "The formats write() writes");
}

}  // namespace rpt::python
