// SPDX-License-Identifier: MIT
// rpt triangulate --follow end to end on a generated scene: its detections fed through a pipe one
// line at a time, each output line read before the next input line is written (so every frame
// must come out flushed on its own), equal to the offline `rpt triangulate` of the same detections
// (persons, track ids, provenance, times), also in the --out run folder (rpt report says the stream
// is not read again); the time from --fps as offline; a named pipe; bad lines exit 2 naming the
// line, --skip-bad-lines counts them; Ctrl-C ends cleanly with exit 130.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "datasets/calibration/calibration.h"
#include "datasets/readers/generic_detections.h"
#include "engine/input.h"
#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr double kFps = 25.0;
constexpr int kFrames = 24;

// The generated scene's detections (all its joints), frame ids "take_<f>".
Detections SceneDetections(std::vector<Camera>* cameras) {
  engine::InputSpec spec;
  spec.dataset = "synthetic";
  spec.params = {"frames=" + std::to_string(kFrames), "people=3", "cameras=4"};
  InputWarnings warnings;
  std::vector<Sequence> sequences = engine::LoadInput(spec, {}, &warnings);
  const Sequence& scene = sequences.at(0);
  *cameras = scene.cameras;
  Detections detections;
  detections.joints = scene.detection_joints;
  for (size_t f = 0; f < scene.frames.size(); ++f) {
    FrameDetections frame;
    frame.frame_id = "take_" + std::to_string(f);
    for (size_t c = 0; c < scene.cameras.size(); ++c) {
      frame.cameras.push_back(scene.cameras[c].name);
      frame.views.push_back(scene.frames[f].views[c]);
    }
    detections.frames.push_back(std::move(frame));
  }
  return detections;
}

std::string JointsLine(const Detections& detections) { return Json{{"joints", detections.joints}}.dump(); }

// Frame f as a line; with_time: "time": f / kFps.
std::string FrameLine(const Detections& detections, size_t f, bool with_time) {
  const FrameDetections& frame = detections.frames[f];
  Json views = Json::array();
  for (size_t c = 0; c < frame.views.size(); ++c) {
    Json poses = Json::array();
    for (int p = 0; p < frame.views[c].num_persons(); ++p) {
      Json joints = Json::array();
      const auto person = frame.views[c].Person(p);
      for (int j = 0; j < frame.views[c].num_joints; ++j) {
        joints.push_back(person(2, j) > 0 ? Json{person(0, j), person(1, j), person(2, j)} : Json());
      }
      poses.push_back(std::move(joints));
    }
    views.push_back({{"camera", frame.cameras[c]}, {"poses", std::move(poses)}});
  }
  Json line = {{"id", frame.frame_id}, {"views", std::move(views)}};
  if (with_time) line["time"] = static_cast<double>(f) / kFps;
  return line.dump();
}

// `rpt <args>` with a pipe to its stdin and one from its stdout; stderr into a file.
class Child {
 public:
  // out_pipe_bytes > 0: the output pipe's capacity (F_SETPIPE_SZ; at least a page).
  Child(const std::string& args, const fs::path& err, int out_pipe_bytes = 0) {
    int in[2], out[2];
    EXPECT_EQ(pipe(in), 0);
    EXPECT_EQ(pipe(out), 0);
    if (out_pipe_bytes > 0) {
      EXPECT_GT(fcntl(out[1], F_SETPIPE_SZ, out_pipe_bytes), 0);
    }
    pid_ = fork();
    if (pid_ == 0) {
      dup2(in[0], STDIN_FILENO);
      dup2(out[1], STDOUT_FILENO);
      const int err_fd = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      dup2(err_fd, STDERR_FILENO);
      for (int fd : {in[0], in[1], out[0], out[1], err_fd}) close(fd);
      const std::string command = "exec " + std::string(RPT_BINARY) + " " + args;
      execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
      _exit(127);
    }
    close(in[0]);
    close(out[1]);
    in_ = in[1];
    out_ = out[0];
  }
  ~Child() {
    CloseInput();
    if (out_ >= 0) close(out_);
    if (pid_ > 0) Wait();
  }

