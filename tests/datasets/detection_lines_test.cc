// SPDX-License-Identifier: MIT
// The live input's parts: io::JsonPull accepts and refuses what nlohmann's parser does (on texts
// chosen at the grammar's edges) and decodes strings the same way; io::LineReader hands out lines
// as they arrive (a last line without newline, CRLF, a too-long line dropped, a stop request ends
// the wait); OpenDetectionLines reads frames exactly (values, cameras in calibration order, ids,
// times) and names the line and place of each kind of bad line.
#include <gtest/gtest.h>

#include <atomic>

#include <fcntl.h>
#include <unistd.h>

#include <charconv>
#include <cstring>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "core/errors.h"
#include "datasets/io/json_pull.h"
#include "datasets/io/line_reader.h"
#include "datasets/readers/detection_lines.h"
#include "tests/error_message.h"

namespace rpt {
namespace {

using Json = nlohmann::json;

// Walks any JSON value with the pull parser, rebuilding it as a nlohmann value.
Json PullValue(io::JsonPull& json) {
  switch (json.Peek()) {
    case io::JsonPull::Kind::kObject: {
      Json object = Json::object();
      json.BeginObject();
      std::string_view key;
      while (json.NextKey(&key)) {
        const std::string name(key);
        object[name] = PullValue(json);
      }
      return object;
    }
    case io::JsonPull::Kind::kArray: {
      Json array = Json::array();
      json.BeginArray();
      while (json.NextElement()) array.push_back(PullValue(json));
      return array;
    }
    case io::JsonPull::Kind::kString:
      return std::string(json.String());
    case io::JsonPull::Kind::kNumber:
      return json.Number();
    case io::JsonPull::Kind::kTrue:
      json.Skip();
      return true;
    case io::JsonPull::Kind::kFalse:
      json.Skip();
      return false;
    case io::JsonPull::Kind::kNull:
      json.Skip();
      return nullptr;
    case io::JsonPull::Kind::kEnd:
      break;
  }
  throw InputError("no value");
}

TEST(JsonPull, AcceptsAndRefusesWhatNlohmannDoes) {
  const std::vector<std::string> texts = {
      "{}", "[]", " [ 1 , 2 ] ", "{\"a\": [1, -0, 0.5, -1.25e-3, 2E+2, 1e0]}", "[true, false, null]",
      "\"\\u00e9\\ud83d\\ude00 \\\" \\\\ \\/ \\b\\f\\n\\r\\t\"", "\"caf\xc3\xa9\"", "[[[[]]]]",
      // refused
      "", "[1,]", "[,1]", "{\"a\" 1}", "{\"a\": 1,}", "{1: 2}", "[01]", "[1.]", "[.5]", "[+1]", "[1e]", "[-]", "[NaN]",
      "[Infinity]", "[tru]", "[nulll]", "\"a", "\"\\x\"", "\"\\u12\"", "\"\\ud800\"", "\"\\udc00x\"", "\"a\tb\"",
      "\"\xff\"", "\"\xc3\"", "[1] 2", "[1]]", "{\"a\": 1}}", "[1e400]",
      // digit runs with a byte just outside '0'..'9' ('/' and ':') in the eight bytes after the point
      // (eight digits there send the number to std::from_chars) and elsewhere
      "[12345678:]", "[1234567:8]", "[1234567/8]", "[0.1234567:9]", "[0.12345678/]", "[12345678.1234567:]",
      "[:2345678]", "[1234567890123456]", "[0.12345678901234567]", "[-98765432.10987654]",
      // eight decimals or more (read by std::from_chars without a second check of their start)
      "[1.123456789e5]", "[1.12345678E+5]", "[-0.123456789e-3]", "[1.123456789e]", "[1.123456789e+]", "[01.123456789]",
      "[-01.123456789]", "[1.123456789.5]", "[1.12345678x]", "[1.123456789e400]", "[-1.123456789e-400]"};
  for (const std::string& text : texts) {
    bool nlohmann_accepts = true;
    Json expected;
    try {
      expected = Json::parse(text);
    } catch (const Json::exception&) {
      nlohmann_accepts = false;
    }
    bool accepts = true;
    Json pulled;
    try {
      io::JsonPull json(text);
      pulled = PullValue(json);
      json.End();
    } catch (const InputError&) {
      accepts = false;
    }
    if (text == "[1e400]" || text == "[1.123456789e400]") {  // nlohmann reads infinity; rpt's numbers are finite
      EXPECT_FALSE(accepts);
      continue;
    }
    EXPECT_EQ(accepts, nlohmann_accepts) << text;
    if (accepts && nlohmann_accepts) {
      EXPECT_EQ(pulled, expected) << text;
    }
  }
}

// Numbers as detectors write them (a few decimals, full precision, integers, tiny and huge values)
// read bit for bit as std::from_chars reads them, whichever path (the short-decimal fast path or
// from_chars) takes them.
TEST(JsonPull, NumbersEqualFromChars) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> pixels(-50, 4000);
  std::vector<std::string> texts = {"0",
                                    "-0",
                                    "0.5",
                                    "1e-400",
                                    "123456789012345678901234",
                                    "9007199254740993",
                                    "0.30000000000000004",
                                    "1.123456789e5",
                                    "-1.1234567890123456e-5",
                                    "4.9406564584124654e-324",
                                    "2.2250738585072014e-308",
                                    "1.7976931348623157e308"};
  for (int i = 0; i < 20000; ++i) {
    const double x = pixels(random) * (i % 7 == 0 ? 1e-9 : 1.0);
    char text[64];
    const char* formats[] = {"%.3f", "%.17g", "%.16g", "%.1f", "%.0f", "%.22f", "%.6e"};
    std::snprintf(text, sizeof(text), formats[i % 7], x);
    texts.push_back(text);
  }
  // Digit runs of every length from 1 to 24 before and after the point (up to seven decimals take
  // the short-decimal path, eight or more std::from_chars), with random digits and with all nines,
  // alone and followed by more text.
  std::uniform_int_distribution<int> digit(0, 9);
  for (int integer = 1; integer <= 24; ++integer) {
    for (int fraction = 0; fraction <= 24; ++fraction) {
      for (int kind = 0; kind < 3; ++kind) {
        std::string text = kind == 2 ? "-" : "";
        for (int i = 0; i < integer; ++i)
          text += static_cast<char>('0' + (kind == 1 ? 9 : (i == 0 ? 1 + digit(random) % 9 : digit(random))));
        if (fraction > 0) text += '.';
        for (int i = 0; i < fraction; ++i) text += static_cast<char>('0' + (kind == 1 ? 9 : digit(random)));
        texts.push_back(text);
      }
    }
  }
  for (const std::string& text : texts) {
    double expected = 0;
    std::from_chars(text.data(), text.data() + text.size(), expected);
    {  // followed by more text: the number ends at the first byte that is not part of it
      const std::string followed = "[" + text + "]";
      io::JsonPull json(followed);
      json.BeginArray();
      ASSERT_TRUE(json.NextElement());
      const double read = json.Number();
      EXPECT_EQ(std::memcmp(&read, &expected, sizeof(double)), 0) << followed;
      EXPECT_FALSE(json.NextElement()) << followed;
    }
    io::JsonPull json(text);
    const double read = json.Number();
    EXPECT_EQ(std::memcmp(&read, &expected, sizeof(double)), 0) << text << ": " << read << " vs " << expected;
    json.End();
  }
}

TEST(JsonPull, ErrorsNameTheColumn) {
  io::JsonPull json("[1, 2 x]");
  json.BeginArray();
  ASSERT_TRUE(json.NextElement());
  EXPECT_EQ(json.Number(), 1);
  ASSERT_TRUE(json.NextElement());
  EXPECT_EQ(json.Number(), 2);
  EXPECT_EQ(test::ErrorMessage([&] { json.NextElement(); }), "column 7: expected ',' or ']', got 'x'");
  io::JsonPull id("7 12.5");
  EXPECT_EQ(id.IntegerText(), "7");
  EXPECT_EQ(id.IntegerText(), "") << "12.5 is no integer and stays unread";
  EXPECT_EQ(id.Number(), 12.5);
  // What writers put where JSON has no value is named with what to write instead.
  io::JsonPull nan("[1, NaN]");
  nan.BeginArray();
  ASSERT_TRUE(nan.NextElement());
  EXPECT_EQ(nan.Number(), 1);
  ASSERT_TRUE(nan.NextElement());
  EXPECT_EQ(test::ErrorMessage([&] { nan.Number(); }),
            "column 5: expected a number, got 'NaN', which is not JSON (a missing joint is [null, null, 0] or has "
            "score 0; Python: json.dumps(..., allow_nan=False) finds them)");
  io::JsonPull bom("\xEF\xBB\xBF{}");
  EXPECT_EQ(test::ErrorMessage([&] { bom.BeginObject(); }),
            "column 1: expected an object '{', got a UTF-8 byte-order mark (write the text without it)");
}

// Lines written to a pipe by a thread, read by a LineReader.
std::vector<std::string> ReadLines(const std::string& text, size_t max_line_bytes,
                                   std::vector<io::LineReader::Result>* results,
                                   std::chrono::microseconds spin = std::chrono::microseconds(0)) {
  int fds[2];
  EXPECT_EQ(pipe(fds), 0);
  std::thread writer([&] {
    for (size_t i = 0; i < text.size(); i += 7) {  // in small pieces: lines arrive split
      EXPECT_GT(write(fds[1], text.data() + i, std::min<size_t>(7, text.size() - i)), 0);
    }
    close(fds[1]);
  });
  io::LineReader reader(fds[0], "pipe", max_line_bytes, nullptr);
  reader.set_spin(spin);
  std::vector<std::string> lines;
  std::string_view line;
  while (true) {
    const io::LineReader::Result result = reader.Next(&line);
    if (result == io::LineReader::Result::kEnd) break;
    results->push_back(result);
    lines.emplace_back(result == io::LineReader::Result::kLine ? std::string(line) : "<too long>");
    EXPECT_EQ(reader.line_number(), static_cast<long>(lines.size()));
  }
  writer.join();
  close(fds[0]);
  return lines;
}

TEST(LineReader, LinesAsTheyArrive) {
  std::vector<io::LineReader::Result> results;
  const std::vector<std::string> lines =
      ReadLines("first\r\n\nsecond line\n" + std::string(100, 'x') + "\nthird\nlast without newline", 40, &results);
  EXPECT_EQ(lines,
            (std::vector<std::string>{"first", "", "second line", "<too long>", "third", "last without newline"}));
  EXPECT_EQ(results[3], io::LineReader::Result::kTooLong);
}

// A line that never ends (a stream of zeros) is reported as too long once it passes the limit,
// while its writer is still writing; its rest is dropped up to its newline and reading goes on.
TEST(LineReader, ALineThatNeverEndsIsReportedAtTheLimit) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  std::atomic<bool> reported{false};
  std::thread writer([&] {
    const std::string chunk(64, 'a');
    for (int i = 0; i < 200 && !reported; ++i) {  // until the reader says it, at most 12.8 kB
      ASSERT_EQ(write(fds[1], chunk.data(), chunk.size()), static_cast<ssize_t>(chunk.size()));
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    EXPECT_TRUE(reported) << "the too-long line was not reported while it was written";
    const std::string rest = "still the same line\nnext\n";
    ASSERT_EQ(write(fds[1], rest.data(), rest.size()), static_cast<ssize_t>(rest.size()));
    close(fds[1]);
  });
  io::LineReader reader(fds[0], "pipe", 1000, nullptr);
  std::string_view line;
  EXPECT_EQ(reader.Next(&line), io::LineReader::Result::kTooLong);
  reported = true;
  EXPECT_EQ(reader.line_number(), 1);
  ASSERT_EQ(reader.Next(&line), io::LineReader::Result::kLine);
  EXPECT_EQ(line, "next");
  EXPECT_EQ(reader.line_number(), 2);
  EXPECT_EQ(reader.Next(&line), io::LineReader::Result::kEnd);
  writer.join();
  close(fds[0]);
}

TEST(LineReader, PollingBeforeSleepingReadsTheSameLines) {
  const std::string text = "first\r\n\nsecond line\n" + std::string(100, 'x') + "\nthird\nlast without newline";
  std::vector<io::LineReader::Result> sleeping, polling;
  const std::vector<std::string> expected = ReadLines(text, 40, &sleeping);
  // Polling for up to 10 s: the lines and the end of the stream come as they arrive, not after 10 s.
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(ReadLines(text, 40, &polling, std::chrono::seconds(10)), expected);
  EXPECT_EQ(polling, sleeping);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << "the end waited for the polling";
}

TEST(LineReader, AStopRequestEndsThePolling) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  auto stop = std::make_shared<io::StopRequest>();
  io::LineReader reader(fds[0], "pipe", 1000, stop);
  reader.set_spin(std::chrono::seconds(30));
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    stop->Request();
  });
  const auto start = std::chrono::steady_clock::now();
  std::string_view line;
  EXPECT_EQ(reader.Next(&line), io::LineReader::Result::kStopped);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10)) << "the stop waited for the polling";
  stopper.join();
  close(fds[0]);
  close(fds[1]);
}

