// SPDX-License-Identifier: MIT
// Private helper for the dataset readers: load a JSON file with parse errors that name the
// file, line and column, and fetch typed values at JSON pointers with errors that name
// the file and the pointer, e.g.
//   "calibration_shelf.json: /0/R: expected 3x3 array of numbers".
// Internal to rpt_datasets (it exposes nlohmann::json, which is a private dependency).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace rpt::io {

inline constexpr std::size_t kAnyCount = std::numeric_limits<std::size_t>::max();

// The one guarded path of every JSON file rpt reads (configs, thresholds, sweep lists and shards,
// run folders, labels, detections, calibrations): the file is read by io::detail::ReadFileBytes
// (a regular file within the input size limit, io/input_limits.h) and parsed with
//  * a depth limit checked while parsing: an array or object nested deeper than kMaxJsonDepth ends
//    the parse with "<source>:<line>:<column>: JSON nested deeper than 256 levels" (the values
//    built so far are never serialised or destroyed recursively beyond that depth);
//  * parse errors that quote at most kMaxQuotedBytes of the offending token.
// No format rpt reads nests deeper than 6 levels.
inline constexpr int kMaxJsonDepth = 256;
inline constexpr std::size_t kMaxQuotedBytes = 40;

// Throws InputError "<path>: file not found" or "<path>:<line>:<column>: JSON parse error: ...".
nlohmann::json LoadJsonFile(const std::filesystem::path& path);
// The same keeping the order of object members (the run folder files `rpt report` shows).
nlohmann::ordered_json LoadOrderedJsonFile(const std::filesystem::path& path);
// Same for text already in memory; `source` names it in messages.
nlohmann::json ParseJsonText(std::string_view text, const std::string& source);
// Throws the InputError ParseJsonText would throw for `text`, without building the document.
void CheckJsonText(std::string_view text, const std::string& source);

// A value for a message: its JSON text, cut to at most `max_bytes` bytes (at a UTF-8 character
// boundary, then "...") while it is written, so a large or deep value costs no more than that.
std::string JsonExcerpt(const nlohmann::json& value, std::size_t max_bytes = kMaxQuotedBytes);
std::string JsonExcerpt(const nlohmann::ordered_json& value, std::size_t max_bytes = kMaxQuotedBytes);
// The byte ranges [first, second) of the elements of the top-level array of `text`, which must be
// valid JSON (CheckJsonText); nullopt when the top-level value is not an array. Lets a reader keep
// a long list as its text and parse one element at a time.
std::optional<std::vector<std::pair<std::size_t, std::size_t>>> JsonArrayElements(std::string_view text);

// "/a/b" + "c" -> "/a/b/c" (escaping '~' and '/'), "/a" + 3 -> "/a/3".
std::string JsonPointerJoin(std::string_view base, std::string_view token);
std::string JsonPointerJoin(std::string_view base, std::size_t index);

// The value at `pointer` ("" is the whole document), or nullptr when absent.
const nlohmann::json* JsonFind(const nlohmann::json& root, const std::string& pointer);
// The value at `pointer`; throws "<source>: <pointer>: missing" when absent.
const nlohmann::json& JsonAt(const nlohmann::json& root, const std::string& pointer, const std::string& source);

double JsonNumber(const nlohmann::json& root, const std::string& pointer, const std::string& source);
// An integer: a JSON integer or an integral float, within the int64 range. Anything else, including
// 2^63 + 5 (stored by nlohmann as an unsigned) and 1e30, throws InputError naming the pointer.
std::int64_t JsonInt(const nlohmann::json& root, const std::string& pointer, const std::string& source);
// JsonInt within [min_value, max_value] ("<source>: <pointer>: 70000 is not an integer in [0, 65535]").
std::int64_t JsonIntIn(const nlohmann::json& root, const std::string& pointer, const std::string& source,
                       std::int64_t min_value, std::int64_t max_value);
// The value as an int64 when it is an integer (or integral float) inside the int64 range.
std::optional<std::int64_t> JsonToInt64(const nlohmann::json& j);
bool JsonBool(const nlohmann::json& root, const std::string& pointer, const std::string& source);
std::string JsonString(const nlohmann::json& root, const std::string& pointer, const std::string& source);
// A flat array of numbers, optionally of an exact length.
std::vector<double> JsonNumbers(const nlohmann::json& root, const std::string& pointer, const std::string& source,
                                std::size_t expected_count = kAnyCount);
// A rows x cols matrix, row-major. Accepts nested [[..], ..] of rows x cols and, for the
// files that store matrices flat, a flat array of rows*cols numbers.
std::vector<double> JsonMatrix(const nlohmann::json& root, const std::string& pointer, const std::string& source,
                               std::size_t rows, std::size_t cols);
// The keys of a JSON object (calibration files keyed by camera id) in the order nlohmann stores
// them (lexicographic), re-sorted numerically when every key is a small non-negative integer.
std::vector<std::string> JsonObjectKeysNumericOrder(const nlohmann::json& object);
// Calls per_camera(id, pointer) for each member of a calibration file keyed by camera id, in the
// order of JsonObjectKeysNumericOrder. Throws InputError naming `source` when root is not a
// non-empty object or a member is not an object; `members` says what a member holds ("R, T, fx").
void ForEachJsonCamera(const nlohmann::json& root, const std::string& source, const std::string& members,
                       const std::function<void(const std::string& id, const std::string& pointer)>& per_camera);

}  // namespace rpt::io
