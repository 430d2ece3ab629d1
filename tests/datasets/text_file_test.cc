// SPDX-License-Identifier: MIT
#include "datasets/io/text_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.h"

namespace rpt::io {
namespace {

namespace fs = std::filesystem;

TEST(TextFile, WritesAndReplaces) {
  const fs::path path = fs::path(testing::TempDir()) / "rpt_text_file_test.txt";
  WriteTextFile(path, NamedBy::kUser, "first version, longer\n");
  WriteTextFile(path, NamedBy::kUser, "second\n");
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), "second\n");
  fs::remove(path);
}

TEST(TextFile, FailureNamesTheFile) {
  const fs::path path = fs::path(testing::TempDir()) / "no_such_folder_rpt" / "out.csv";
  try {
    WriteTextFile(path, NamedBy::kUser, "x");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

#ifdef __linux__
TEST(TextFile, FullDiskIsAnError) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "/dev/full is absent";
  EXPECT_THROW(WriteTextFile("/dev/full", NamedBy::kUser, std::string(1 << 16, 'x')), InputError);
}
#endif

}  // namespace
}  // namespace rpt::io