TEST(LineReader, AStopRequestEndsTheWait) {
  int fds[2];
  ASSERT_EQ(pipe(fds), 0);
  auto stop = std::make_shared<io::StopRequest>();
  io::LineReader reader(fds[0], "pipe", 1000, stop);
  ASSERT_EQ(write(fds[1], "one\n", 4), 4);
  std::string_view line;
  ASSERT_EQ(reader.Next(&line), io::LineReader::Result::kLine);
  EXPECT_EQ(line, "one");
  std::thread stopper([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    stop->Request();
  });
  EXPECT_EQ(reader.Next(&line), io::LineReader::Result::kStopped) << "no input, the writer still open";
  stopper.join();
  close(fds[0]);
  close(fds[1]);
}

Camera TestCamera(const std::string& name) {
  Camera camera;
  camera.name = name;
  camera.K << 1000, 0, 320, 0, 1000, 240, 0, 0, 1;
  camera.t = Eigen::Vector3d(0, 0, 5);
  camera.width = 640;
  camera.height = 480;
  return camera;
}

// A source on `text` (the whole stream, from a pipe).
struct Stream {
  explicit Stream(const std::string& text, DetectionLinesOptions options = {}) {
    EXPECT_EQ(pipe(fds), 0);
    EXPECT_EQ(write(fds[1], text.data(), text.size()), static_cast<ssize_t>(text.size()));  // fits the pipe
    close(fds[1]);
    source = OpenDetectionLines({TestCamera("a"), TestCamera("b")},
                                std::make_unique<io::LineReader>(fds[0], "live", 1 << 20, nullptr), options,
                                "cams.json", &counts);
  }
  ~Stream() { close(fds[0]); }
  int fds[2];
  DetectionLinesCounts counts;
  std::unique_ptr<FrameSource> source;
};