  void WriteLine(const std::string& line) {
    const std::string text = line + "\n";
    ASSERT_EQ(write(in_, text.data(), text.size()), static_cast<ssize_t>(text.size()));
  }
  void CloseInput() {
    if (in_ >= 0) close(in_);
    in_ = -1;
  }
  // The next output line, or "<timeout>" when none comes within 60 s (a line not flushed).
  std::string ReadLine() {
    while (true) {
      const size_t newline = buffer_.find('\n');
      if (newline != std::string::npos) {
        std::string line = buffer_.substr(0, newline);
        buffer_.erase(0, newline + 1);
        return line;
      }
      pollfd fd{out_, POLLIN, 0};
      if (poll(&fd, 1, 60000) <= 0) return "<timeout>";
      char chunk[65536];
      const ssize_t n = read(out_, chunk, sizeof(chunk));
      if (n <= 0) return "<end>";
      buffer_.append(chunk, static_cast<size_t>(n));
    }
  }
  void Signal(int signal_number) { kill(pid_, signal_number); }
  // Whether the process ended within `seconds` (then Wait() returns its code at once); else it is
  // killed (SIGKILL) and false returned.
  bool EndsWithin(double seconds) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (std::chrono::steady_clock::now() < until) {
      if (waitpid(pid_, &status_, WNOHANG) == pid_) {
        ended_ = true;
        return true;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    kill(pid_, SIGKILL);
    return false;
  }
  // Everything left in the output pipe, once the process has ended.
  std::string RestOfOutput() {
    std::string rest = buffer_;
    buffer_.clear();
    char chunk[65536];
    for (ssize_t n; (n = read(out_, chunk, sizeof(chunk))) > 0;) rest.append(chunk, static_cast<size_t>(n));
    return rest;
  }
  // The exit code (-1 when killed by a signal).
  int Wait() {
    if (!ended_) waitpid(pid_, &status_, 0);
    pid_ = -1;
    return WIFEXITED(status_) ? WEXITSTATUS(status_) : -1;
  }

 private:
  pid_t pid_ = -1;
  int status_ = 0;
  bool ended_ = false;
  int in_ = -1, out_ = -1;
  std::string buffer_;
};

class Follow : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::TempDir("follow");
    std::vector<Camera> cameras;
    detections_ = SceneDetections(&cameras);
    WriteCalibration(dir_ / "cameras.json", cameras);
    WriteGenericDetections(dir_ / "detections.json", detections_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string Cameras() const { return (dir_ / "cameras.json").string(); }

  // The offline run's predictions.json.
  Json Offline() {
    const fs::path out = dir_ / "offline";
    const test::CommandResult r =
        test::RunRpt("triangulate --cameras " + Cameras() + " --detections " + (dir_ / "detections.json").string() +
                     " --fps 25 --quiet --out " + out.string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return Json::parse(test::ReadAll(out / "predictions.json"));
  }

  // Writes the lines (joints line first) to a file and returns its path.
  fs::path LinesFile(const std::string& name, const std::vector<std::string>& frame_lines) {
    std::ofstream out(dir_ / name);
    out << JointsLine(detections_) << "\n";
    for (const std::string& line : frame_lines) out << line << "\n";
    return dir_ / name;
  }

  fs::path dir_;
  Detections detections_;
};

TEST_F(Follow, FrameByFrameThroughAPipeEqualsTheOfflineRun) {
  const Json offline = Offline();
  ASSERT_EQ(offline["frames"].size(), static_cast<size_t>(kFrames));
  const fs::path run = dir_ / "follow_run";
  Child child("triangulate --follow - --cameras " + Cameras() + " --out " + run.string(), dir_ / "err.txt");
  child.WriteLine(JointsLine(detections_));
  const Json header = Json::parse(child.ReadLine());
  EXPECT_EQ(header["joints"], offline["joints"]);
  EXPECT_EQ(header["units"]["position"], "m");
  EXPECT_EQ(header["units"]["time"], "s");
  int persons = 0, tracked = 0;
  for (int f = 0; f < kFrames; ++f) {
    child.WriteLine(FrameLine(detections_, static_cast<size_t>(f), /*with_time=*/true));
    const std::string line = child.ReadLine();  // before the next frame goes in
    ASSERT_NE(line, "<timeout>") << "frame " << f << " was not written on its own";
    const Json frame = Json::parse(line);
    EXPECT_EQ(frame, offline["frames"][f]) << "frame " << f;
    persons += static_cast<int>(frame["persons"].size());
    for (const Json& id : frame["track_ids"]) tracked += id.get<int>() >= 0 ? 1 : 0;
  }
  child.CloseInput();
  EXPECT_EQ(child.ReadLine(), "<end>");
  EXPECT_EQ(child.Wait(), 0);
  const std::string err = test::ReadAll(dir_ / "err.txt");
  EXPECT_NE(err.find("stdin: " + std::to_string(kFrames + 1) + " lines, " + std::to_string(kFrames) + " frames"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("end of input"), std::string::npos) << err;
  EXPECT_NE(err.find("line in -> line out"), std::string::npos) << err;
  EXPECT_GT(persons, 2 * kFrames) << "about three persons per frame";
  EXPECT_EQ(tracked, persons) << "every person tracked: the times are known";
  // --out: the run folder holds the same frames.
  const Json written = Json::parse(test::ReadAll(run / "predictions.json"));
  EXPECT_EQ(written["frames"], offline["frames"]);
  // rpt report on it: the recorded tables; the stream is not read again, and it says why.
  const test::CommandResult report = test::RunRpt("report " + run.string());
  EXPECT_EQ(report.exit_code, 0) << report.err;
  EXPECT_NE(report.err.find("the run read a live stream"), std::string::npos) << report.err;
}

TEST_F(Follow, TimesFromFpsAndANamedPipe) {
  const Json offline = Offline();
  const fs::path fifo = dir_ / "detections.fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // rpt opens the pipe before its writer does (the wait is in poll(), not in open()); it sleeps at
  // once when no line is there (--spin-us 0; the test above polls first, the default).
  Child child("triangulate --follow " + fifo.string() + " --fps 25 --spin-us 0 --cameras " + Cameras(),
              dir_ / "err.txt");
  // Written from another thread while this one reads the output: neither pipe can fill up.
  std::thread writer([&] {
    std::ofstream out(fifo);
    out << JointsLine(detections_) << "\n";
    for (int f = 0; f < kFrames; ++f) out << FrameLine(detections_, static_cast<size_t>(f), false) << "\n";
  });
  child.ReadLine();  // the joints line
  for (int f = 0; f < kFrames; ++f) EXPECT_EQ(Json::parse(child.ReadLine()), offline["frames"][f]) << "frame " << f;
  writer.join();
  EXPECT_EQ(child.Wait(), 0) << test::ReadAll(dir_ / "err.txt");
}

TEST_F(Follow, ABadLineIsAnErrorNamingItsLine) {
  const std::string good = FrameLine(detections_, 0, true);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"views\": [{\"camera\": \"nope\", \"poses\": []}]}",
       "stdin:3: /views/0/camera: camera 'nope' is not in the calibration"},
      {"{\"views\": [}", "stdin:3: column 12: expected"},
      {"{\"views\": [{\"camera\": \"cam0\", \"poses\": [[[1, 2, 0.5]]]}]}",
       "stdin:3: /views/0/poses/0: 1 joints, expected "},
      {"{\"views\": [{\"camera\": \"cam0\", \"poses\": [[[1, 2]]]}]}",
       "stdin:3: /views/0/poses/0/0: expected [x, y, score] or null"},
      {"{\"id\": \"x\"}", "stdin:3: /views: missing"},
      {good, "stdin:3: /id: frame id 'take_0' repeats one of the last 1024 frames"},
      {"{\"time\": \"soon\", \"views\": []}", "stdin:3: /time: expected the time in seconds"},
  };
  for (const auto& [bad, message] : cases) {
    const fs::path lines = LinesFile("bad.jsonl", {good, bad, FrameLine(detections_, 1, true)});
    const test::CommandResult r =
        test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " + lines.string());
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find("error: " + message), std::string::npos) << bad << "\n" << r.err;
    // The frame before the bad line was written (the joints line and one frame), and said.
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 2) << bad << "\n" << r.out;
    EXPECT_NE(r.err.find("stdin: 3 lines read, 1 frames written to stdout before the error\nerror: "),
              std::string::npos)
        << r.err;
  }
  const fs::path no_joints = dir_ / "no_joints.jsonl";
  std::ofstream(no_joints) << good << "\n";
  const test::CommandResult r =
      test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " + no_joints.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("stdin:1: column"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the first line is {\"joints\": [names]}"), std::string::npos) << r.err;
}

