// SPDX-License-Identifier: MIT
// One parameterised test over every reader (the reader contract, datasets/frame_source.h): the
// sources a reader opens, pulled frame by frame (round robin over the sequences, one reused frame
// buffer for all of them), give exactly the headers, frames and warnings of the same sources
// materialised, and so do they with frames pulled ahead and completed on several threads at once
// (Pull and Complete). The tests are defined in reader_stream_test.cc; each reader's test file adds its
// fixtures with INSTANTIATE_TEST_SUITE_P(<Reader>, ReaderStreamTest, ...).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "datasets/frame_source.h"
#include "datasets/sequence.h"
#include "tests/datasets/io_test_util.h"

namespace rpt::test {

struct ReaderFixture {
  std::string name;         // the test's name (letters, digits, underscores)
  std::string shared_data;  // a real fixture under ../shared/data the test needs (skipped without); empty = none
  // Writes what it needs under `dir` (a fresh folder) and opens the sources; called twice.
  std::function<std::vector<std::unique_ptr<FrameSource>>(const std::filesystem::path& dir)> open;
};

inline void PrintTo(const ReaderFixture& fixture, std::ostream* out) { *out << fixture.name; }

class ReaderStreamTest : public ::testing::TestWithParam<ReaderFixture> {
 protected:
  // Skips without the fixture's shared data; else opens the fixture's sources twice in dir_:
  // materialised_ (the whole sequences) and sources_ (to be read frame by frame), as many of each.
  void SetUp() override;

  TempDir dir_;
  std::vector<Sequence> materialised_;
  std::vector<std::unique_ptr<FrameSource>> sources_;
};

// The name of a ReaderStreamTest instance: the fixture's name.
inline std::string ReaderFixtureName(const ::testing::TestParamInfo<ReaderFixture>& info) { return info.param.name; }

}  // namespace rpt::test
