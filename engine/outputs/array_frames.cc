// SPDX-License-Identifier: MIT
#include "engine/outputs/array_frames.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>

#include "core/errors.h"
#include "core/nan.h"
#include "core/printable_text.h"
#include "datasets/io/json_output.h"
#include "datasets/io/npz_writer.h"
#include "datasets/io/staged_output.h"

namespace rpt::engine {
namespace {

// A frame's record in a part file (native byte order; read back by the same process):
//   double time_s, int32 num_persons P, uint32 id bytes, the id, int32 track_ids[P],
//   double values[P * joints * 4], uint8 provenance[P * joints].
template <typename T>
void Put(std::ostream& out, const T* data, size_t count) {
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(count * sizeof(T)));
}
template <typename T>
bool Get(std::istream& in, T* data, size_t count) {
  in.read(reinterpret_cast<char*>(data), static_cast<std::streamsize>(count * sizeof(T)));
  return static_cast<size_t>(in.gcount()) == count * sizeof(T);
}

}  // namespace

struct ArrayFrames::Sequence {
  std::unique_ptr<io::ScratchFile> scratch;  // declared before `out`: closed after it
  std::filesystem::path path;
  std::ofstream out;
  std::string name;
  double fps = 0;
  JointNames joints;
  std::int64_t frames = 0;
  int max_persons = 0;
  std::size_t max_id_code_points = 0, max_id_bytes = 0;
  std::vector<double> values;  // one frame's, reused
  std::vector<std::uint8_t> provenance;
};

ArrayFrames::ArrayFrames(std::filesystem::path name_like, std::string run_id, int num_sequences, ExportOptions options)
    : name_like_(std::move(name_like)), run_id_(std::move(run_id)), options_(std::move(options)) {
  sequences_.resize(static_cast<size_t>(num_sequences));
}

ArrayFrames::~ArrayFrames() = default;

void ArrayFrames::BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) {
  auto s = std::make_unique<Sequence>();
  std::filesystem::path name_like = name_like_;
  name_like += ".part-" + std::to_string(sequence);
  s->scratch = std::make_unique<io::ScratchFile>(name_like);
  s->path = s->scratch->path();
  s->out.open(s->path, std::ios::binary | std::ios::trunc);
  if (!s->out) throw InputError(s->path.string() + ": cannot open for writing: " + std::strerror(errno));
  s->name = header.name;
  s->fps = header.fps;
  s->joints = output_joints;
  sequences_[sequence] = std::move(s);
}

void ArrayFrames::Frame(const FrameOutput& frame) {
  Sequence& s = *sequences_[frame.sequence];
  const Poses3D& persons = *frame.persons;
  const int num_persons = persons.num_persons();
  const size_t num_joints = static_cast<size_t>(persons.num_joints);
  s.values.resize(static_cast<size_t>(num_persons) * num_joints * 4);
  s.provenance.resize(static_cast<size_t>(num_persons) * num_joints);
  for (int p = 0; p < num_persons; ++p) {
    for (size_t j = 0; j < num_joints; ++j) {
      const size_t k = static_cast<size_t>(p) * num_joints + j;
      if (JointWritten(persons, p, static_cast<int>(j), options_)) {
        std::copy_n(persons.data.data() + 4 * k, 4, s.values.data() + 4 * k);
      } else {
        std::fill_n(s.values.data() + 4 * k, 3, kNaN);
        s.values[4 * k + 3] = 0;
      }
      s.provenance[k] = static_cast<std::uint8_t>(persons.Provenance(p, static_cast<int>(j)));
    }
  }
  const std::string& id = frame.input->id;
  const auto id_bytes = static_cast<std::uint32_t>(id.size());
  const double time_s = frame.input->timestamp_s;
  const auto count = static_cast<std::int32_t>(num_persons);
  Put(s.out, &time_s, 1);
  Put(s.out, &count, 1);
  Put(s.out, &id_bytes, 1);
  Put(s.out, id.data(), id.size());
  Put(s.out, persons.track_ids.data(), persons.track_ids.size());
  Put(s.out, s.values.data(), s.values.size());
  Put(s.out, s.provenance.data(), s.provenance.size());
  ++s.frames;
  s.max_persons = std::max(s.max_persons, num_persons);
  s.max_id_code_points = std::max(s.max_id_code_points, io::Utf32Length(id));
  s.max_id_bytes = std::max(s.max_id_bytes, io::ValidUtf8(id).size());
}

void ArrayFrames::EndSequence(int sequence) {
  Sequence& s = *sequences_[sequence];
  s.out.flush();
  if (!s.out) throw InputError(s.path.string() + ": write failed (" + io::WriteFailureReason(s.path, errno) + ")");
  s.out.close();
}

JointNames ArrayFrames::joints() const {
  const Sequence* first = nullptr;
  for (const auto& s : sequences_) {
    if (s == nullptr) continue;
    if (first == nullptr) first = s.get();
    if (s->joints != first->joints) {
      throw InputError("--export npz/h5: sequence " + QuoteName(s->name) + " has other output joints than " + QuoteName(first->name) +
                       "; the arrays need one joint list (export the sequences in separate runs)");
    }
  }
  return first == nullptr ? JointNames{} : first->joints;
}