// Times in milliseconds where seconds are expected (a tester's stream: 2 people, 180 track ids,
// no word): every frame is farther than track.max_gap_s from the last, so every track ends; the
// run says so once at the end. Seconds (the same lines) give no such warning.
TEST_F(Follow, TimesInMillisecondsAreNamedInAWarning) {
  std::vector<std::string> seconds, milliseconds;
  for (int f = 0; f < kFrames; ++f) {
    Json line = Json::parse(FrameLine(detections_, static_cast<size_t>(f), true));
    seconds.push_back(line.dump());
    line["time"] = line["time"].get<double>() * 1000;
    milliseconds.push_back(line.dump());
  }
  const std::string warning = "frames more than track.max_gap_s (1.0 s) after the previous frame, at regular steps "
                              "of milliseconds' size: are the times in milliseconds?";
  const test::CommandResult ms = test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " +
                                              LinesFile("ms.jsonl", milliseconds).string());
  EXPECT_EQ(ms.exit_code, 0) << ms.err;
  EXPECT_NE(ms.err.find("warning: stdin: " + std::to_string(kFrames - 1) + " " + warning), std::string::npos) << ms.err;
  EXPECT_NE(ms.err.find("(largest step in s = 40)"), std::string::npos) << ms.err;
  const test::CommandResult s = test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " +
                                             LinesFile("s.jsonl", seconds).string());
  EXPECT_EQ(s.exit_code, 0) << s.err;
  EXPECT_EQ(s.err.find("max_gap_s"), std::string::npos) << s.err;
  // With a frame rate the steps are compared with its period: 40 s steps at --fps 25 are 1000 periods.
  const test::CommandResult fps = test::RunRpt("triangulate --follow - --fps 25 --cameras " + Cameras() + " < " +
                                               LinesFile("ms.jsonl", milliseconds).string());
  EXPECT_NE(fps.err.find(warning), std::string::npos) << fps.err;
  const test::CommandResult other = test::RunRpt("triangulate --follow - --fps 10 --cameras " + Cameras() + " < " +
                                                 LinesFile("ms.jsonl", milliseconds).string());
  EXPECT_EQ(other.err.find("max_gap_s"), std::string::npos) << "40 s steps at 10 fps are not milliseconds: " << other.err;
}

