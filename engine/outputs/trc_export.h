// SPDX-License-Identifier: MIT
// TRC files for OpenSim (--export trc): one file per sequence and track, trc/<sequence>_track<id>.trc
// ('/' in a sequence name becomes '_'; untracked persons, id -1, are not written), one marker per
// joint, one row per frame the track is in:
//   PathFileType  4  (X/Y/Z)  <file name>
//   DataRate  CameraRate  NumFrames  NumMarkers  Units  OrigDataRate  OrigDataStartFrame  OrigNumFrames
//   <fps>  <fps>  <rows>  <joints>  m|mm  <fps>  <first frame + 1>  <rows>
//   Frame#  Time  <joint>\t\t\t ...
//           X1  Y1  Z1  X2 ...
//   (blank line)
//   <frame number>  <time_s>  x  y  z ...
// Tab-separated; a missing joint (or a filled one without ExportOptions::filled_joints) has empty
// fields. Axes per ExportOptions::trc_axes (y up for OpenSim: (x, z, -y)), units per
// trc_millimetres. With the sequence's fps the frame number is 1 + (time - the sequence's first
// time) x fps, rounded (frames the input skipped leave a gap in Frame#, as in Time: a tool that
// rebuilds time from Frame# / DataRate gets the rows' times), and the data rate is that fps; without
// it the rate is 1 / the median step between the sequence's frame times (the first 1000 steps; a
// pause does not lower it), else (one timed frame) the track's mean rate, and the frame numbers
// follow the times at that rate in the same way (numbered when the file is written, the rate being
// known then). OrigDataStartFrame is the track's first frame number.
// A frame with an unknown time is an InputError naming the sequence and the frame (a TRC row needs
// a time: give --fps). Streams, and memory holds the live tracks only: each track's rows go to a
// part file beside its target (at most kMaxOpenTrcParts open at once, others reopened to append),
// and a track's file (header and rows) is written as soon as a frame comes without it: a track is
// in every frame from its first to its end, coasting included (core/pipeline/track.h); the rest at
// EndSequence. Should a track id come back after its file was written, its later rows go to
// <sequence>_track<id>_from<frame#>.trc (told by the names this export wrote, not by the files in
// `dir`: a file of an earlier run there is replaced). `dir` should hold no TRC files of another
// run (RunFolder empties it; rpt.export.write removes them).
#pragma once

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "datasets/io/staged_output.h"
#include "engine/frame_sink.h"
#include "engine/outputs/export_options.h"

namespace rpt::engine {

inline constexpr int kMaxOpenTrcParts = 32;
inline constexpr size_t kRateSteps = 1000;

class TrcExport final : public FrameSink {
 public:
  // Writes into `dir` (created when the first file is written).
  TrcExport(std::filesystem::path dir, int num_sequences, ExportOptions options);
  ~TrcExport() override;

  void BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) override;
  void Frame(const FrameOutput& frame) override;
  void EndSequence(int sequence) override;

  // The files written so far.
  long files() const;

 private:
  struct Track {
    std::unique_ptr<io::ScratchFile> scratch;  // the rows so far
    std::filesystem::path part;                // its path
    std::unique_ptr<std::ofstream> out;  // null while closed
    long rows = 0;
    long last_frame = 0;  // the sequence's index of the track's last frame
    long first_number = 0, last_number = 0;  // Frame# of the first and last rows
    double first_time_s = 0, last_time_s = 0;
  };
  struct Sequence {
    std::string name;  // as a file name
    JointNames joints;
    double fps = 0;
    long frames = 0;
    long timed_frames = 0;  // frames with a known time, from first_time_s to last_time_s
    double first_time_s = 0, last_time_s = 0;
    std::vector<double> steps;  // the first kRateSteps steps between frame times, for the rate
    std::map<int, Track> tracks;  // the live ones
    int open = 0;
    long files = 0;
  };
  std::ofstream& TrackStream(Sequence* s, int track_id, double time_s);
  // Closes the track's part and writes its file.
  void FinishTrack(Sequence* s, int track_id, Track* track);
  void WriteFile(const Sequence& s, int track_id, const Track& track);

  std::filesystem::path dir_;
  bool folder_created_ = false;  // dir_ is made with the first track
  std::set<std::string> written_names_;  // the file names written, over all sequences
  ExportOptions options_;
  std::vector<Sequence> sequences_;
};

// TRC holds tracks only: "<dir>: no TRC file written: no person was tracked (...: <how_to_time>)"
// when `trc` wrote no file although the run output `persons` > 0 persons (times unknown); else "".
std::string NoTrcFileWarning(const TrcExport& trc, const std::filesystem::path& dir, long persons,
                             const std::string& how_to_time);

}  // namespace rpt::engine
