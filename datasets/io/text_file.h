// SPDX-License-Identifier: MIT
// The one checked text writer: every text output of the project (tables, JSON, caches written as
// text, JUnit XML) goes through it. The text goes to a temporary beside the file, is flushed to disk
// and checked, then renamed over the file (datasets/io/staged_output.h): the file holds either its
// old or its complete new text, and a failed open, write or close (a full disk) is an error naming
// the file, never a silently truncated output.
#pragma once

#include <filesystem>
#include <functional>
#include <ostream>
#include <string>

#include "datasets/io/staged_output.h"

namespace rpt::io {

// Writes `text` to `path`, replacing it (a link there is replaced, never written through; what
// `named_by` changes: io::NamedBy). Throws InputError naming the file when it cannot be opened,
// written or closed (e.g. a full disk); the old file is then left as it was.
void WriteTextFile(const std::filesystem::path& path, NamedBy named_by, const std::string& text);

// The same for text too large to build in memory first: `write` streams it into the stream.
void WriteTextFile(const std::filesystem::path& path, NamedBy named_by,
                   const std::function<void(std::ostream&)>& write);

}  // namespace rpt::io
