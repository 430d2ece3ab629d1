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

// Whether `inner` is `outer` or lies below it (both absolute, normalised, no trailing separator).
bool Within(const fs::path& inner, const fs::path& outer) {
  auto o = outer.begin(), i = inner.begin();
  for (; o != outer.end(); ++o, ++i) {
    if (i == inner.end() || *i != *o) return false;
  }
  return true;
}

// `path` absolute, with links resolved where it exists, normalised, without a trailing separator.
fs::path Resolved(const fs::path& path) {
  std::error_code ec;
  fs::path resolved = fs::weakly_canonical(fs::absolute(path, ec), ec);
  if (ec) resolved = fs::absolute(path).lexically_normal();
  while (!resolved.has_filename() && resolved.has_relative_path()) resolved = resolved.parent_path();  // "a/b/"
  return resolved;
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
