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
  // The input's own mistakes first (an unknown dataset, a --root the synthetic dataset does not
  // read): they were said as "the output lies inside the input folder".
  CheckDatasetAndRoot(spec);
  const fs::path place = Resolved(out);
  for (const std::string& input : InputPaths(spec)) {
    const fs::path resolved = Resolved(input);
    // A file inside the output folder too: a take folder holding the detector's predictions.json
    // and cameras.json, given as --out, had the input replaced by the run's own predictions.json.
    const bool clash = Within(place, resolved) || Within(resolved, place);
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

void CheckOutputOutsideRunFolder(const fs::path& out, const fs::path& run_dir) {
  const fs::path place = Resolved(out), run = Resolved(run_dir);
  std::error_code ec;
  if (place == run || (Within(place, run) && place.extension() != ".html" && fs::exists(place, ec))) {
    throw ConfigError("--out " + QuoteName(out.string()) + ": " +
                      (place == run ? std::string("is the run folder ") : std::string("is a file of the run folder ")) +
                      QuoteName(run_dir.string()) +
                      ", which this command reads: choose another name (the default is " +
                      QuoteName((run_dir / "report.html").string()) + ")");
  }
}

}  // namespace rpt::engine
