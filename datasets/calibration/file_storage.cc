// SPDX-License-Identifier: MIT
#include "datasets/calibration/file_storage.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/errors.h"
#include "core/printable_text.h"
#include "datasets/io/child_process.h"

namespace rpt::file_storage {
namespace {

constexpr int kMaxNesting = 2;  // numbers in a sequence of sequences (rows), no deeper

bool IsNumber(const cv::FileNode& node) { return node.isInt() || node.isReal(); }

double NumberOf(const cv::FileNode& node) {
  return node.isInt() ? static_cast<double>(static_cast<int>(node)) : static_cast<double>(node);
}

// Appends the numbers of a sequence (of sequences) of numbers; false when something else is in it.
bool AppendNumbers(const cv::FileNode& node, int depth, std::vector<double>* out) {
  if (IsNumber(node)) {
    out->push_back(NumberOf(node));
    return true;
  }
  if (!node.isSeq() || depth >= kMaxNesting) return false;
  for (cv::FileNodeIterator it = node.begin(); it != node.end(); ++it) {
    if (!AppendNumbers(*it, depth + 1, out)) return false;
  }
  return true;
}

Value ToValue(const cv::FileNode& node) {
  Value value;
  if (IsNumber(node)) {
    value.kind = Value::Kind::kNumber;
    value.numbers = {NumberOf(node)};
  } else if (node.isString()) {
    value.kind = Value::Kind::kString;
    value.strings = {node.string()};
  } else if (node.isMap()) {
    // !!opencv-matrix (rows, cols, dt, data) or a plain map with "data" (ROS camera_info).
    const cv::FileNode data = node["data"];
    if (data.isSeq() && AppendNumbers(data, 1, &value.numbers)) value.kind = Value::Kind::kNumbers;
  } else if (node.isSeq()) {
    if (node.size() > 0 && (*node.begin()).isString()) {
      value.kind = Value::Kind::kStrings;
      for (cv::FileNodeIterator it = node.begin(); it != node.end(); ++it) {
        if (!(*it).isString()) return Value{};
        value.strings.push_back((*it).string());
      }
    } else if (AppendNumbers(node, 0, &value.numbers)) {
      value.kind = Value::Kind::kNumbers;
    }
  }
  if (value.kind == Value::Kind::kOther) value.numbers.clear();
  return value;
}

std::string KindName(const Value& value) {
  switch (value.kind) {
    case Value::Kind::kNumber:
      return "a number";
    case Value::Kind::kString:
      return "a string";
    case Value::Kind::kNumbers:
      return std::to_string(value.numbers.size()) + " numbers";
    case Value::Kind::kStrings:
      return "a list of strings";
    case Value::Kind::kOther:
      break;
  }
  return "no number, string or matrix";
}

// OpenCV's message of a cv::Exception: parse errors carry "<name>(<line>): <what>" in `func`
// (cv::FileStorage::Impl::parseError passes its arguments in that order).
std::string Describe(const cv::Exception& e, const std::string& source, int line_offset) {
  if (e.code == cv::Error::StsParseError) {
    const std::string& text = e.func;
    const std::size_t open = text.find('(');
    const std::size_t close = text.find("): ", open == std::string::npos ? 0 : open);
    if (open != std::string::npos && close != std::string::npos) {
      const std::string digits = text.substr(open + 1, close - open - 1);
      if (!digits.empty() && digits.size() < 10 && digits.find_first_not_of("0123456789") == std::string::npos) {
        const int line = std::max(1, std::stoi(digits) - line_offset);
        return source + ":" + std::to_string(line) + ": " + text.substr(close + 3) + " (OpenCV FileStorage parser)";
      }
    }
    return source + ": " + text + " (OpenCV FileStorage parser)";
  }
  return source + ": not a readable OpenCV FileStorage file (OpenCV: " + e.err + ")";
}

}  // namespace

const Value* File::Find(const std::string& key) const {
  for (const auto& [name, value] : nodes) {
    if (name == key) return &value;
  }
  return nullptr;
}

const Value* File::FindAny(const std::vector<std::string>& keys, std::string* found) const {
  for (const std::string& key : keys) {
    if (const Value* value = Find(key)) {
      *found = key;
      return value;
    }
  }
  return nullptr;
}

std::vector<double> File::AnyNumbers(const std::string& key) const {
  const Value* value = Find(key);
  if (value == nullptr) throw InputError(source + ": " + key + ": missing");
  if (value->kind != Value::Kind::kNumbers && value->kind != Value::Kind::kNumber) {
    throw InputError(source + ": " + key + ": expected numbers (a matrix or a list), got " + KindName(*value));
  }
  for (const double v : value->numbers) {
    if (!std::isfinite(v)) throw InputError(source + ": " + key + ": a value is NaN or infinite");
  }
  return value->numbers;
}

std::vector<double> File::Numbers(const std::string& key, std::size_t count, const std::string& shape) const {
  std::vector<double> numbers = AnyNumbers(key);
  if (numbers.size() != count) {
    throw InputError(source + ": " + key + ": expected " + shape + " numbers, got " + std::to_string(numbers.size()));
  }
  return numbers;
}

double File::Number(const std::string& key) const { return Numbers(key, 1, "1")[0]; }

int File::Integer(const std::string& key, int min_value, int max_value) const {
  const double v = Number(key);
  if (!(v >= min_value && v <= max_value) || v != std::floor(v)) {
    throw InputError(source + ": " + key + ": expected an integer in [" + std::to_string(min_value) + ", " +
                     std::to_string(max_value) + "], got " + std::to_string(v));
  }
  return static_cast<int>(v);
}

std::string File::String(const std::string& key) const {
  const Value* value = Find(key);
  if (value == nullptr) throw InputError(source + ": " + key + ": missing");
  if (value->kind != Value::Kind::kString)
    throw InputError(source + ": " + key + ": expected a string, got " + KindName(*value));
  return value->strings[0];
}

std::vector<std::string> File::Strings(const std::string& key) const {
  const Value* value = Find(key);
  if (value == nullptr) throw InputError(source + ": " + key + ": missing");
  if (value->kind == Value::Kind::kString) return value->strings;  // a list of one written as a scalar
  if (value->kind != Value::Kind::kStrings) {
    throw InputError(source + ": " + key + ": expected a list of strings, got " + KindName(*value));
  }
  return value->strings;
}

File ReadFile(const std::filesystem::path& path, std::chrono::milliseconds parse_limit) {
  File file;
  file.source = path.string();
  std::ifstream in(path, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(path, ec)) throw InputError(file.source + ": file not found or unreadable");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) text.erase(0, 3);  // UTF-8 byte order mark
  if (text.find('\0') != std::string::npos) throw InputError(file.source + ": not a text file (it holds a NUL byte)");
  // OpenCV tells the format by the first bytes: %YAML, <?xml (or <opencv_storage>), {. YAML
  // written by other tools (ROS camera_info, by hand) has no %YAML header: one is added, and the
  // line numbers of parse errors are counted back.
  int line_offset = 0;
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  const bool known_start =
      first != std::string::npos && (text.compare(first, 5, "%YAML") == 0 || text[first] == '<' || text[first] == '{');
  if (!known_start) {
    text = "%YAML:1.0\n" + text;
    line_offset = 1;
  }
  // First in a child process: OpenCV's parsers can loop forever (or crash) on a damaged file. Any
  // ending of the child but a timeout or a crash lets the parse below run and report.
  const io::ChildOutcome trial = io::RunInChild(
      [&text] {
        try {
          const cv::FileStorage storage(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
          return 0;
        } catch (...) {
          return 1;
        }
      },
      parse_limit);
  if (trial.kind == io::ChildOutcome::Kind::kTimedOut) {
    throw InputError(file.source + ": OpenCV's FileStorage parser did not finish within " + io::LimitText(parse_limit) +
                     ": the file is damaged; rpt did not read it");
  }
  if (trial.kind == io::ChildOutcome::Kind::kSignaled) {
    throw InputError(file.source + ": OpenCV's FileStorage parser crashed (" + io::SignalName(trial.signal) +
                     "): the file is damaged; rpt did not read it");
  }
  try {
    cv::FileStorage storage(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
    if (!storage.isOpened()) throw InputError(file.source + ": not a readable OpenCV FileStorage file");
    const cv::FileNode root = storage.root();
    if (!root.isMap()) {
      throw InputError(file.source + ": expected keys and values at the top level (a map), not " +
                       (root.isSeq() ? "a sequence" : "a single value"));
    }
    for (cv::FileNodeIterator it = root.begin(); it != root.end(); ++it) {
      const cv::FileNode node = *it;
      file.nodes.emplace_back(node.name(), ToValue(node));
    }
  } catch (const cv::Exception& e) {
    throw InputError(Describe(e, file.source, line_offset));
  } catch (const std::length_error& e) {
    // OpenCV 4.6's YAML parser computes a negative key length for some damaged files (e.g.
    // "   o:3\n   :") and throws this from std::string instead of a parse error.
    throw InputError(file.source + ": not a readable OpenCV FileStorage file (OpenCV's parser failed: " + e.what() +
                     ")");
  }
  return file;
}

struct Writer::Impl {
  cv::FileStorage storage;
  std::string source;

  // Throws InputError naming `key` when `value` holds a control character: OpenCV writes it as it
  // is, and its reader cuts the text there ("cam\x01x" came back as "cam").
  void CheckText(const std::string& key, const std::string& value) const {
    const bool control = std::any_of(value.begin(), value.end(), [](char c) {
      const auto byte = static_cast<unsigned char>(c);
      return byte < 0x20 || byte == 0x7f;
    });
    if (control) {
      throw InputError(source + ": cannot write " + key + " " + QuoteName(value) +
                       ": OpenCV's files cannot hold control characters (its reader cuts the text there); rename it "
                       "or write json or toml");
    }
  }

  // Runs `write`; a cv::Exception (a key OpenCV refuses) becomes an InputError naming the key.
  template <class Write>
  void Guard(const std::string& key, Write&& write) {
    try {
      write();
    } catch (const cv::Exception& e) {
      throw InputError(source + ": cannot write " + key + ": " + e.err);
    }
  }
};

Writer::Writer(bool xml, const std::string& source) : impl_(std::make_unique<Impl>()) {
  impl_->source = source;
  impl_->Guard("the header",
               [&] { impl_->storage.open(xml ? ".xml" : ".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY); });
}

Writer::~Writer() = default;

void Writer::Matrix(const std::string& key, int rows, int cols, const std::vector<double>& values) {
  cv::Mat m(rows, cols, CV_64F);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) m.at<double>(r, c) = values[static_cast<std::size_t>(r * cols + c)];
  }
  impl_->Guard(key, [&] { impl_->storage.write(key, m); });
}

void Writer::Integer(const std::string& key, int value) {
  impl_->Guard(key, [&] { impl_->storage.write(key, value); });
}

// write() rather than <<, which reads strings starting with '[', '{', ']' or '}' as structure marks.
void Writer::String(const std::string& key, const std::string& value) {
  impl_->CheckText(key, value);
  impl_->Guard(key, [&] { impl_->storage.write(key, value); });
}

void Writer::Strings(const std::string& key, const std::vector<std::string>& values) {
  for (const std::string& value : values) impl_->CheckText(key, value);
  impl_->Guard(key, [&] {
    impl_->storage.startWriteStruct(key, cv::FileNode::SEQ);
    for (const std::string& value : values) impl_->storage.write("", value);
    impl_->storage.endWriteStruct();
  });
}

std::string Writer::Finish() {
  std::string text;
  impl_->Guard("the end", [&] { text = impl_->storage.releaseAndGetString(); });
  return text;
}

}  // namespace rpt::file_storage