// A detector restarted by its supervisor (`while true; do detector; done | rpt ...`) writes its
// joints line again and counts its frame ids from the start: a restart, not a bad line (it ended the
// run, or --skip-bad-lines dropped up to 1024 frames).
TEST_F(Follow, AWriterThatRestartsIsFollowedOn) {
  std::vector<std::string> lines;  // after the joints line LinesFile writes
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      // Blanks around it and between its tokens (Python's json.dumps writes ", " and ": ") are no
      // difference: it was refused unless byte for byte the first line.
      std::string spaced;
      for (const char c : JointsLine(detections_)) spaced += c == ',' ? ", " : c == ':' ? ": " : std::string(1, c);
      lines.push_back(" " + spaced + " ");
    }
    for (int f = 0; f < 5; ++f) lines.push_back(FrameLine(detections_, static_cast<size_t>(f), true));
  }
  const test::CommandResult r = test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " +
                                             LinesFile("restart.jsonl", lines).string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("12 lines, 10 frames"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("warning: stdin: 1 restarts of the writer (its joints line again)"), std::string::npos) << r.err;
  // Other joints after the first line are still an error.
  lines[5] = Json{{"joints", {"nose"}}}.dump();
  const test::CommandResult other = test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " +
                                                 LinesFile("other.jsonl", lines).string());
  EXPECT_EQ(other.exit_code, 2);
  EXPECT_NE(other.err.find("stdin:7: /joints: a joints line after the first line that is not the first line again"),
            std::string::npos)
      << other.err;
}

// A live stream's end, where the warnings are counted, may be hours away: the first bad line and
// times in milliseconds are said as they happen (here: before the input ends).
TEST_F(Follow, WarningsAreSaidAsTheyHappen) {
  Child child("triangulate --follow - --skip-bad-lines --cameras " + Cameras(), dir_ / "err.txt");
  child.WriteLine(JointsLine(detections_));
  for (int f = 0; f < 12; ++f) {
    if (f == 3) child.WriteLine("not a frame");
    Json line = Json::parse(FrameLine(detections_, static_cast<size_t>(f), true));
    line["time"] = line["time"].get<double>() * 1000;
    child.WriteLine(line.dump());
    ASSERT_NE(child.ReadLine(), "<timeout>") << "frame " << f;
  }
  const std::string early = test::ReadAll(dir_ / "err.txt");  // the input is still open
  EXPECT_NE(early.find("warning: a bad line skipped (the first of --skip-bad-lines): stdin:5: "), std::string::npos)
      << early;
  EXPECT_NE(early.find("warning: stdin: 10 frames more than track.max_gap_s (1.0 s) after the previous frame, at "
                       "regular steps of milliseconds' size"),
            std::string::npos)
      << "checked at the 10th step: " << early;
  EXPECT_NE(early.find("(said as it happens; counted at the end)"), std::string::npos) << early;
  child.CloseInput();
  EXPECT_EQ(child.Wait(), 0);
  const std::string all = test::ReadAll(dir_ / "err.txt");
  EXPECT_NE(all.find("warning: stdin: 11 frames more than track.max_gap_s"), std::string::npos) << "the count at the end: " << all;
  EXPECT_NE(all.find("warning: stdin: 1 bad lines skipped"), std::string::npos) << all;
}

