// SPDX-License-Identifier: MIT
// The rpt entry point: --version, unknown subcommands and unknown flags with "did you mean".
#include <gtest/gtest.h>

#include <string>

#include "core/closest_name.h"
#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

TEST(Main, VersionPrintsProjectVersionAndGitRevision) {
  const test::CommandResult r = test::RunRpt("--version");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out.rfind("rpt 0.", 0), 0u) << r.out;
  EXPECT_NE(r.out.find(" (git "), std::string::npos) << r.out;
}

// OpenCV's image and video files (imgcodecs, videoio: about 220 shared libraries, 0.2 s to load)
// are loaded by `rpt render` alone (engine/render/image_codecs.h). The loader's trace of a command
// lists every library it maps: OpenCV's core, never the image and video ones.
TEST(Main, CommandsOtherThanRenderStartWithoutTheImageAndVideoLibraries) {
  for (const char* args : {"--version", "config --dump"}) {
    const test::CommandResult r = test::RunRpt(args, "LD_DEBUG=libs ");
    EXPECT_EQ(r.exit_code, 0) << args;
    EXPECT_NE(r.err.find("libopencv_core"), std::string::npos) << args << ": no loader trace\n" << r.err.substr(0, 500);
    EXPECT_EQ(r.err.find("libopencv_imgcodecs"), std::string::npos) << args;
    EXPECT_EQ(r.err.find("libopencv_videoio"), std::string::npos) << args;
  }
}

TEST(Main, UnknownSubcommandSuggestsTheClosestAndExitsWith2) {
  const test::CommandResult r = test::RunRpt("evl --dataset synthetic");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown subcommand 'evl'; did you mean 'eval'?"), std::string::npos) << r.err;
  const test::CommandResult far = test::RunRpt("frobnicate");
  EXPECT_EQ(far.exit_code, 2);
  EXPECT_NE(far.err.find("unknown subcommand 'frobnicate'"), std::string::npos) << far.err;
  EXPECT_EQ(far.err.find("did you mean"), std::string::npos) << far.err;
}

TEST(Main, UnknownFlagOfASubcommandSuggestsTheClosest) {
  const test::CommandResult r = test::RunRpt("check --thresholdz x.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--thresholdz: did you mean '--thresholds'?"), std::string::npos) << r.err;
}

TEST(ClosestName, PicksTheNearestNameWithinATypoDistance) {
  EXPECT_EQ(EditDistance("kitten", "sitting"), 3);
  EXPECT_EQ(ClosestName("evl", {"demo", "eval", "sweep"}), "eval");
  EXPECT_EQ(ClosestName("recal500", {"recall100", "recall500"}), "recall500");
  EXPECT_EQ(ClosestName("zzz", {"eval", "check"}), "");
  // A swap of two neighbours is one edit: "cuont" is close to "count".
  EXPECT_EQ(EditDistance("cuont", "count"), 1);
  EXPECT_EQ(ClosestName("cuont", {"count", "seed"}), "count");
}

}  // namespace
}  // namespace rpt
