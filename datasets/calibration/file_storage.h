// SPDX-License-Identifier: MIT
// OpenCV cv::FileStorage files (YAML, XML, JSON) read into plain values and written, for the
// OpenCV and EasyMocap calibration readers and writers. Every OpenCV call happens here, inside a
// try: a cv::Exception (a parse error, a damaged file) becomes an InputError naming the file and
// the line or the node.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace rpt::file_storage {

// One top-level node of the file.
struct Value {
  enum class Kind {
    kNumber,   // an integer or real
    kString,   // a string
    kNumbers,  // a matrix (!!opencv-matrix, or a map with "data") or a (nested) sequence of numbers
    kStrings,  // a sequence of strings
    kOther,    // anything else (empty, mixed, nested maps): only named in messages
  };
  Kind kind = Kind::kOther;
  std::vector<double> numbers;       // kNumber: one; kNumbers: row-major
  std::vector<std::string> strings;  // kString: one
};

// The top-level nodes of a file in file order.
struct File {
  std::string source;  // the path, for messages
  std::vector<std::pair<std::string, Value>> nodes;

  // The node called `key`, or nullptr.
  const Value* Find(const std::string& key) const;
  // The first of `keys` that exists (its name in *found), or nullptr.
  const Value* FindAny(const std::vector<std::string>& keys, std::string* found) const;

  // The numbers of node `key`, exactly `count` of them ("3x3" etc. in `shape` for messages).
  // Throws InputError "<source>: <key>: expected <shape> numbers, got ..." otherwise; also when
  // a number is NaN or infinite.
  std::vector<double> Numbers(const std::string& key, std::size_t count, const std::string& shape) const;
  // Any number of numbers (for distortion coefficients).
  std::vector<double> AnyNumbers(const std::string& key) const;
  double Number(const std::string& key) const;
  // An integer in [min_value, max_value].
  int Integer(const std::string& key, int min_value, int max_value) const;
  std::string String(const std::string& key) const;
  std::vector<std::string> Strings(const std::string& key) const;
};

// OpenCV 4.6's YAML parser loops forever on some damaged files (e.g. "   - a\n\"\nK"): the text is
// parsed in a child process first (io::RunInChild), bounded by this limit.
inline constexpr std::chrono::milliseconds kParseLimit{5000};

// Reads a FileStorage file (YAML with or without the %YAML header, XML, JSON). Throws InputError
// "<path>: file not found", "<path>:<line>: <OpenCV's parse error>", "<path>: not an OpenCV
// FileStorage file (...)", or "<path>: OpenCV's FileStorage parser did not finish (crashed) ...".
File ReadFile(const std::filesystem::path& path, std::chrono::milliseconds parse_limit = kParseLimit);

// A FileStorage text being written; YAML, or XML when `xml`. Keys OpenCV refuses (only letters,
// digits, '-', '_' and ' ') throw InputError "<source>: cannot write <key>: ...".
class Writer {
 public:
  Writer(bool xml, const std::string& source);
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  // A rows x cols !!opencv-matrix of doubles (dt d, written exactly), row-major values.
  void Matrix(const std::string& key, int rows, int cols, const std::vector<double>& values);
  void Integer(const std::string& key, int value);
  void String(const std::string& key, const std::string& value);
  void Strings(const std::string& key, const std::vector<std::string>& values);
  // The text written so far, ended.
  std::string Finish();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace rpt::file_storage
