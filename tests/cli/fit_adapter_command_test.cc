// SPDX-License-Identifier: MIT
// rpt fit-adapter and rpt eval --adapter end to end: the adapter file states its split, eval
// refuses it on its own fitting frames, on other joints and when the file is bad (exit 2, the file
// and the place named).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/cli/cli_test_util.h"

namespace rpt {
namespace {

namespace fs = std::filesystem;

TEST(FitAdapterCommand, WritesTheSplitAndEvalRefusesItsOwnFramesOtherJointsAndBadFiles) {
  const fs::path dir = test::TempDir("fit_adapter");
  const std::string adapter = (dir / "adapter.json").string();
  const test::CommandResult fit = test::RunRpt(
      "fit-adapter --dataset synthetic --param frames=20 --param people=2 --param noise=perfect --out " + adapter);
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  EXPECT_NE(fit.out.find("fitted on synthetic frames=20 people=2 noise=perfect: 20 frames ('synthetic_000000' to "
                         "'synthetic_000019'), 40 matched persons"),
            std::string::npos)
      << fit.out;
  const nlohmann::json file = nlohmann::json::parse(test::ReadAll(adapter));
  EXPECT_EQ(file["fit"]["dataset"], "synthetic");
  EXPECT_EQ(file["fit"]["params"], nlohmann::json({"frames=20", "people=2", "noise=perfect"}));
  EXPECT_EQ(file["fit"]["frame_ids"].size(), 20u);
  EXPECT_EQ(file["joints"].size(), 20u);

  // The same frames: refused.
  const test::CommandResult own = test::RunRpt("eval --dataset synthetic --param frames=20 --quiet --out " +
                                               (dir / "own").string() + " --adapter " + adapter);
  EXPECT_EQ(own.exit_code, 2) << own.err;
  EXPECT_NE(own.err.find("error: " + adapter + ": frame 'synthetic_000000' is one it was fitted on"), std::string::npos)
      << own.err;
  EXPECT_FALSE(fs::exists(dir / "own"));

  // Other joints: refused before any frame.
  const test::CommandResult wholebody = test::RunRpt("eval --dataset synthetic --param frames=2 --param joints=wholebody "
                                                     "--quiet --out " + (dir / "wb").string() + " --adapter " + adapter);
  EXPECT_EQ(wholebody.exit_code, 2) << wholebody.err;
  EXPECT_NE(wholebody.err.find("error: " + adapter + ": fitted for other joints than the predictions'"),
            std::string::npos)
      << wholebody.err;

  // A bad file: the file and the JSON path.
  nlohmann::json bad = file;
  bad["joints"][2]["offset_m"][1] = "far";
  const std::string bad_path = (dir / "bad.json").string();
  std::ofstream(bad_path) << bad.dump();
  const test::CommandResult broken = test::RunRpt("eval --dataset synthetic --param frames=2 --quiet --out " +
                                                  (dir / "bad").string() + " --adapter " + bad_path);
  EXPECT_EQ(broken.exit_code, 2) << broken.err;
  EXPECT_NE(broken.err.find("error: " + bad_path + ": /joints/2/offset_m/1: expected a number, got string \"far\""),
            std::string::npos)
      << broken.err;
  const test::CommandResult missing = test::RunRpt("eval --dataset synthetic --param frames=2 --quiet --out " +
                                                   (dir / "missing").string() + " --adapter " + (dir / "no.json").string());
  EXPECT_EQ(missing.exit_code, 2) << missing.err;
  EXPECT_NE(missing.err.find((dir / "no.json").string()), std::string::npos) << missing.err;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt
