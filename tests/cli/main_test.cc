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

// A refused option value reaches the terminal with its control characters escaped (CLI11 quoted it
// raw: an ESC ]0;...BEL set the terminal's title), and a bound as a short number.
TEST(Main, RefusedOptionValuesAreShownEscaped) {
  const test::CommandResult r =
      test::RunRpt("eval --dataset synthetic --simulate --detector \"$(printf 'x\\033]0;T\\a')\"");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("error: --detector: x\\x1b]0;T\\x07 not in {perfect,clean,realistic,hard}"), std::string::npos)
      << r.err;
  EXPECT_EQ(r.err.find('\x1b'), std::string::npos);
  EXPECT_NE(r.err.find("\nRun with --help for more information."), std::string::npos) << "line breaks kept: " << r.err;
  const test::CommandResult threads = test::RunRpt("eval --dataset synthetic --threads 1e400");
  EXPECT_EQ(threads.exit_code, 2);
  EXPECT_NE(threads.err.find("--threads: '1e400' is not a whole number >= 0"), std::string::npos) << threads.err;
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
