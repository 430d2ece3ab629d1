// SPDX-License-Identifier: MIT
#include "datasets/io/mat.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "core/errors.h"
#include "datasets/io/binary.h"
#include "datasets/io/inflate_budget.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"
#include "tests/test_data.h"

namespace rpt::io {
namespace {

using ::testing::HasSubstr;
using test::ByteVec;
namespace m = test::mat;


// Collects the classes of all non-cell leaves.
void CollectClasses(const MatValue& v, std::set<std::string>& out) {
  if (v.IsCell()) {
    for (const auto& c : v.cells) CollectClasses(c, out);
  } else if (!v.IsEmpty()) {
    out.insert(MatClassName(v.mat_class));
  }
}

// ---------------------------------------------------------------------------------------
// Real fixtures

TEST(MatFixture, ShelfActorsGT) {
  RPT_REQUIRE_SHARED_DATA("shelf/actorsGT.mat");
  const MatFile file = ReadMat(test::SharedData("shelf/actorsGT.mat"));
  EXPECT_THAT(file.header_text, HasSubstr("MATLAB 5.0 MAT-file"));
  const MatValue& actor3d = file.Get("actor3D");
  ASSERT_TRUE(actor3d.IsCell());
  EXPECT_EQ(actor3d.dims, (std::vector<std::size_t>{1, 4}));
  const MatValue& frames0 = actor3d.Cell(0, 0);
  ASSERT_TRUE(frames0.IsCell());
  EXPECT_EQ(frames0.dims, (std::vector<std::size_t>{3, 1}));
  const MatValue& pose = frames0.Cell(0);
  EXPECT_EQ(pose.Describe(), "14x3 double");
  EXPECT_NEAR(pose.At(0, 0), -0.1430438, 1e-7);
  EXPECT_NEAR(pose.At(0, 1), -0.0922845, 1e-7);
  EXPECT_NEAR(pose.At(0, 2), -0.0411864, 1e-7);
  const auto rows = pose.RowMajor(14, 3);
  EXPECT_EQ(rows[1], pose.At(0, 1));
  // Actors 1 and 3 are not annotated in this subset.
  for (std::size_t actor : {1, 3}) {
    for (std::size_t f = 0; f < actor3d.Cell(actor).NumElements(); ++f) {
      EXPECT_TRUE(actor3d.Cell(actor).Cell(f).IsEmpty()) << actor << " " << f;
    }
  }
  const MatValue& empty = actor3d.Cell(1).Cell(0);
  EXPECT_THAT(test::InputErrorOf([&] { empty.RowMajor(14, 3); }),
              HasSubstr("actorsGT.mat: actor3D{1,2}{1,1}: expected a 14x3 numeric matrix, got " + empty.Describe()));
  // actor2D: per actor, per frame, a 1xC cell of 14x2 matrices.
  const MatValue& actor2d = file.Get("actor2D");
  const MatValue& views = actor2d.Cell(0).Cell(0);
  ASSERT_TRUE(views.IsCell());
  EXPECT_EQ(views.NumElements(), 5u);
  EXPECT_EQ(views.Cell(0).Describe(), "14x2 double");
  EXPECT_THAT(test::InputErrorOf([&] { file.Get("actor4D"); }), HasSubstr("variable 'actor4D' not found (variables: actor2D, actor3D)"));
}

TEST(MatFixture, CampusActorsGT) {
  RPT_REQUIRE_SHARED_DATA("campus/actorsGT.mat");
  const MatFile file = ReadMat(test::SharedData("campus/actorsGT.mat"));
  const MatValue& actor3d = file.Get("actor3D");
  EXPECT_EQ(actor3d.dims, (std::vector<std::size_t>{1, 3}));
  const MatValue& pose = actor3d.Cell(0).Cell(0);
  EXPECT_NEAR(pose.At(0, 0), 1.2796, 1e-4);
  EXPECT_NEAR(pose.At(0, 1), 1.8390, 1e-4);
  EXPECT_NEAR(pose.At(0, 2), 0.0857, 1e-4);
  // Empty entries are 1x0 doubles.
  EXPECT_EQ(actor3d.Cell(1).Cell(0).dims, (std::vector<std::size_t>{1, 0}));
  std::set<std::string> classes;
  CollectClasses(file.Get("actor2D"), classes);
  EXPECT_EQ(classes, (std::set<std::string>{"double", "uint8", "uint16"}));
}

TEST(MatFixture, TruncatedFixtureNeverCrashes) {
  RPT_REQUIRE_SHARED_DATA("shelf/actorsGT.mat");
  const auto bytes = detail::ReadFileBytes(test::SharedData("shelf/actorsGT.mat"));
  for (std::size_t cut = 0; cut < bytes.size(); cut += 53) {
    if (cut == 128) continue;  // header only: a valid, empty MAT file
    EXPECT_THAT(test::InputErrorOf([&] { ParseMat(std::span(bytes).first(cut), "shelf_cut.mat"); }), HasSubstr("shelf_cut.mat")) << cut;
  }
}

// ---------------------------------------------------------------------------------------
// Files written here

// Variables: "a" 2x3 double (uncompressed), "c" compressed 1x4 cell {14x3 double stored as
// uint8, 0x0 empty, 1x0 empty, 1x2 uint16 in the small element format}, "s" 1x1 struct
// {name: char 'cam', flag: logical}.
struct SampleMat {
  ByteVec bytes;
  std::vector<std::size_t> variable_ends;  // file offsets where a variable ends
};

SampleMat MakeSampleMat() {
  SampleMat out;
  out.bytes = m::Header();
  test::Append(out.bytes, m::Matrix(m::kDoubleClass, {2, 3}, "a", m::Doubles({1, 2, 3, 4, 5, 6})));
  out.variable_ends.push_back(out.bytes.size());

  ByteVec cells;
  ByteVec u8(42);
  for (int i = 0; i < 42; ++i) u8[i] = static_cast<std::uint8_t>(i);
  test::Append(cells, m::Matrix(m::kDoubleClass, {14, 3}, "", m::Element(m::kUInt8, u8)));
  test::Append(cells, m::Matrix(m::kDoubleClass, {0, 0}, "", m::Doubles({})));
  test::Append(cells, m::Matrix(m::kDoubleClass, {1, 0}, "", m::Doubles({})));
  test::Append(cells, m::Matrix(m::kUInt16Class, {1, 2}, "", m::Element(m::kUInt16, ByteVec{0x10, 0x27, 0xff, 0xff}, true)));
  test::Append(out.bytes, m::Compressed(m::Matrix(m::kCellClass, {1, 4}, "c", cells)));
  out.variable_ends.push_back(out.bytes.size());

  ByteVec fields;
  ByteVec name_len;
  test::AppendLE(name_len, 8, 4);
  test::Append(fields, m::Element(m::kInt32, name_len, true));
  ByteVec names(16, 0);
  std::memcpy(names.data(), "name", 4);
  std::memcpy(names.data() + 8, "flag", 4);
  test::Append(fields, m::Element(m::kInt8, names));
  test::Append(fields, m::Matrix(m::kCharClass, {1, 3}, "", m::Element(m::kUtf16, ByteVec{'c', 0, 'a', 0, 'm', 0})));
  test::Append(fields, m::Matrix(m::kUInt8Class, {1, 1}, "", m::Element(m::kUInt8, ByteVec{1}, true), 0x0200));
  test::Append(out.bytes, m::Matrix(m::kStructClass, {1, 1}, "s", fields));
  out.variable_ends.push_back(out.bytes.size());
  return out;
}

TEST(Mat, RoundTripCompressedUncompressedAndEmptyCells) {
  test::TempDir dir;
  const MatFile file = ReadMat(dir.Write("sample.mat", MakeSampleMat().bytes));
  ASSERT_EQ(file.variables.size(), 3u);
  const MatValue& a = file.Get("a");
  EXPECT_EQ(a.Describe(), "2x3 double");
  EXPECT_EQ(a.At(1, 0), 2.0);  // column-major storage
  EXPECT_EQ(a.RowMajor(2, 3), (std::vector<double>{1, 3, 5, 2, 4, 6}));

  const MatValue& c = file.Get("c");
  ASSERT_EQ(c.NumElements(), 4u);
  EXPECT_EQ(c.Cell(0).Describe(), "14x3 double");
  EXPECT_EQ(c.Cell(0).At(13, 2), 41.0);
  EXPECT_TRUE(c.Cell(1).IsEmpty());
  EXPECT_TRUE(c.Cell(2).IsEmpty());
  EXPECT_EQ(c.Cell(1).dims, (std::vector<std::size_t>{0, 0}));
  EXPECT_EQ(c.Cell(2).dims, (std::vector<std::size_t>{1, 0}));
  EXPECT_EQ(c.Cell(3).Describe(), "1x2 uint16");
  EXPECT_EQ(c.Cell(3).Numeric(), (std::vector<double>{10000, 65535}));
  EXPECT_THAT(test::InputErrorOf([&] { c.Cell(0, 4); }), HasSubstr("sample.mat: c: cell index {1,5} out of range for 1x4 cell"));
  EXPECT_THAT(test::InputErrorOf([&] { c.Cell(3).Text(); }), HasSubstr("sample.mat: c{1,4}: expected a char array, got 1x2 uint16"));

  const MatValue& s = file.Get("s");
  ASSERT_TRUE(s.IsStruct());
  EXPECT_EQ(s.field_names, (std::vector<std::string>{"name", "flag"}));
  EXPECT_EQ(s.Field("name").Text(), "cam");
  EXPECT_TRUE(s.Field("flag").logical);
  EXPECT_EQ(s.Field("flag").Describe(), "1x1 logical");
  EXPECT_THAT(test::InputErrorOf([&] { s.Field("pose"); }), HasSubstr("s: struct has no field 'pose' (fields: name, flag)"));
}

TEST(Mat, TruncatedAtEveryCut) {
  const SampleMat sample = MakeSampleMat();
  for (std::size_t cut = 0; cut < sample.bytes.size(); ++cut) {
    const std::span<const std::uint8_t> part = std::span(sample.bytes).first(cut);
    const bool boundary = cut == 128 || std::count(sample.variable_ends.begin(), sample.variable_ends.end(), cut) > 0;
    if (boundary) {
      EXPECT_NO_THROW(ParseMat(part, "cut.mat")) << cut;
    } else {
      EXPECT_THAT(test::InputErrorOf([&] { ParseMat(part, "cut.mat"); }), HasSubstr("cut.mat")) << cut;
    }
  }
}

TEST(Mat, CorruptCompressedData) {
  ByteVec bytes = MakeSampleMat().bytes;
  const std::size_t compressed_at = m::Header().size() + m::Matrix(m::kDoubleClass, {2, 3}, "a", m::Doubles({1, 2, 3, 4, 5, 6})).size();
  ASSERT_EQ(bytes[compressed_at], 15);
  for (std::size_t k = 8; k < 40; ++k) bytes[compressed_at + k] ^= 0x5a;
  EXPECT_THAT(test::InputErrorOf([&] { ParseMat(bytes, "z.mat"); }), HasSubstr("z.mat: compressed variable at byte"));
}

TEST(Mat, HostileDimensionsAndNesting) {
  // Dimensions whose product overflows.
  ByteVec f1 = m::Header();
  test::Append(f1, m::Matrix(m::kDoubleClass, {0x7fffffff, 0x7fffffff, 0x7fffffff}, "x", m::Doubles({})));
  EXPECT_THAT(test::InputErrorOf([&] { ParseMat(f1, "dims.mat"); }), HasSubstr("dims.mat"));
  // A cell claiming more elements than its bytes can hold.
  ByteVec f2 = m::Header();
  test::Append(f2, m::Matrix(m::kCellClass, {100000, 100000}, "big", ByteVec{}));
  EXPECT_THAT(test::InputErrorOf([&] { ParseMat(f2, "cells.mat"); }), HasSubstr("cells.mat: big: cell array of 10000000000 elements does not fit"));
  // Numeric data shorter than the dimensions.
  ByteVec f3 = m::Header();
  test::Append(f3, m::Matrix(m::kDoubleClass, {14, 3}, "short", m::Doubles({1, 2})));
  EXPECT_THAT(test::InputErrorOf([&] { ParseMat(f3, "short.mat"); }), HasSubstr("short.mat: short: numeric data holds 2 values, dimensions need 42"));
  // Cells nested 100 deep.
  ByteVec inner = m::Matrix(m::kDoubleClass, {0, 0}, "", m::Doubles({}));
  for (int i = 0; i < 100; ++i) inner = m::Matrix(m::kCellClass, {1, 1}, i == 99 ? "deep" : "", inner);
  ByteVec f4 = m::Header();
  test::Append(f4, inner);
  EXPECT_THAT(test::InputErrorOf([&] { ParseMat(f4, "deep.mat"); }), HasSubstr("nest deeper than 64 levels"));
}

TEST(Mat, RefusedVariantsAndMissingFile) {
  ByteVec v73 = m::Header("MATLAB 7.3 MAT-file, Platform: GLNXA64, HDF5 schema 1.00");
  EXPECT_THAT(test::InputErrorOf([&] { ParseMat(v73, "new.mat"); }), HasSubstr("new.mat: MAT v7.3"));
  ByteVec be = m::Header();
  be[126] = 'M';
  be[127] = 'I';
  EXPECT_THAT(test::InputErrorOf([&] { ParseMat(be, "be.mat"); }), HasSubstr("be.mat: big-endian MAT files are not supported"));
  EXPECT_THAT(test::InputErrorOf([&] { ParseMat(ByteVec(10, 0), "tiny.mat"); }), HasSubstr("tiny.mat: too short"));
  ByteVec sparse = m::Header();
  test::Append(sparse, m::Matrix(5, {2, 2}, "sp", ByteVec{}));
  const MatFile file = ParseMat(sparse, "sparse.mat");
  EXPECT_THAT(test::InputErrorOf([&] { file.Get("sp").Numeric(); }), HasSubstr("sparse.mat: sp: MAT class sparse (5) is not supported"));
  EXPECT_THAT(test::InputErrorOf([] { ReadMat("/nonexistent/Shelf/actorsGT.mat"); }), HasSubstr("/nonexistent/Shelf/actorsGT.mat: file not found"));
}

// A 4 MB MAT file with four compressed variables took 5.1 GB and 46 s, then exited 0 (issue 10):
// each variable was under the per-call cap. Now all variables of a file share one budget (64 x
// the file size, at least 64 MiB), checked before each variable is inflated.
TEST(Mat, CompressedVariablesShareOneDecompressionBudget) {
  const ByteVec zeros = m::Matrix(m::kDoubleClass, {3'000'000, 1}, "v", m::Doubles(std::vector<double>(3'000'000, 0.0)));
  ByteVec bytes = m::Header();
  std::vector<std::size_t> starts;
  for (const char name : std::string("abcd")) {
    ByteVec named = zeros;  // the 1-character name sits in the small element after flags and dims
    const std::size_t at = std::search(named.begin(), named.end(), std::begin("v"), std::begin("v") + 1) - named.begin();
    named[at] = static_cast<std::uint8_t>(name);
    starts.push_back(bytes.size());
    test::Append(bytes, m::Compressed(named));
  }
  ASSERT_LT(bytes.size(), 1'000'000u) << "a small file";
  EXPECT_THAT(test::InputErrorOf([&] { ParseMat(bytes, "bomb.mat"); }),
              HasSubstr("bomb.mat: compressed variable at byte " + std::to_string(starts[2]) +
                        ": decompressing 22.9 MB would take the data decompressed from bomb.mat to 68.7 MB, above the "
                        "limit of 64.0 MB (64 x the file size, at least 64 MB, at most 4096 MB; raise it with "
                        "--max-inflate-mb N if the file is genuine)"));
  SetInflateLimitMb(100);  // what `rpt --max-inflate-mb 100` does
  const MatFile file = ParseMat(bytes, "bomb.mat");
  SetInflateLimitMb(0);
  EXPECT_EQ(file.variables.size(), 4u);
  EXPECT_EQ(file.Get("d").NumElements(), 3'000'000u);
}

}  // namespace
}  // namespace rpt::io
