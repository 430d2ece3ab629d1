// SPDX-License-Identifier: MIT
#include "engine/output_place.h"

#include <algorithm>
#include <system_error>

#include "core/errors.h"
#include "core/printable_text.h"
#include "engine/input_digests.h"

namespace rpt::engine {
namespace {

namespace fs = std::filesystem;

// Whether `inner` is `outer` or lies below it (both absolute, normalised).
bool Within(const fs::path& inner, const fs::path& outer) {
  auto o = outer.begin(), i = inner.begin();
  for (; o != outer.end(); ++o, ++i) {
    if (o->empty()) continue;  // a trailing separator
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

fs::path Resolved(const fs::path& path) {
  std::error_code ec;
  fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
  return ec ? fs::absolute(path).lexically_normal() : resolved;
}

}  // namespace

void CheckOutputOutsideInput(const fs::path& out, const InputSpec& spec) {
  const fs::path place = Resolved(out);
  for (const std::string& input : InputPaths(spec)) {
    std::error_code ec;
    const fs::path resolved = Resolved(input);
    const bool folder = fs::is_directory(resolved, ec);
    const bool clash = folder ? Within(place, resolved) || Within(resolved, place) : place == resolved;
    if (!clash) continue;
    throw ConfigError("--out " + QuoteName(out.string()) + ": " +
                      (place == resolved ? std::string("is the input ")
                       : Within(place, resolved) ? std::string("lies inside the input folder ")
                                                 : std::string("holds the input ")) +
                      QuoteName(input) +
                      "; rpt does not write into its input (the output folder is replaced as a whole): choose "
                      "a folder elsewhere");
  }
}

}  // namespace rpt::engine
