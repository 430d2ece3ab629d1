// SPDX-License-Identifier: MIT
// The fuzz targets in the ordinary test suite (no clang needed): every format has seeds, every
// seed is accepted by its reader, and cut or flipped seeds are refused with input errors only.
// Inputs that crashed a fuzzer become regression tests at the end of this file.
#include "fuzz/fuzz_targets.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <initializer_list>
#include <set>
#include <sstream>

#include "core/errors.h"
#include "datasets/readers/colmap_text.h"
#include "fuzz/fuzz_seeds.h"

namespace rpt::fuzz {
namespace {

const std::map<std::string, std::vector<std::pair<std::string, Bytes>>>& Seeds() {
  static const auto seeds = MakeFuzzSeeds();
  return seeds;
}

TEST(FuzzTargets, EveryTargetHasSeedsAndEverySeedIsAccepted) {
  std::set<std::string> names;
  for (const FuzzTarget& target : FuzzTargets()) {
    EXPECT_TRUE(names.insert(target.name).second) << "duplicate target " << target.name;
    EXPECT_EQ(FindFuzzTarget(target.name), &target);
    const auto it = Seeds().find(target.name);
    ASSERT_NE(it, Seeds().end()) << "no seeds for " << target.name;
    ASSERT_FALSE(it->second.empty()) << target.name;
    for (const auto& [file, bytes] : it->second) {
      EXPECT_TRUE(RunFuzzTarget(target, bytes)) << target.name << ": seed " << file << " refused";
    }
  }
  for (const auto& [name, files] : Seeds()) EXPECT_TRUE(names.count(name)) << "seeds for unknown target " << name;
  EXPECT_EQ(FindFuzzTarget("no such format"), nullptr);
}


// scripts/fuzz.sh takes its list of formats from RPT_FUZZ_TARGETS in fuzz/CMakeLists.txt: a target
// missing there would never be fuzzed.
TEST(FuzzTargets, TheCMakeListNamesEveryTarget) {
  std::set<std::string> listed;
  std::istringstream in(RPT_FUZZ_TARGET_LIST);
  for (std::string name; in >> name;) EXPECT_TRUE(listed.insert(name).second) << "listed twice: " << name;
  std::set<std::string> targets;
  for (const FuzzTarget& target : FuzzTargets()) targets.insert(target.name);
  EXPECT_EQ(listed, targets);
}

// Runs every seed of `target` cut at 24 places and with one byte changed at 24 places: the
// reader accepts or refuses with an input error; anything else (another exception) fails here,
// a crash aborts. Adds to the counts of runs and of refused inputs.
void CheckCutAndFlippedSeeds(const FuzzTarget& target, long* runs, long* refused) {
  for (const auto& [file, seed] : Seeds().at(target.name)) {
    constexpr std::size_t kPlaces = 24;
    for (std::size_t k = 0; k < kPlaces; ++k) {
      const std::size_t at = seed.size() * k / kPlaces;
      const Bytes cut(seed.begin(), seed.begin() + static_cast<std::ptrdiff_t>(at));
      Bytes flipped = seed;
      flipped[at] ^= static_cast<std::uint8_t>(0x55 + k);
      for (const Bytes* input : std::initializer_list<const Bytes*>{&cut, &flipped}) {
        ++*runs;
        try {
          *refused += RunFuzzTarget(target, *input) ? 0 : 1;
        } catch (const std::exception& e) {
          ADD_FAILURE() << target.name << " (" << file << " " << (input == &cut ? "cut" : "flipped") << " at " << at
                        << "): " << e.what();
        }
      }
    }
  }
}

TEST(FuzzTargets, CutAndFlippedSeedsEndInInputErrorsOnly) {
  long runs = 0, refused = 0;
  for (const FuzzTarget& target : FuzzTargets()) {
    CheckCutAndFlippedSeeds(target, &runs, &refused);
  }
  // Cutting a file anywhere but at its end leaves nothing a reader should accept most of the time.
  EXPECT_GT(refused, runs / 2);
}

// ---------------------------------------------------------------------------------------------
// Regressions: inputs that crashed a fuzz target, made again here.

// Found by CutAndFlippedSeedsEndInInputErrorsOnly: the sequences cache with byte size * 14 / 24
// xor 0x63 made ReadSequencesHdf5 throw std::bad_alloc. That byte was the seventh of the dimension
// in the first dataspace message of a one-dimensional dataset of 20 elements (version 1, rank 1,
// maximum dimensions given: 20 becomes about 2.8e16); found by that pattern, as the attributes
// rpt adds move it.
TEST(FuzzRegressions, Hdf5SequencesCacheWithAFlippedByteIsAnInputError) {
  const auto& seeds = Seeds().at("hdf5");
  const auto it = std::find_if(seeds.begin(), seeds.end(), [](const auto& seed) { return seed.first == "sequences.h5"; });
  ASSERT_NE(it, seeds.end());
  Bytes bytes = it->second;
  const Bytes dataspace = {1, 1, 1, 0, 0, 0, 0, 0, 20, 0, 0, 0, 0, 0, 0, 0, 20, 0, 0, 0, 0, 0, 0, 0};
  const auto at = std::search(bytes.begin(), bytes.end(), dataspace.begin(), dataspace.end());
  ASSERT_NE(at, bytes.end());
  at[8 + 6] ^= 0x63;
  bool accepted = true;
  EXPECT_NO_THROW(accepted = RunFuzzTarget(*FindFuzzTarget("hdf5"), bytes));
  EXPECT_FALSE(accepted);
}

TEST(FuzzRegressions, Hdf5CutAndFlippedSeedsEndInInputErrorsOnly) {
  long runs = 0, refused = 0;
  CheckCutAndFlippedSeeds(*FindFuzzTarget("hdf5"), &runs, &refused);
  EXPECT_GT(refused, runs / 2);
}

// Found by review while adding the egohumans_images target: an exo camera whose only image is
// cam01/-2147483648.jpg made ReadEgohumans read through a null pointer (the time-stamp distance
// overflowed int and no image was taken as the nearest). Time stamps count from 1: a negative one
// is refused naming images.txt and the line.
TEST(FuzzRegressions, EgohumansNegativeImageTimeStampIsAnInputError) {
  const std::string images = "1 0.7071068 -0.7071068 0 0 0.2 1.5 4 1 cam01/-2147483648.jpg\n\n"
                             "3 0.5 -0.5 0.5 -0.5 -0.3 1.4 4.2 2 cam02/00003.jpg\n\n";
  std::string message;
  try {
    FindFuzzTarget("egohumans_images")->read(Bytes(images.begin(), images.end()));
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_THAT(message, ::testing::HasSubstr("images.txt:1: image name 'cam01/-2147483648.jpg' is not <camera>/<time stamp>.jpg"));
}

// Found by review while adding the h3wb_npz target: a frame_id of 9223372036854775807 (int64) is
// 2^63 as a double, and its conversion back to long long was undefined behaviour (here it gave the
// frame id "h3wb_S8_Directions-1_-000000" at -1.8e17 s). Frame ids beyond 2^53 are refused, naming
// the key.
TEST(FuzzRegressions, H3wbNpzFrameIdBeyondTwoToThe53IsAnInputError) {
  Bytes bytes = Seeds().at("h3wb_npz").front().second;
  // The seed's frame_id array (int64 7) as pickled: SHORT_BINBYTES of 8 bytes.
  const Bytes seven = {'C', 8, 7, 0, 0, 0, 0, 0, 0, 0};
  const auto at = std::search(bytes.begin(), bytes.end(), seven.begin(), seven.end());
  ASSERT_NE(at, bytes.end());
  ASSERT_EQ(std::search(at + 1, bytes.end(), seven.begin(), seven.end()), bytes.end());
  std::fill(at + 2, at + 9, 0xff);
  at[9] = 0x7f;
  std::string message;
  try {
    FindFuzzTarget("h3wb_npz")->read(bytes);
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_THAT(message, ::testing::HasSubstr("h3wb_train.npz[train_data.npy]: key 'S8'['Directions 1'].frame_id: element 0 is "
                                            "9.2233720368547758e+18, out of range (|frame_id| <= 2^53)"));
}

// Found by random mutations of the egohumans_images seed (the colmap_images target reaches it too):
// an image line whose CAMERA_ID and NAME were separated by a form feed made ParseColmapImagesText
// throw std::out_of_range. The fields were split at any white space, the NAME looked for after
// spaces and tabs only; both use the same white space now.
TEST(FuzzRegressions, ColmapImageNameAfterAFormFeedIsRead) {
  const std::string text = "4\v1 0 0 0 0 0 0 3\faria01/00001.jpg\f\n\n";
  bool accepted = false;
  EXPECT_NO_THROW(accepted = RunFuzzTarget(*FindFuzzTarget("colmap_images"), Bytes(text.begin(), text.end())));
  EXPECT_TRUE(accepted);
  std::istringstream in(text);
  const std::vector<ColmapImage> images = ParseColmapImagesText(in, "images.txt");
  ASSERT_EQ(images.size(), 1u);
  EXPECT_EQ(images[0].image_id, 4);
  EXPECT_EQ(images[0].camera_id, 3);
  EXPECT_EQ(images[0].name, "aria01/00001.jpg");
}

// The coverage-guided run of `colmap_images` (scripts/fuzz.sh, before the fix above) found the
// same std::out_of_range with carriage returns (the crash input, verbatim): the fields were split
// at "\r" but the NAME was looked for after spaces and tabs only.
TEST(FuzzRegressions, ColmapImageLineEndingInCarriageReturnsIsAnInputErrorOrRead) {
  const std::string text = "# Im\xf8ge list\n1 1 0 0 000068 0 0.068 0 -1\r\r\r\r\r\r\r\ra\n\n";
  EXPECT_NO_THROW(RunFuzzTarget(*FindFuzzTarget("colmap_images"), Bytes(text.begin(), text.end())));
}

// Found by a random-mutation loop over the calibration seeds (a throwaway loop, not part of the
// suite): OpenCV 4.6's YAML parser threw std::length_error from std::string (a negative key
// length) for this indented key-less colon; it is an input error naming the file now.
TEST(FuzzRegressions, OpenCVYamlWithAKeylessColonIsAnInputError) {
  const std::string text = "   o:3\n   :";
  bool accepted = true;
  EXPECT_NO_THROW(accepted = RunFuzzTarget(*FindFuzzTarget("calibration_opencv"), Bytes(text.begin(), text.end())));
  EXPECT_FALSE(accepted);
}

// Found by scripts/fuzz.sh (calibration_easymocap, a timeout): OpenCV 4.6's YAML parser loops
// forever on this text; the parse runs in a child process bounded in time
// (file_storage::kParseLimit), and the file is an input error after it.
TEST(FuzzRegressions, OpenCVYamlThatLoopsTheParserIsAnInputError) {
  const std::string text = "%YAML:1.:\n   - cam_a\n   - cam_b\n\"  - cam_a\n   - cam_d\nK_cam_a: L!";
  bool accepted = true;
  EXPECT_NO_THROW(accepted =
                      RunFuzzTarget(*FindFuzzTarget("calibration_easymocap"), Bytes(text.begin(), text.end())));
  EXPECT_FALSE(accepted);
}

}  // namespace
}  // namespace rpt::fuzz