TEST(DetectionLines, FramesAsWritten) {
  DetectionLinesOptions options;
  options.fps = 10;
  Stream stream(
      "{\"joints\": [\"nose\", \"neck\"]}\n"
      "{\"id\": 7, \"time\": 1.5, \"views\": [{\"poses\": [[[1, 2, 0.5], [null, null, 0]]], \"camera\": \"b\"}]}\n"
      "\n"
      "{\"views\": [{\"camera\": \"a\", \"poses\": [[[3, 4, 1.2], [5, 6, 0]], [null, [7, 8, 1]]]}, {\"camera\": \"b\", "
      "\"poses\": null}]}\n"
      "{\"id\": \"x\", \"time\": null, \"views\": []}\n",
      options);
  const SequenceHeader& header = stream.source->header();
  EXPECT_EQ(header.detection_joints, (JointNames{"nose", "neck"}));
  EXPECT_EQ(stream.source->num_frames(), -1);
  SequenceFrame frame;
  ASSERT_TRUE(stream.source->Next(&frame));
  EXPECT_EQ(frame.id, "7");
  EXPECT_EQ(frame.timestamp_s, 1.5);
  ASSERT_EQ(frame.views.size(), 2u);
  EXPECT_EQ(frame.views[0].num_persons(), 0);
  EXPECT_TRUE(frame.views[0].unavailable) << "camera a is not in the line: no data from it";
  EXPECT_FALSE(frame.views[1].unavailable);
  EXPECT_EQ(frame.views[1].data, (std::vector<double>{1, 2, 0.5, 0, 0, 0}));
  ASSERT_TRUE(stream.source->Next(&frame));
  EXPECT_EQ(frame.id, "4") << "the line number";
  EXPECT_EQ(frame.timestamp_s, 0.1) << "frame 1 at 10 fps";
  EXPECT_EQ(frame.views[0].data, (std::vector<double>{3, 4, 1, 5, 6, 0, 0, 0, 0, 7, 8, 1})) << "1.2 clamped to 1";
  EXPECT_EQ(frame.views[1].num_persons(), 0);
  EXPECT_FALSE(frame.views[0].unavailable || frame.views[1].unavailable) << "both listed (b with null: nobody)";
  ASSERT_TRUE(stream.source->Next(&frame));
  EXPECT_EQ(frame.id, "x");
  EXPECT_TRUE(std::isnan(frame.timestamp_s));
  EXPECT_EQ(frame.views[0].num_persons() + frame.views[1].num_persons(), 0);
  EXPECT_FALSE(stream.source->Next(&frame));
  EXPECT_EQ(stream.counts.lines, 5);
  EXPECT_EQ(stream.counts.frames, 3);
  std::vector<std::string> warnings;
  for (const InputWarning& w : stream.source->warnings().items()) warnings.push_back(w.Line());
  EXPECT_EQ(warnings,
            (std::vector<std::string>{"live: 1 scores above 1 clamped to 1 (largest = 1.2)",
                                      "live: 1 frames without times: nothing is carried between them (no "
                                      "tracking, no smoothing); give \"time\" in the lines or the rate with --fps"}));
}

