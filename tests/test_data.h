// SPDX-License-Identifier: MIT
// Locating the real-data fixtures in ../shared/data (never copied into the project).
// Tests using them call RPT_REQUIRE_SHARED_DATA(path) and are skipped when it is absent.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace rpt::test {

// $RPT_SHARED_DATA if set, else ../shared/data next to the source tree.
inline std::filesystem::path SharedDataDir() {
  if (const char* env = std::getenv("RPT_SHARED_DATA")) return env;
  return RPT_SHARED_DATA_DIR;
}

inline std::filesystem::path SharedData(const std::string& relative) { return SharedDataDir() / relative; }

}  // namespace rpt::test

// Skips the current test when the fixture file or folder is missing.
#define RPT_REQUIRE_SHARED_DATA(relative)                                              \
  do {                                                                                 \
    if (!std::filesystem::exists(::rpt::test::SharedData(relative)))                   \
      GTEST_SKIP() << "shared data not available: " << ::rpt::test::SharedData(relative); \
  } while (0)
