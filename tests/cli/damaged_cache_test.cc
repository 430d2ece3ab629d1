// SPDX-License-Identifier: MIT
// `rpt inspect` on damaged HDF5 caches, as a user sees it: exit code 0 (the damage missed what is
// read) or 2 with one printable error line naming the file, and nothing after it. Before, a byte
// changed in an attribute's value reached the terminal raw ("attribute format is '\xffpt-...'"),
// and after some damaged object headers HDF5 1.10 printed "HDF5: infinite loop closing library"
// at exit (its own leak, upstream HDFGroup/hdf5 #3790). The damaged files are made here.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "core/printable_text.h"
#include "tests/cli/cli_test_util.h"

namespace rpt::test {
namespace {

namespace fs = std::filesystem;

std::string ReadBytes(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// True when the message is already escaped for a terminal: PrintableText (which leaves valid,
// harmless UTF-8 as it is and writes everything else as \xNN) changes nothing. Not "ASCII only": a
// damaged attribute can hold bytes that happen to be valid UTF-8 (CI once read '@a\xdf\x84...', a
// heap address HDF5 returned for a damaged string), and those are quoted as they are.
bool PrintedEscaped(const std::string& text) { return PrintableText(text) == text; }

TEST(DamagedCache, OnePrintableErrorLineAndNothingAfterIt) {
  const fs::path dir = TempDir("damaged_cache");
  const fs::path valid = dir / "valid.h5";
  ASSERT_EQ(RunRpt("convert --dataset synthetic --param frames=3 --param people=1 --param cameras=2 --simulate --out " +
                   valid.string()).exit_code,
            0);
  const std::string bytes = ReadBytes(valid);
  const fs::path damaged = dir / "damaged.h5";
  int refused = 0;
  int variants = 0;
  // Each byte around the first attribute names ("format": the group's format tag; "count": the
  // group's frame count), set to 0x00 and to 0xff.
  for (const std::string name : {"format", "count"}) {
    const size_t at = bytes.find(name);
    ASSERT_NE(at, std::string::npos) << name;
    for (size_t k = at >= 48 ? at - 48 : 0; k < std::min(bytes.size(), at + name.size() + 48); ++k) {
      for (const char value : {'\x00', '\xff'}) {
        std::string changed = bytes;
        changed[k] = value;
        std::ofstream(damaged, std::ios::binary) << changed;
        const CommandResult r = RunRpt("inspect --labels " + damaged.string() + " --detections " + damaged.string());
        ++variants;
        const std::string where = name + " byte " + std::to_string(k) + " = " + std::to_string(static_cast<unsigned char>(value));
        ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 2) << where << ": exit " << r.exit_code << "\n" << r.err;
        EXPECT_TRUE(PrintedEscaped(r.err)) << where << ": " << r.err;
        // Nothing printed by the library itself (its error stack, its shutdown); rpt's own message
        // may name it ("the HDF5 library ... crashed walking the file's groups").
        EXPECT_EQ(r.err.find("HDF5-DIAG"), std::string::npos) << where << ": " << r.err;
        EXPECT_EQ(r.err.find("HDF5: "), std::string::npos) << where << ": " << r.err;
        if (r.exit_code == 2) {
          ++refused;
          EXPECT_EQ(r.err.rfind("error: " + damaged.string(), 0), 0u) << where << ": " << r.err;
          EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << where << ": one line, nothing after it\n" << r.err;
        }
      }
    }
  }
  EXPECT_GT(refused, variants / 4) << "the damage must reach what inspect reads";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace rpt::test