TEST(DetectionLines, BadLinesNameTheLineAndThePlace) {
  const std::string joints = "{\"joints\": [\"nose\"]}\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"views\": [{\"camera\": \"c\", \"poses\": []}]}",
       "live:2: /views/0/camera: camera 'c' is not in the calibration cams.json (cameras: a, b)"},
      {"{\"views\": [{\"camera\": \"a\", \"poses\": []}, {\"camera\": \"a\", \"poses\": []}]}",
       "live:2: /views/1/camera: camera 'a' appears twice in this frame"},
      {"{\"views\": [{\"camera\": \"a\", \"poses\": [[[1, 2, 3]]]}]}",
       "live:2: /views/0/poses/0/0: score 3 outside [0, 1] (values up to 1.5 are clamped to 1)"},
      {"{\"views\": [{\"camera\": \"a\", \"poses\": [[[1, 2, 1], [1, 2, 1]]]}]}",
       "live:2: /views/0/poses/0: more than 1 joints (as many as the joints line names)"},
      {"{\"views\": [{\"camera\": \"a\"}]}", "live:2: /views/0/poses: missing (write [] for no detections)"},
      {"{\"views\": [], \"views\": []}", "live:2: /views: given twice"},
      {"{\"id\": \"\", \"views\": []}", "live:2: /id: empty id"},
      {"{\"id\": 1.5, \"views\": []}", "live:2: /id: expected a string or an integer id"},
      {"{\"joints\": [\"neck\"]}",  // the first line again would be a restart (Follow.AWriterThatRestartsIsFollowedOn)
       "live:2: /joints: a joints line after the first line that is not the first line again (a restarted writer "
       "repeats it as it was): the joints are given once, on the first line"},
      {"{\"views\": []} x", "live:2: column 15: unexpected 'x' after the end of the JSON value"},
  };
  for (const auto& [line, message] : cases) {
    Stream stream(joints + line + "\n");
    SequenceFrame frame;
    EXPECT_EQ(test::ErrorMessage([&] { stream.source->Next(&frame); }), message) << line;
  }
  EXPECT_EQ(test::ErrorMessage([] { Stream stream("{\"joints\": [\"nose\", \"nose\"]}\n"); }).substr(0, 10),
            "live:1: /j");
  EXPECT_EQ(test::ErrorMessage([] { Stream stream(""); }),
            "live:1: no joints line: the stream must start with {\"joints\": [names]}");
}

}  // namespace
}  // namespace rpt
