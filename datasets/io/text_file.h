// SPDX-License-Identifier: MIT
// The one checked text writer: every text output of the project (tables, JSON, caches written as
// text, JUnit XML) goes through it, so a failed open, write or close is always an error naming
// the file, never a silently truncated output.
#pragma once

#include <filesystem>
#include <string>

namespace rpt::io {

// Writes `text` to `path`, replacing it. Throws InputError naming the file when it cannot be
// opened, written or closed (e.g. a full disk).
void WriteTextFile(const std::filesystem::path& path, const std::string& text);

}  // namespace rpt::io
