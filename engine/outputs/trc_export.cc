// SPDX-License-Identifier: MIT
#include "engine/outputs/trc_export.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string_view>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/io/staged_output.h"
#include "datasets/io/text_file.h"
#include "engine/outputs/file_names.h"
#include "engine/outputs/text_escaping.h"
#include "core/text.h"
#include "engine/outputs/fixed_decimal.h"

namespace rpt::engine {
TrcExport::TrcExport(std::filesystem::path dir, int num_sequences, ExportOptions options)
    : dir_(std::move(dir)), options_(std::move(options)), sequences_(static_cast<size_t>(num_sequences)) {}

TrcExport::~TrcExport() {
  for (Sequence& s : sequences_) {
    for (auto& [id, track] : s.tracks) {
      track.out.reset();
      std::error_code ec;
      std::filesystem::remove(track.part, ec);
    }
  }
}

long TrcExport::files() const {
  long count = 0;
  for (const Sequence& s : sequences_) count += s.files;
  return count;
}

void TrcExport::BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) {
  Sequence& s = sequences_[sequence];
  s.name = FileNameOf(header.name);  // one-to-one, never a path
  s.joints = output_joints;
  s.fps = header.fps;
  s.steps.reserve(kRateSteps);
}

std::ofstream& TrcExport::TrackStream(Sequence* s, int track_id, double time_s) {
  auto [it, created] = s->tracks.try_emplace(track_id);
  Track& track = it->second;
  if (created) {
    // The folder with the first track: a run without tracks (no times) left an empty trc/ beside
    // its "no TRC file written" warning.
    if (!folder_created_) {
      std::error_code ec;
      std::filesystem::create_directories(dir_, ec);
      if (ec) throw InputError(dir_.string() + ": cannot create the folder: " + ec.message());
      folder_created_ = true;
    }
    // A new scratch file (never an existing name, so never through a link), removed with the track.
    track.scratch = std::make_unique<io::ScratchFile>(dir_ / (s->name + "_track" + std::to_string(track_id) + ".trc.part"));
    track.part = track.scratch->path();
    track.first_time_s = time_s;
  }
  track.last_time_s = time_s;
  if (track.out == nullptr) {
    if (s->open >= kMaxOpenTrcParts) {  // close the others; they reopen to append when needed
      for (auto& [id, other] : s->tracks) {
        if (other.out == nullptr) continue;
        other.out->flush();
        if (!*other.out) throw InputError(other.part.string() + ": write failed (" + io::WriteFailureReason(other.part, errno) + ")");
        other.out.reset();
      }
      s->open = 0;
    }
    track.out = std::make_unique<std::ofstream>(track.part, std::ios::binary | (created ? std::ios::trunc : std::ios::app));
    if (!*track.out) throw InputError(track.part.string() + ": cannot open for writing: " + std::strerror(errno));
    ++s->open;
  }
  return *track.out;
}

void TrcExport::Frame(const FrameOutput& frame) {
  Sequence& s = sequences_[frame.sequence];
  const long frame_idx = s.frames++;
  const Poses3D& persons = *frame.persons;
  const double time_s = frame.input->timestamp_s;
  if (std::isfinite(time_s)) {
    if (s.timed_frames++ == 0) {
      s.first_time_s = time_s;
    } else if (time_s > s.last_time_s && s.steps.size() < kRateSteps) {
      s.steps.push_back(time_s - s.last_time_s);
    }
    s.last_time_s = time_s;
  }
  const double scale = options_.trc_millimetres ? 1000.0 : 1.0;
  std::string number;
  for (int p = 0; p < persons.num_persons(); ++p) {
    if (persons.track_ids[p] < 0) continue;
    if (!std::isfinite(time_s)) {
      throw InputError("--export trc: sequence " + QuoteName(s.name) + ", frame " + QuoteName(frame.input->id) +
                       ": the frame's time is unknown (a TRC row needs one; give --fps)");
    }
    std::ofstream& out = TrackStream(&s, persons.track_ids[p], time_s);
    Track& track = s.tracks[persons.track_ids[p]];
    // With the sequence's fps, Frame# follows the time (a skipped frame leaves a gap); never back.
    long frame_number = frame_idx + 1;
    if (s.fps > 0) frame_number = 1 + std::lround((time_s - s.first_time_s) * s.fps);
    if (track.rows > 0) frame_number = std::max(frame_number, track.last_number + 1);
    if (track.rows == 0) track.first_number = frame_number;
    track.last_number = frame_number;
    ++track.rows;
    track.last_frame = frame_idx;
    number.assign(std::to_string(frame_number)).push_back('\t');  // C-locale numbers whatever LC_NUMERIC says
    AppendFixedDecimal(time_s, 6, &number);
    out << number;
    const auto person = persons.Person(p);
    for (int j = 0; j < persons.num_joints; ++j) {
      if (!JointWritten(persons, p, j, options_)) {
        out << "\t\t\t";
        continue;
      }
      double x = person(0, j), y = person(1, j), z = person(2, j);
      if (options_.trc_axes == TrcAxes::kYUp) {
        const double up = z;
        z = -y;
        y = up;
      }
      number.clear();
      for (const double value : {x * scale, y * scale, z * scale}) {
        number.push_back('\t');
        AppendFixedDecimal(value, 6, &number);
      }
      out << number;
    }
    out << "\n";
  }
  // A track is in every frame from its first to its end (it coasts while its person is not
  // detected, core/pipeline/track.h): one missing from this frame has ended, and its file is
  // written now, so that only the live tracks are held.
  for (auto it = s.tracks.begin(); it != s.tracks.end();) {
    if (it->second.last_frame == frame_idx) {
      ++it;
      continue;
    }
    FinishTrack(&s, it->first, &it->second);
    it = s.tracks.erase(it);
  }
}