std::vector<std::string> ArrayFrames::sequence_names() const {
  std::vector<std::string> names;
  for (const auto& s : sequences_) {
    if (s != nullptr) names.push_back(s->name);
  }
  return names;
}

std::vector<double> ArrayFrames::sequence_fps() const {
  std::vector<double> fps;
  for (const auto& s : sequences_) {
    if (s != nullptr) fps.push_back(s->fps > 0 ? s->fps : kNaN);
  }
  return fps;
}

std::vector<std::int64_t> ArrayFrames::sequence_frame_offsets() const {
  std::vector<std::int64_t> offsets = {0};
  for (const auto& s : sequences_) {
    if (s != nullptr) offsets.push_back(offsets.back() + s->frames);
  }
  return offsets;
}

std::int64_t ArrayFrames::num_frames() const { return sequence_frame_offsets().back(); }

int ArrayFrames::max_persons() const {
  int count = 0;
  for (const auto& s : sequences_) {
    if (s != nullptr) count = std::max(count, s->max_persons);
  }
  return count;
}

std::size_t ArrayFrames::max_id_code_points() const {
  std::size_t count = 0;
  for (const auto& s : sequences_) {
    if (s != nullptr) count = std::max(count, s->max_id_code_points);
  }
  return count;
}

std::size_t ArrayFrames::max_id_bytes() const {
  std::size_t count = 0;
  for (const auto& s : sequences_) {
    if (s != nullptr) count = std::max(count, s->max_id_bytes);
  }
  return count;
}

std::int64_t ArrayFrames::block_frames() const {
  const size_t row_bytes = static_cast<size_t>(max_persons()) * joints().size() * 4 * sizeof(double);
  return std::clamp<std::int64_t>(row_bytes == 0 ? 4096 : static_cast<std::int64_t>((1u << 20) / row_bytes), 1, 4096);
}

ArrayFrames::Blocks::Blocks(const ArrayFrames& frames, std::int64_t block_frames)
    : frames_(frames), block_frames_(std::max<std::int64_t>(1, block_frames)) {}

bool ArrayFrames::Blocks::ReadFrame(std::int64_t slot) {
  const auto& sequences = frames_.sequences_;
  while (part_ < sequences.size()) {
    if (sequences[part_] == nullptr || sequences[part_]->frames == 0) {
      ++part_;
      continue;
    }
    if (!in_.is_open()) {
      in_.open(sequences[part_]->path, std::ios::binary);
      if (!in_) throw InputError(sequences[part_]->path.string() + ": cannot read back: " + std::strerror(errno));
    }
    if (in_.peek() != std::ifstream::traits_type::eof()) break;
    in_.close();
    ++part_;
  }
  if (part_ >= sequences.size()) return false;
  const std::string& path = sequences[part_]->path.string();
  const size_t num_joints = sequences[part_]->joints.size();
  const size_t max_persons = static_cast<size_t>(frames_.max_persons());
  std::int32_t count = 0;
  std::uint32_t id_bytes = 0;
  bool ok = Get(in_, &times_s_[slot], 1) && Get(in_, &count, 1) && Get(in_, &id_bytes, 1) && count >= 0 &&
            static_cast<size_t>(count) <= max_persons;
  if (ok) {
    std::string& id = ids_[slot];
    id.resize(id_bytes);
    const size_t persons = static_cast<size_t>(count);
    ok = Get(in_, id.data(), id_bytes) && Get(in_, track_ids_.data() + slot * max_persons, persons) &&
         Get(in_, poses_.data() + slot * max_persons * num_joints * 4, persons * num_joints * 4) &&
         Get(in_, provenance_.data() + slot * max_persons * num_joints, persons * num_joints);
  }
  if (!ok) throw InputError(path + ": cannot read back (damaged while the run went on?)");
  num_persons_[slot] = count;
  return true;
}

bool ArrayFrames::Blocks::Next() {
  first_ += count_;
  count_ = 0;
  const size_t max_persons = static_cast<size_t>(frames_.max_persons());
  size_t num_joints = 0;
  for (const auto& s : frames_.sequences_) {
    if (s != nullptr) num_joints = s->joints.size();
  }
  const size_t block = static_cast<size_t>(block_frames_);
  // Padding everywhere first; each frame's record overwrites its persons.
  poses_.assign(block * max_persons * num_joints * 4, kNaN);
  track_ids_.assign(block * max_persons, -1);
  provenance_.assign(block * max_persons * num_joints, kPaddingProvenance);
  num_persons_.assign(block, 0);
  times_s_.assign(block, kNaN);
  ids_.resize(block);
  while (count_ < block_frames_ && ReadFrame(count_)) ++count_;
  // Trim to the frames read (the last block may be short).
  const size_t n = static_cast<size_t>(count_);
  poses_.resize(n * max_persons * num_joints * 4);
  track_ids_.resize(n * max_persons);
  provenance_.resize(n * max_persons * num_joints);
  num_persons_.resize(n);
  times_s_.resize(n);
  ids_.resize(n);
  return count_ > 0;
}

}  // namespace rpt::engine