// A misnamed time key turned tracking off for the whole stream, said only at its end: the unknown
// key (with the name meant) and the frame without a time are said at the first frame.
TEST_F(Follow, AnUnknownKeyAndAFrameWithoutTimeAreSaidAtOnce) {
  Child child("triangulate --follow - --cameras " + Cameras(), dir_ / "err.txt");
  child.WriteLine(JointsLine(detections_));
  for (int f = 0; f < 3; ++f) {
    Json line = Json::parse(FrameLine(detections_, static_cast<size_t>(f), true));
    line["timestamp"] = line["time"];
    line.erase("time");
    child.WriteLine(line.dump());
    ASSERT_NE(child.ReadLine(), "<timeout>") << "frame " << f;
  }
  const std::string early = test::ReadAll(dir_ / "err.txt");  // the input is still open
  EXPECT_NE(early.find("warning: stdin:2: frame lines with the unknown key 'timestamp' (did you mean 'time'?), not "
                       "read (said as it happens; counted at the end)"),
            std::string::npos)
      << early;
  EXPECT_NE(early.find("warning: stdin:2: a frame without a time, and no --fps"), std::string::npos) << early;
  child.CloseInput();
  EXPECT_EQ(child.Wait(), 0);
  const std::string all = test::ReadAll(dir_ / "err.txt");
  EXPECT_NE(all.find("warning: stdin: 3 frame lines with the unknown key 'timestamp' (did you mean 'time'?)"),
            std::string::npos)
      << all;
}

// As in a detections file (Triangulate.JointsAtPixelZeroAreMissing): a joint at pixel (0, 0) with
// a score is missing, counted at the end; the output equals that of the lines with score 0 there.
TEST_F(Follow, JointsAtPixelZeroAreMissing) {
  std::vector<std::string> origin, missing;
  for (int f = 0; f < kFrames; ++f) {
    Json line = Json::parse(FrameLine(detections_, static_cast<size_t>(f), true));
    line["views"][0]["poses"][0][9] = Json{0.0, 0.0, 0.8};
    origin.push_back(line.dump());
    line["views"][0]["poses"][0][9] = nullptr;
    missing.push_back(line.dump());
  }
  const test::CommandResult o = test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " +
                                             LinesFile("origin.jsonl", origin).string());
  ASSERT_EQ(o.exit_code, 0) << o.err;
  EXPECT_NE(o.err.find("warning: stdin: " + std::to_string(kFrames) + " detected joints at pixel (0, 0) with a score "
                       "above 0 read as missing"),
            std::string::npos)
      << o.err;
  const test::CommandResult m = test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " +
                                             LinesFile("missing.jsonl", missing).string());
  ASSERT_EQ(m.exit_code, 0) << m.err;
  EXPECT_EQ(o.out, m.out);
}

// Detections in another pixel frame than the calibration's gave a live run that found nobody, or
// wrong persons, without a word (the file's run warns): the stream's joints are checked against
// each camera's image as a file's are, and a run that triangulated nobody says what to check.
TEST_F(Follow, DetectionsInNormalisedCoordinatesAreNamed) {
  std::vector<Camera> cameras = ReadCalibration(Cameras()).cameras;
  std::vector<std::string> normalised;
  for (int f = 0; f < kFrames; ++f) {
    Json line = Json::parse(FrameLine(detections_, static_cast<size_t>(f), true));
    for (Json& view : line["views"]) {
      const Camera& camera = *std::find_if(cameras.begin(), cameras.end(),
                                           [&](const Camera& c) { return c.name == view["camera"].get<std::string>(); });
      for (Json& person : view["poses"]) {
        for (Json& joint : person) {
          if (joint.is_null()) continue;
          joint[0] = joint[0].get<double>() / camera.width;
          joint[1] = joint[1].get<double>() / camera.height;
        }
      }
    }
    normalised.push_back(line.dump());
  }
  const test::CommandResult r = test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " +
                                             LinesFile("normalised.jsonl", normalised).string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const Camera& camera : cameras) {
    EXPECT_NE(r.err.find(" detected joints of camera '" + camera.name + "', all within 1.5 pixels of the origin"),
              std::string::npos)
        << r.err;
  }
  EXPECT_NE(r.err.find("warning: no person was triangulated in any of the " + std::to_string(kFrames) + " frames"),
            std::string::npos)
      << r.err;
  // The same stream in pixels: neither is said.
  std::vector<std::string> pixels;
  for (int f = 0; f < kFrames; ++f) pixels.push_back(FrameLine(detections_, static_cast<size_t>(f), true));
  const test::CommandResult p = test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " +
                                             LinesFile("pixels.jsonl", pixels).string());
  ASSERT_EQ(p.exit_code, 0) << p.err;
  EXPECT_EQ(p.err.find("warning"), std::string::npos) << p.err;
}

// A camera the stream never names (its detector never started) is said, as a file's reader says
// it (live it was silent, offline warned; robotics tester); the stream with every camera says
// nothing (DetectionsInNormalisedCoordinatesAreNamed).
TEST_F(Follow, ACameraTheStreamNeverNamesIsSaid) {
  const std::vector<Camera> cameras = ReadCalibration(Cameras()).cameras;
  std::vector<std::string> lines;
  for (int f = 0; f < kFrames; ++f) {
    Json line = Json::parse(FrameLine(detections_, static_cast<size_t>(f), true));
    Json views = Json::array();
    for (const Json& view : line["views"]) {
      if (view["camera"] != cameras[0].name) views.push_back(view);
    }
    line["views"] = views;
    lines.push_back(line.dump());
  }
  const test::CommandResult r = test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " +
                                             LinesFile("without_first.jsonl", lines).string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find(": 1 cameras of the calibration the detections never name, so nothing of theirs in any frame "
                       "(cameras " + cameras[0].name + "): triangulated from the others"),
            std::string::npos)
      << r.err;
}

TEST_F(Follow, SkipBadLinesCountsThem) {
  std::vector<std::string> lines;
  for (int f = 0; f < 6; ++f) lines.push_back(FrameLine(detections_, static_cast<size_t>(f), true));
  // Lines 3, 5, 6 and 12 are bad (the joints line is line 1); line 7 is blank.
  lines.insert(lines.begin() + 1, "not json");
  lines.insert(lines.begin() + 3, "{\"views\": [{\"camera\": \"nope\", \"poses\": []}]}");
  lines.insert(lines.begin() + 4, lines[0]);  // a repeated id
  lines.insert(lines.begin() + 5, "   ");
  lines.push_back("[1, 2]");
  const fs::path file = LinesFile("skip.jsonl", lines);
  const test::CommandResult r =
      test::RunRpt("triangulate --follow - --skip-bad-lines --cameras " + Cameras() + " < " + file.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1 + 6) << r.out;
  EXPECT_NE(r.err.find("warning: stdin: 4 bad lines skipped (the first: stdin:3: column 1: expected"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("stdin: 12 lines, 6 frames"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("4 bad line(s) skipped"), std::string::npos) << r.err;
  // Without the flag the first bad line ends the run.
  const test::CommandResult strict =
      test::RunRpt("triangulate --follow - --cameras " + Cameras() + " < " + file.string());
  EXPECT_EQ(strict.exit_code, 2);
  EXPECT_NE(strict.err.find("error: stdin:3: column 1: "), std::string::npos) << strict.err;
}

// A frame the triangulator would refuse for its size is a bad line: named by its line, and with
// --skip-bad-lines skipped, so one burst of false detections does not end the stream.
TEST_F(Follow, AFrameTooLargeIsABadLine) {
  std::string pose = "[";
  for (size_t j = 0; j < detections_.joints.size(); ++j) pose += std::string(j > 0 ? ", " : "") + "[100, 200, 0.9]";
  pose += "]";
  std::string poses = pose;
  for (int p = 1; p < 5; ++p) poses += ", " + pose;  // 5 poses; the scene's frames have 3 people
  const std::string crowd = "{\"views\": [{\"camera\": \"cam0\", \"poses\": [" + poses + "]}]}";
  const fs::path file =
      LinesFile("crowd.jsonl", {FrameLine(detections_, 0, true), crowd, FrameLine(detections_, 1, true)});
  const std::string run = "triangulate --follow - --cameras " + Cameras() +
                          " --set triangulate.max_persons_per_view=4 < " + file.string();
  const test::CommandResult stopped = test::RunRpt(run);
  EXPECT_EQ(stopped.exit_code, 2);
  EXPECT_NE(stopped.err.find("error: stdin:3: view 0 (camera 'cam0') has 5 2D poses, above "
                             "triangulate.max_persons_per_view (4)"),
            std::string::npos)
      << stopped.err;
  const test::CommandResult skipped = test::RunRpt(run + " --skip-bad-lines");
  EXPECT_EQ(skipped.exit_code, 0) << skipped.err;
  EXPECT_EQ(std::count(skipped.out.begin(), skipped.out.end(), '\n'), 1 + 2) << skipped.out;
  EXPECT_NE(skipped.err.find("1 bad line(s) skipped"), std::string::npos) << skipped.err;
}

TEST_F(Follow, CtrlCEndsCleanlyAfterTheFramesInHand) {
  Child child("triangulate --follow - --cameras " + Cameras(), dir_ / "err.txt");
  child.WriteLine(JointsLine(detections_));
  child.ReadLine();
  for (int f = 0; f < 3; ++f) {
    child.WriteLine(FrameLine(detections_, static_cast<size_t>(f), true));
    ASSERT_NE(child.ReadLine(), "<timeout>");
  }
  child.Signal(SIGINT);  // the input stays open: the signal ends the run, not the end of the input
  EXPECT_EQ(child.ReadLine(), "<end>");
  EXPECT_EQ(child.Wait(), 130);
  const std::string err = test::ReadAll(dir_ / "err.txt");
  EXPECT_NE(err.find("stdin: 4 lines, 3 frames"), std::string::npos) << err;
  EXPECT_NE(err.find("stopped by SIGINT"), std::string::npos) << err;
}

// A reader that stops taking the output (its pipe full) cannot hold a stop: Ctrl-C ends the run
// 2 s later (it waited in write() until the reader woke, for ever if it never did); every line the
// reader gets is complete, and stderr says the last frame's line was not written.
TEST_F(Follow, CtrlCEndsTheRunWhenTheReaderStopsTakingTheOutput) {
  Child child("triangulate --follow - --cameras " + Cameras(), dir_ / "err.txt", 4096);
  child.WriteLine(JointsLine(detections_));
  for (int f = 0; f < 10; ++f) child.WriteLine(FrameLine(detections_, static_cast<size_t>(f), true));
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // it fills the 4 KB pipe and waits
  child.Signal(SIGTERM);
  const auto signalled = std::chrono::steady_clock::now();
  ASSERT_TRUE(child.EndsWithin(30)) << "still running 30 s after SIGTERM";
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - signalled).count(), 10.0);
  EXPECT_EQ(child.Wait(), 143);
  const std::string out = child.RestOfOutput();
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.back(), '\n');
  std::istringstream lines(out);
  int count = 0;
  for (std::string line; std::getline(lines, line); ++count) {
    EXPECT_TRUE(Json::accept(line)) << line;
  }
  EXPECT_LT(count, 11) << "the reader took no line: not all were written";
  const std::string err = test::ReadAll(dir_ / "err.txt");
  EXPECT_NE(err.find("warning: stdout did not take the output for 2 s after the stop: the last frame's line was not "
                     "written"),
            std::string::npos)
      << err;
  EXPECT_NE(err.find("stopped by SIGTERM"), std::string::npos) << err;
}

// Names from someone else (a file and a folder named with a terminal escape sequence) reach the
// terminal escaped, offline and live: the sequence's name in the summary line, the results folder,
// the progress label.
TEST_F(Follow, NamesReachTheTerminalEscaped) {
  const std::string hostile = "take\x1b[2J";
  const fs::path detections = dir_ / (hostile + ".json");
  fs::copy_file(dir_ / "detections.json", detections);
  const fs::path lines =
      LinesFile(hostile + ".jsonl", {FrameLine(detections_, 0, true), FrameLine(detections_, 1, true)});
  const std::string out = (dir_ / ("out_" + hostile)).string();
  const test::CommandResult offline = test::RunRpt("triangulate --cameras " + Cameras() + " --detections '" +
                                                   detections.string() + "' --fps 25 --out '" + out + "'");
  const test::CommandResult live = test::RunRpt("triangulate --cameras " + Cameras() + " --follow '" + lines.string() +
                                                "' --out '" + out + "_live'");
  for (const test::CommandResult* r : {&offline, &live}) {
    ASSERT_EQ(r->exit_code, 0) << r->err;
    EXPECT_EQ(r->out.find('\x1b'), std::string::npos) << r->out;
    EXPECT_EQ(r->err.find('\x1b'), std::string::npos) << r->err;
  }
  EXPECT_NE(offline.out.find("results in " + (dir_ / "out_take\\x1b[2J").string()), std::string::npos) << offline.out;
  EXPECT_NE(live.err.find("take\\x1b[2J: 3 lines, 2 frames"), std::string::npos) << live.err;
  EXPECT_NE(live.err.find("results in " + (dir_ / "out_take\\x1b[2J_live").string()), std::string::npos) << live.err;
}

// A file that a detector is still writing, followed like tail -f: lines appended after the run
// started are triangulated as they come (a line written in two parts waits for its newline), and
// Ctrl-C ends the run; with a finite wait, the run ends that long after the last line.
TEST_F(Follow, AGrowingFileIsFollowedWithWaitForLines) {
  const Json offline = Offline();
  const fs::path file = LinesFile("growing.jsonl", {FrameLine(detections_, 0, true)});
  Child child("triangulate --follow " + file.string() + " --cameras " + Cameras() + " --wait-for-lines inf",
              dir_ / "err.txt");
  ASSERT_NE(child.ReadLine(), "<timeout>");  // the header
  EXPECT_EQ(Json::parse(child.ReadLine()), offline["frames"][0]);
  const auto append = [&](const std::string& text) {
    std::ofstream out(file, std::ios::app);
    out << text;
  };
  append(FrameLine(detections_, 1, true) + "\n");
  const std::string second = child.ReadLine();
  ASSERT_NE(second, "<timeout>") << "a line appended to the file was not read";
  EXPECT_EQ(Json::parse(second), offline["frames"][1]);
  const std::string third = FrameLine(detections_, 2, true);
  append(third.substr(0, third.size() / 2));
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  append(third.substr(third.size() / 2) + "\n");
  const std::string line = child.ReadLine();
  ASSERT_NE(line, "<timeout>");
  EXPECT_EQ(Json::parse(line), offline["frames"][2]) << "the line written in two parts is read whole";
  child.Signal(SIGINT);
  EXPECT_EQ(child.ReadLine(), "<end>");
  EXPECT_EQ(child.Wait(), 130);
  const std::string err = test::ReadAll(dir_ / "err.txt");
  EXPECT_NE(err.find("growing: 4 lines, 3 frames"), std::string::npos) << err;

  // A finite wait: the run ends by itself after it (exit 0), every line triangulated; without
  // the wait the same file ends at once.
  const auto start = std::chrono::steady_clock::now();
  const test::CommandResult waited = test::RunRpt("triangulate --follow " + file.string() + " --cameras " + Cameras() +
                                                  " --wait-for-lines 0.4");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_EQ(waited.exit_code, 0) << waited.err;
  EXPECT_GE(seconds, 0.4) << "the run did not wait at the end of the file";
  EXPECT_NE(waited.err.find("growing: 4 lines, 3 frames"), std::string::npos) << waited.err;
  EXPECT_NE(waited.err.find("end of input"), std::string::npos) << waited.err;
}

