// SPDX-License-Identifier: MIT
#include "engine/outputs/predictions_writer.h"

#include <cstring>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "datasets/io/json_output.h"
#include "datasets/io/staged_output.h"
#include "datasets/io/text_file.h"
#include "engine/outputs/frame_json.h"

namespace rpt::engine {
namespace {

using Json = nlohmann::json;

}  // namespace

// One sequence's frames, as the JSON text of the "frames" list (without the brackets), in a scratch
// file of its own (created new, so a link planted at its name in an old run folder is never written
// through; removed on every way out, Ctrl-C included).
struct PredictionsWriter::Part {
  std::unique_ptr<io::ScratchFile> scratch;  // declared before `out`: closed after it
  std::filesystem::path path;
  std::ofstream out;
  JointNames joints;
  std::string name;
  double fps = 0;
  long frames = 0;
  int replaced = 0;  // strings with invalid UTF-8
  std::string text;  // the frame being written (its capacity reused)
  bool begun = false;
};

PredictionsWriter::PredictionsWriter(std::filesystem::path path, std::string run_id, int num_sequences,
                                     ExportOptions options)
    : path_(std::move(path)), run_id_(std::move(run_id)), options_(std::move(options)) {
  parts_.resize(static_cast<size_t>(num_sequences));
}

PredictionsWriter::~PredictionsWriter() = default;

void PredictionsWriter::BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) {
  auto part = std::make_unique<Part>();
  std::filesystem::path name_like = path_;
  name_like += ".part-" + std::to_string(sequence);
  part->scratch = std::make_unique<io::ScratchFile>(name_like);
  part->path = part->scratch->path();
  part->out.open(part->path, std::ios::binary | std::ios::trunc);
  if (!part->out) throw InputError(part->path.string() + ": cannot open for writing: " + std::strerror(errno));
  part->joints = output_joints;
  part->name = header.name;
  part->fps = header.fps;
  part->begun = true;
  parts_[sequence] = std::move(part);
}

void PredictionsWriter::Frame(const FrameOutput& frame) {
  Part& part = *parts_[frame.sequence];
  part.text.assign(part.frames++ == 0 ? "\n" : ",\n");
  AppendFrameJson(frame, options_, &part.text, &part.replaced);
  part.out << part.text;
}

void PredictionsWriter::EndSequence(int sequence) {
  Part& part = *parts_[sequence];
  part.out.flush();
  // Named as the file it is a part of (the part's scratch name is nothing the user knows).
  if (!part.out) throw InputError(path_.string() + ": write failed (" + io::WriteFailureReason(part.path, errno) + ")");
  part.out.close();
}

int PredictionsWriter::Finish() {
  int replaced = 0;
  JointNames joints;
  for (const auto& part : parts_) {
    if (part != nullptr && joints.empty()) joints = part->joints;
  }
  Json sequences = Json::array();
  for (const auto& part : parts_) {
    if (part == nullptr) continue;
    sequences.push_back({{"name", part->name}, {"frames", part->frames}, {"fps", part->fps > 0 ? Json(part->fps) : Json()}});
  }
  io::WriteTextFile(path_, io::NamedBy::kRpt, [&](std::ostream& out) {
    out << "{\"run_id\": " << io::DumpJson(Json(run_id_), -1, &replaced)
        << ", \"joints\": " << io::DumpJson(Json(joints), -1, &replaced)
        << ",\n\"units\": {\"position\": \"m\", \"time\": \"s\", \"score\": \"1\"}, \"provenance_names\": "
        << io::DumpJson(Json(ProvenanceNames()), -1) << ",\n\"sequences\": " << io::DumpJson(sequences, -1, &replaced)
        << ",\n\"frames\": [";
    bool first = true;
    for (const auto& part : parts_) {
      if (part == nullptr || part->frames == 0) continue;
      std::ifstream in(part->path, std::ios::binary);
      if (!in) throw InputError(part->path.string() + ": cannot read back: " + std::strerror(errno));
      if (!first) out << ",";
      first = false;
      out << in.rdbuf();
      replaced += part->replaced;
    }
    out << "\n]}\n";
  });
  for (auto& part : parts_) part.reset();  // the scratch files go
  return replaced;
}

}  // namespace rpt::engine
