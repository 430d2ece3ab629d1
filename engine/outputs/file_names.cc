// SPDX-License-Identifier: MIT
#include "engine/outputs/file_names.h"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <unordered_set>

namespace rpt::engine {

std::string FileNameOf(const std::string& text) {
  static const char* const kHex = "0123456789ABCDEF";
  constexpr size_t kMaxBytes = 200, kCutAt = 180;  // file systems allow 255 bytes; room for ".png" and "~2"
  if (text.empty()) return "%";
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (std::isalnum(c) || c == '-' || c == '_' || (c == '.' && i > 0)) {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 0xf];
    }
  }
  if (out.size() <= kMaxBytes) return out;
  size_t cut = kCutAt;
  while (cut > 0 && (out[cut - 1] == '%' || (cut > 1 && out[cut - 2] == '%'))) --cut;  // never inside a %XX
  std::uint64_t hash = 14695981039346656037ull;                                        // FNV-1a over the whole text
  for (const char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
  char suffix[24];
  std::snprintf(suffix, sizeof(suffix), "~%016llx", static_cast<unsigned long long>(hash));
  return out.substr(0, cut) + suffix;
}

std::vector<std::string> UniqueFileNames(const std::vector<std::string>& texts) {
  std::vector<std::string> names;
  std::unordered_set<std::string> taken;  // lower case: "Cam" and "cam" are one file on some file systems
  const auto lower = [](std::string name) {
    for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return name;
  };
  for (const std::string& text : texts) {
    const std::string name = FileNameOf(text);
    std::string unique = name;
    for (int n = 2; !taken.insert(lower(unique)).second; ++n) unique = name + "~" + std::to_string(n);
    names.push_back(unique);
  }
  return names;
}

}  // namespace rpt::engine