// A followed file that shrinks (truncated, rewritten) is an error, not frames read from the
// middle of other lines; a wait on a pipe, a negative wait, and a wait without --follow too.
TEST_F(Follow, WaitForLinesMistakes) {
  const fs::path file = LinesFile("shrinking.jsonl", {FrameLine(detections_, 0, true)});
  Child child("triangulate --follow " + file.string() + " --cameras " + Cameras() + " --wait-for-lines 60",
              dir_ / "err.txt");
  ASSERT_NE(child.ReadLine(), "<timeout>");  // the header
  ASSERT_NE(child.ReadLine(), "<timeout>");  // frame 0: the run waits at the end now
  fs::resize_file(file, 10);
  EXPECT_EQ(child.ReadLine(), "<end>");
  EXPECT_EQ(child.Wait(), 2);
  const std::string err = test::ReadAll(dir_ / "err.txt");
  EXPECT_NE(err.find("shrinking.jsonl: the file shrank from "), std::string::npos) << err;
  EXPECT_NE(err.find(" to 10 bytes while its end was waited on"), std::string::npos) << err;

  const std::string base = "triangulate --cameras " + Cameras();
  for (const auto& [args, message] : std::vector<std::pair<std::string, std::string>>{
           {" --follow - --wait-for-lines 5 < /dev/null", "--wait-for-lines: stdin is not a regular file"},
           {" --follow " + file.string() + " --wait-for-lines -1", "--wait-for-lines -1.0: expected seconds >= 0"},
           {" --detections " + (dir_ / "detections.json").string() + " --wait-for-lines 5",
            "--wait-for-lines: only with --follow"}}) {
    const test::CommandResult r = test::RunRpt(base + args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
}

TEST_F(Follow, OptionsThatDoNotFit) {
  const std::string base = "triangulate --follow - --cameras " + Cameras();
  for (const auto& [extra, message] : std::vector<std::pair<std::string, std::string>>{
           {" --detections x.json", "--detections: not with --follow"},
           {" --json", "--json: not with --follow"},
           {" --rename-camera cam0=a", "the detection mapping flags (--map-*, --coco-*, --openpose-joints, "
                                       "--rename-camera, ...): not with --follow"}}) {
    const test::CommandResult r = test::RunRpt(base + extra + " < /dev/null");
    EXPECT_EQ(r.exit_code, 2) << extra;
    EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  }
  const test::CommandResult no_cameras = test::RunRpt("triangulate --follow - < /dev/null");
  EXPECT_EQ(no_cameras.exit_code, 2);
  EXPECT_NE(no_cameras.err.find("--follow needs --cameras"), std::string::npos) << no_cameras.err;
  const test::CommandResult skip = test::RunRpt("triangulate --skip-bad-lines --cameras " + Cameras() +
                                                " --detections " + (dir_ / "detections.json").string());
  EXPECT_EQ(skip.exit_code, 2);
  EXPECT_NE(skip.err.find("--skip-bad-lines: only with --follow"), std::string::npos) << skip.err;
  const test::CommandResult spin = test::RunRpt("triangulate --spin-us 0 --cameras " + Cameras() + " --detections " +
                                                (dir_ / "detections.json").string());
  EXPECT_EQ(spin.exit_code, 2);
  EXPECT_NE(spin.err.find("--spin-us: only with --follow"), std::string::npos) << spin.err;
  const test::CommandResult negative = test::RunRpt(base + " --spin-us -1 < /dev/null");
  EXPECT_EQ(negative.exit_code, 2);
  EXPECT_NE(negative.err.find("--spin-us -1: expected a time >= 0"), std::string::npos) << negative.err;
}

}  // namespace
}  // namespace rpt