void TrcExport::FinishTrack(Sequence* s, int track_id, Track* track) {
  if (track->out != nullptr) {
    track->out->flush();
    if (!*track->out) throw InputError(track->part.string() + ": write failed (" + io::WriteFailureReason(track->part, errno) + ")");
    track->out.reset();
    --s->open;
  }
  WriteFile(*s, track_id, *track);
  ++s->files;
}

void TrcExport::WriteFile(const Sequence& s, int track_id, const Track& track) {
  double rate = s.fps;
  // Without it, the camera's rate: 1 / the median step between the sequence's frame times (a mean
  // over a pause gave 22.47 for a 25 Hz camera, and tracks of one run different rates).
  if (!(rate > 0) && !s.steps.empty()) {
    std::vector<double> steps = s.steps;
    const auto middle = steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2);
    std::nth_element(steps.begin(), middle, steps.end());
    if (*middle > 0) rate = 1.0 / *middle;
  }
  if (!(rate > 0) && track.rows > 1 && track.last_time_s > track.first_time_s) {
    rate = (track.rows - 1) / (track.last_time_s - track.first_time_s);
  }
  // Without the sequence's fps the rows were numbered by frame index (the rate is known only now):
  // they are numbered here from their times at `rate`, as with an fps, so that Frame# / DataRate
  // agrees with Time after the frames the input skipped.
  const bool renumber = !(s.fps > 0) && rate > 0;
  const long first_number =
      renumber ? 1 + std::lround((track.first_time_s - s.first_time_s) * rate) : track.first_number;
  std::string name = s.name + "_track" + std::to_string(track_id) + ".trc";
  if (written_names_.count(name) > 0) {  // the track came back
    name = s.name + "_track" + std::to_string(track_id) + "_from" + std::to_string(first_number) + ".trc";
  }
  written_names_.insert(name);
  io::WriteTextFile(dir_ / name, io::NamedBy::kRpt, [&](std::ostream& out) {
    out << "PathFileType\t4\t(X/Y/Z)\t" << name << "\n";
    out << "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n";
    const std::string rate_text = GeneralText(rate, 10);  // printf's "%.10g" in the C locale (29.97002997 stays)
    out << rate_text << "\t" << rate_text << "\t" << track.rows << "\t" << s.joints.size() << "\t"
        << (options_.trc_millimetres ? "mm" : "m") << "\t" << rate_text << "\t" << first_number << "\t" << track.rows
        << "\n";
    out << "Frame#\tTime";
    for (const std::string& joint : s.joints) out << "\t" << TrcField(joint) << "\t\t";
    out << "\n\t";
    for (size_t j = 1; j <= s.joints.size(); ++j) out << "\tX" << j << "\tY" << j << "\tZ" << j;
    out << "\n\n";
    std::ifstream in(track.part, std::ios::binary);
    if (!in) throw InputError(track.part.string() + ": cannot read back: " + std::strerror(errno));
    if (!renumber) {
      if (in.peek() != std::ifstream::traits_type::eof()) out << in.rdbuf();
      return;
    }
    std::string line;
    long last = 0;
    for (long row = 0; std::getline(in, line); ++row) {  // "<index + 1>\t<time>\t..." as Frame() wrote it
      const size_t number_end = line.find('\t');
      double time_s = 0;
      if (number_end == std::string::npos ||
          std::from_chars(line.data() + number_end + 1,
                          line.data() + std::min(line.find('\t', number_end + 1), line.size()), time_s)
                  .ec != std::errc()) {
        throw InputError(track.part.string() + ": row " + std::to_string(row + 1) + " is not as written");
      }
      long number = row == 0 ? first_number : 1 + std::lround((time_s - s.first_time_s) * rate);
      if (row > 0) number = std::max(number, last + 1);  // never back, as with an fps
      last = number;
      // C-locale digits whatever the stream's locale, as Frame() writes them.
      out << std::to_string(number) << std::string_view(line).substr(number_end) << "\n";
    }
  });
}

void TrcExport::EndSequence(int sequence) {
  Sequence& s = sequences_[sequence];
  for (auto& [id, track] : s.tracks) FinishTrack(&s, id, &track);
  s.tracks.clear();
}

std::string NoTrcFileWarning(const TrcExport& trc, const std::filesystem::path& dir, long persons,
                             const std::string& how_to_time) {
  if (trc.files() > 0 || persons <= 0) return "";
  return PrintableText(dir.string(), LineBreaks::kEscape) +
         ": no TRC file written: no person was tracked (TRC holds tracks, and tracking needs the frames' times: " +
         how_to_time + ")";
}

}  // namespace rpt::engine
