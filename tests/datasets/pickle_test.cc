// SPDX-License-Identifier: MIT
#include "datasets/io/pickle.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.h"
#include "datasets/io/binary.h"
#include "tests/datasets/io_test_util.h"
#include "tests/error_message.h"
#include "tests/test_data.h"

namespace rpt::io {
namespace {

using ::testing::HasSubstr;
using test::ByteVec;
using test::PickleWriter;

PyView Parse(const PickleWriter& w, const std::string& name = "test.pkl") { return ParsePickle(w.bytes, name); }


// ---------------------------------------------------------------------------------------
// Real fixtures (skipped when shared/data is absent)

TEST(PickleFixture, ShelfPredictions) {
  RPT_REQUIRE_SHARED_DATA("shelf/pred_shelf_maskrcnn_hrnet_coco.pkl");
  const PyView root = ReadPickle(test::SharedData("shelf/pred_shelf_maskrcnn_hrnet_coco.pkl"));
  ASSERT_TRUE(root.IsDict());
  EXPECT_TRUE(root.value().is_defaultdict);
  EXPECT_EQ(root.Size(), 15u);
  for (const auto& [key, detections] : root.Items()) {
    SCOPED_TRACE(key.AsStr());
    ASSERT_TRUE(detections.IsList());
    EXPECT_GE(detections.Size(), 3u);
    EXPECT_LE(detections.Size(), 5u);
    for (const auto& det : detections.Elements()) {
      const NdArray& pred = det.Key("pred").AsArray();
      EXPECT_EQ(pred.dtype.Str(), "<f8");
      EXPECT_EQ(pred.shape, (std::vector<std::int64_t>{17, 3}));
    }
  }
  const auto first = root.Key("2_0").At(0).Key("pred").ToDoubles({17, 3});
  EXPECT_NEAR(first[0], 278.49, 0.01);
  EXPECT_NEAR(first[1], 70.81, 0.01);
  EXPECT_NEAR(first[2], 0.40, 0.01);
}

TEST(PickleFixture, CampusPredictionsAreEmptyLists) {
  RPT_REQUIRE_SHARED_DATA("campus/pred_campus_maskrcnn_hrnet_coco.pkl");
  const PyView root = ReadPickle(test::SharedData("campus/pred_campus_maskrcnn_hrnet_coco.pkl"));
  ASSERT_EQ(root.Size(), 15u);
  for (const auto& [key, value] : root.Items()) {
    EXPECT_TRUE(value.IsList());
    EXPECT_EQ(value.Size(), 0u) << key.AsStr();
  }
}

TEST(PickleFixture, Human36mCameras) {
  RPT_REQUIRE_SHARED_DATA("human36m/cameras.pkl");
  const PyView root = ReadPickle(test::SharedData("human36m/cameras.pkl"));
  ASSERT_EQ(root.Size(), 44u);
  for (const auto& [key, value] : root.Items()) {
    ASSERT_TRUE(key.IsTuple());
    ASSERT_EQ(key.Size(), 2u);
    EXPECT_TRUE(key.At(0).IsStr());
  }
  const PyView cam = root.Key(*MakeStrTuple({"S1", "54138969"}));
  const auto f = cam.Key("f").ToDoubles({2, 1});
  EXPECT_NEAR(f[0], 1145.049405, 1e-6);
  EXPECT_NEAR(f[1], 1143.781096, 1e-6);
  const auto c = cam.Key("c").ToDoubles({2, 1});
  EXPECT_NEAR(c[0], 512.541505, 1e-6);
  EXPECT_NEAR(c[1], 515.451487, 1e-6);
  // R is camera->world, stored Fortran-ordered: its first column is R_w2c's first row.
  EXPECT_TRUE(cam.Key("R").AsArray().fortran_order);
  const auto R = cam.Key("R").ToDoubles({3, 3});  // row-major
  EXPECT_NEAR(R[0 * 3 + 0], -0.915362, 1e-6);
  EXPECT_NEAR(R[1 * 3 + 0], 0.401808, 1e-6);
  EXPECT_NEAR(R[2 * 3 + 0], 0.025748, 1e-6);
  // Orthonormal.
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double dot = 0;
      for (int k = 0; k < 3; ++k) dot += R[i * 3 + k] * R[j * 3 + k];
      EXPECT_NEAR(dot, i == j ? 1.0 : 0.0, 1e-6);
    }
  }
  const auto T = cam.Key("T").ToDoubles({3, 1});  // camera centre in metres
  EXPECT_NEAR(T[0], 1.841107, 1e-5);
  EXPECT_NEAR(T[1], 4.955285, 1e-5);
  EXPECT_NEAR(T[2], 1.563445, 1e-5);
  EXPECT_EQ(cam.Key("w").AsInt(), 1000);
  EXPECT_EQ(cam.Key("h").AsInt(), 1002);
  EXPECT_EQ(cam.Key("name").AsStr(), "camera1");
  EXPECT_EQ(cam.Key("id").AsStr(), "54138969");
  // Accessor errors name the file and the path.
  const std::string msg = test::InputErrorOf([&] { cam.Key("R").AsStr(); });
  EXPECT_THAT(msg, HasSubstr("cameras.pkl: key ('S1', '54138969').R: expected str, got ndarray <f8 (3, 3)"));
  EXPECT_THAT(test::InputErrorOf([&] { cam.Key("nope"); }), HasSubstr("missing key 'nope'"));
}

TEST(PickleFixture, TruncatedFixtureNeverCrashes) {
  RPT_REQUIRE_SHARED_DATA("shelf/pred_shelf_maskrcnn_hrnet_coco.pkl");
  const auto bytes = detail::ReadFileBytes(test::SharedData("shelf/pred_shelf_maskrcnn_hrnet_coco.pkl"));
  for (std::size_t cut = 0; cut < bytes.size(); cut += 97) {
    EXPECT_THROW(ParsePickle(std::span(bytes).first(cut), "pred_cut.pkl"), InputError) << cut;
  }
}

// ---------------------------------------------------------------------------------------
// Round trips on pickles written here

TEST(Pickle, ScalarsAndContainers) {
  PickleWriter w;
  w.Proto(3).EmptyDict().Put(0).Mark();
  w.Str("small").Int(7);
  w.Str("medium").Int(40000);
  w.Str("negative").Int(-5);
  w.Str("big").Int(std::int64_t{1} << 40);
  w.Str("very_negative").Int(-(std::int64_t{1} << 50));
  w.Str("float").Float(-2.5);
  w.Str("none").None();
  w.Str("yes").Bool(true);
  w.Str("bytes").Bytes(std::string("\x00\x01\xff", 3));
  w.Str("list").EmptyList().Mark().Int(1).Int(2).Int(3).Appends();
  w.Str("tuple").Str("a").Int(1).Tuple2();
  w.Int(5).Str("int key");
  w.Str("a").Str("b").Tuple2().Str("tuple key");
  w.SetItems().Stop();
  const PyView v = Parse(w);
  EXPECT_EQ(v.Key("small").AsInt(), 7);
  EXPECT_EQ(v.Key("medium").AsInt(), 40000);
  EXPECT_EQ(v.Key("negative").AsInt(), -5);
  EXPECT_EQ(v.Key("big").AsInt(), std::int64_t{1} << 40);
  EXPECT_EQ(v.Key("very_negative").AsInt(), -(std::int64_t{1} << 50));
  EXPECT_DOUBLE_EQ(v.Key("float").AsDouble(), -2.5);
  EXPECT_TRUE(v.Key("none").IsNone());
  EXPECT_TRUE(v.Key("yes").AsBool());
  EXPECT_EQ(v.Key("bytes").AsBytes(), std::string("\x00\x01\xff", 3));
  EXPECT_EQ(v.Key("list").ToDoubles({3}), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(v.Key("tuple").At(0).AsStr(), "a");
  EXPECT_EQ(v.Key(*MakeInt(5)).AsStr(), "int key");
  EXPECT_EQ(v.Key(*MakeStrTuple({"a", "b"})).AsStr(), "tuple key");
  // Insertion order is kept.
  EXPECT_EQ(v.Items().front().first.AsStr(), "small");
  EXPECT_THAT(test::InputErrorOf([&] { v.Key("list").AsArray(); }), HasSubstr("test.pkl: key 'list': expected ndarray, got list"));
  EXPECT_THAT(test::InputErrorOf([&] { v.Key("list").At(9); }), HasSubstr("test.pkl: key 'list': index 9 out of range"));
}

TEST(Pickle, NumpyArraysOfSeveralDtypes) {
  PickleWriter w;
  w.Proto(2).EmptyList().Mark();
  w.Array({2, 3}, "f8", "<", false, test::RawOf(std::vector<double>{1, 2, 3, 4, 5, 6}));
  w.Array({2, 3}, "f8", "<", true, test::RawOf(std::vector<double>{1, 4, 2, 5, 3, 6}));  // Fortran order
  w.Array({3}, "f4", "<", false, test::RawOf(std::vector<float>{0.5f, -1.5f, 3.25f}));
  w.Array({2}, "i8", "<", false, test::RawOf(std::vector<std::int64_t>{-7, 1LL << 40}));
  w.Array({2}, "u1", "|", false, ByteVec{200, 3});
  w.Array({2}, "b1", "|", false, ByteVec{1, 0});
  w.Array({2}, "i4", ">", false, ByteVec{0xff, 0xff, 0xff, 0xfe, 0, 0, 1, 0});  // big endian -2, 256
  w.Array({}, "f8", "<", false, test::RawOf(std::vector<double>{42.0}));       // 0-d
  w.Array({0, 17, 3}, "f8", "<", false, ByteVec{});
  w.Appends().Stop();
  const PyView v = Parse(w);
  ASSERT_EQ(v.Size(), 9u);
  const std::vector<double> expected{1, 2, 3, 4, 5, 6};
  EXPECT_EQ(v.At(0).ToDoubles({2, 3}), expected);
  EXPECT_EQ(v.At(1).ToDoubles({2, 3}), expected);
  EXPECT_EQ(v.At(2).ToDoubles({-1}), (std::vector<double>{0.5, -1.5, 3.25}));
  EXPECT_EQ(v.At(3).AsArray().ElementAsInt(1), 1LL << 40);
  EXPECT_EQ(v.At(4).ToDoubles(), (std::vector<double>{200, 3}));
  EXPECT_EQ(v.At(5).ToDoubles(), (std::vector<double>{1, 0}));
  EXPECT_EQ(v.At(6).ToDoubles(), (std::vector<double>{-2, 256}));
  EXPECT_DOUBLE_EQ(v.At(7).AsDouble(), 42.0);
  EXPECT_EQ(v.At(8).AsArray().Size(), 0u);
  EXPECT_THAT(test::InputErrorOf([&] { v.At(0).ToDoubles({3, 2}); }), HasSubstr("[0]: expected shape (3, 2), got ndarray <f8 (2, 3)"));
}

TEST(Pickle, StructuredDtypeFromPickle) {
  // dtype([('R','<f4',(2,2)), ('id','<i2')]) pickled like numpy does: a 'V18' record with
  // names/fields state and a sub-array dtype for 'R'.
  PickleWriter w;
  w.Proto(3).ArrayBegin().ShapeTuple({2});
  w.Global("numpy", "dtype").Str("V18").Bool(false).Bool(true).Tuple3().Reduce().Put(10);
  w.Mark().Int(3).Str("|").None();
  w.Mark().Str("R").Str("id").Tuple();
  w.EmptyDict().Mark();
  w.Str("R");
  w.Global("numpy", "dtype").Str("V16").Bool(false).Bool(true).Tuple3().Reduce();
  w.Mark().Int(3).Str("|");
  w.DType("f4", "<").Mark().Int(2).Int(2).Tuple().Tuple2();  // sub-array (base, shape)
  w.None().None().Int(16).Int(4).Int(0).Tuple().Build();
  w.Int(0).Tuple2();
  w.Str("id").DType("i2", "<").Int(16).Tuple2();
  w.SetItems();
  w.Int(18).Int(1).Int(16).Tuple().Build();
  ByteVec data;
  for (int r = 0; r < 2; ++r) {
    test::Append(data, test::RawOf(std::vector<float>{1.0f + r, 2, 3, 4}));
    test::Append(data, test::RawOf(std::vector<std::int16_t>{static_cast<std::int16_t>(100 + r)}));
  }
  w.Bool(false).Bytes(test::AsString(data)).ArrayEnd().Stop();
  const PyView v = Parse(w);
  const NdArray& a = v.AsArray();
  ASSERT_TRUE(a.dtype.IsStructured());
  EXPECT_EQ(a.dtype.item_size, 18u);
  ASSERT_EQ(a.dtype.fields.size(), 2u);
  EXPECT_EQ(a.dtype.fields[0].shape, (std::vector<std::int64_t>{2, 2}));
  EXPECT_EQ(a.dtype.fields[1].offset, 16u);
  EXPECT_EQ(v.Field("R").ToDoubles({2, 2, 2}), (std::vector<double>{1, 2, 3, 4, 2, 2, 3, 4}));
  EXPECT_EQ(v.Field("id").ToDoubles({2}), (std::vector<double>{100, 101}));
  EXPECT_THAT(test::InputErrorOf([&] { v.Field("K"); }), HasSubstr("no field 'K' (fields: R, id)"));
}

TEST(Pickle, ObjectArrayScalarsAndDefaultdict) {
  PickleWriter w;
  w.Proto(2).Global("collections", "defaultdict").Global("builtins", "list").Tuple1().Reduce().Mark();
  // A 1-d object array holding a dict and None.
  w.Str("objects").ArrayBegin().ShapeTuple({2}).DType("O8", "|", -1, -1, 63).Bool(false);
  w.EmptyList().Mark().EmptyDict().Str("x").Int(1).SetItem().None().Appends();
  w.ArrayEnd();
  // numpy scalars: float64 and int64.
  w.Str("f64").Global("numpy.core.multiarray", "scalar").DType("f8", "<");
  w.Bytes(test::AsString(test::RawOf(std::vector<double>{1.5}))).Tuple2().Reduce();
  w.Str("i64").Global("numpy._core.multiarray", "scalar").DType("i8", "<");
  w.Bytes(test::AsString(test::RawOf(std::vector<std::int64_t>{-3}))).Tuple2().Reduce();
  // Unicode array.
  w.Str("names");
  ByteVec u = test::RawOf(std::vector<std::uint32_t>{'a', 'b', 'c', 0});
  w.ArrayBegin().ShapeTuple({2}).DType("U2", "<", 8, 4, 8).Bool(false).Bytes(test::AsString(u)).ArrayEnd();
  w.SetItems().Stop();
  const PyView v = Parse(w);
  EXPECT_TRUE(v.value().is_defaultdict);
  const PyView objects = v.Key("objects");
  ASSERT_EQ(objects.Size(), 2u);
  EXPECT_EQ(objects.At(0).Key("x").AsInt(), 1);
  EXPECT_TRUE(objects.At(1).IsNone());
  EXPECT_DOUBLE_EQ(v.Key("f64").AsDouble(), 1.5);
  EXPECT_EQ(v.Key("i64").AsInt(), -3);
  EXPECT_EQ(v.Key("names").AsArray().ElementAsString(0), "ab");
  EXPECT_EQ(v.Key("names").AsArray().ElementAsString(1), "c");
}

TEST(Pickle, Protocol2BytesViaCodecsEncode) {
  // Python 3 writes bytes at protocol 2 as _codecs.encode(latin-1 text, 'latin1').
  PickleWriter w;
  w.Proto(2).Global("numpy.core.multiarray", "_reconstruct").Global("numpy", "ndarray").Int(0).Tuple1();
  w.Global("_codecs", "encode").Put(1).Str("b").Str("latin1").Tuple2().Reduce().Tuple3().Reduce();
  w.Mark().Int(1).ShapeTuple({2}).DType("u1", "|").Bool(false);
  w.Get(1).Str("\xc3\xbf\x07").Str("latin1").Tuple2().Reduce();  // "\u00ff\x07" in UTF-8
  w.ArrayEnd().Stop();
  EXPECT_EQ(Parse(w).ToDoubles(), (std::vector<double>{255, 7}));
}

TEST(Pickle, Protocol5FrameStackGlobalMemoizeFrombuffer) {
  PickleWriter body;
  body.Proto(5);  // sets SHORT_BINUNICODE use; the PROTO bytes are dropped below
  body.bytes.clear();
  body.Str("numpy.core.numeric").Op(0x94).Str("_frombuffer").Op(0x94).Op(0x93).Op(0x94).Mark();
  const ByteVec data = test::RawOf(std::vector<double>{1, 2, 3, 4});
  body.Op(0x96);
  test::AppendLE(body.bytes, data.size(), 8);
  body.Raw(data);
  body.Str("numpy").Str("dtype").Op(0x93).Str("f8").Bool(false).Bool(true).Tuple3().Op('R');
  body.Mark().Int(3).Str("<").None().None().None().Int(-1).Int(-1).Int(0).Tuple().Build();
  body.Int(2).Int(2).Tuple2().Str("F").Tuple().Reduce().Op(0x94).Stop();
  ByteVec bytes = {0x80, 5, 0x95};
  test::AppendLE(bytes, body.bytes.size(), 8);
  test::Append(bytes, body.bytes);
  const PyView v = ParsePickle(bytes, "p5.pkl");
  EXPECT_TRUE(v.AsArray().fortran_order);
  EXPECT_EQ(v.ToDoubles({2, 2}), (std::vector<double>{1, 3, 2, 4}));
}

TEST(Pickle, SharedReferencesThroughMemo) {
  PickleWriter w;
  w.Proto(3).EmptyList().Put(0).Mark();
  w.EmptyDict().Put(1).Str("k").Int(1).SetItem();
  w.Get(1).Get(1).Appends().Stop();
  const PyView v = Parse(w);
  ASSERT_EQ(v.Size(), 3u);
  EXPECT_EQ(v.At(2).Key("k").AsInt(), 1);
  EXPECT_EQ(v.At(0).ptr(), v.At(2).ptr());
}

// ---------------------------------------------------------------------------------------
// Hostile and malformed input

TEST(Pickle, RefusesDisallowedGlobals) {
  PickleWriter w;
  w.Proto(2).Global("os", "system").Str("echo pwned").Tuple1().Reduce().Stop();
  const std::string msg = test::InputErrorOf([&] { Parse(w, "evil.pkl"); });
  EXPECT_THAT(msg, HasSubstr("evil.pkl"));
  EXPECT_THAT(msg, HasSubstr("'os.system' is not allowed"));
  EXPECT_THAT(msg, HasSubstr("GLOBAL (0x63) at byte 2"));

  PickleWriter s;
  s.Proto(4).Str("builtins").Str("eval").Op(0x93).Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(s, "evil4.pkl"); }), HasSubstr("'builtins.eval' is not allowed"));

  PickleWriter r;  // an allowed class passed to _reconstruct must still be ndarray
  r.Proto(2).Global("numpy.core.multiarray", "_reconstruct").Global("collections", "OrderedDict").Int(0).Tuple1()
      .Bytes("b").Tuple3().Reduce().Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(r); }), HasSubstr("only numpy.ndarray can be reconstructed"));
}

TEST(Pickle, RefusesUnknownAndUnsupportedOpcodes) {
  PickleWriter w;
  w.Proto(2).None().Op(0xff);
  EXPECT_THAT(test::InputErrorOf([&] { Parse(w, "odd.pkl"); }), HasSubstr("odd.pkl: unknown pickle opcode 0xff at byte 3"));
  PickleWriter p;
  p.Proto(2).Op('P');
  p.bytes.push_back('1');
  p.bytes.push_back('\n');
  EXPECT_THAT(test::InputErrorOf([&] { Parse(p); }), HasSubstr("persistent ids are not supported"));
  PickleWriter t;
  t.Op('I');
  EXPECT_THAT(test::InputErrorOf([&] { Parse(t); }), HasSubstr("text (protocol 0/1) opcodes"));
  PickleWriter v;
  v.Proto(6);
  EXPECT_THAT(test::InputErrorOf([&] { Parse(v); }), HasSubstr("unsupported pickle protocol 6"));
}

TEST(Pickle, TruncatedAtEveryCutThrowsInputError) {
  PickleWriter w;
  w.Proto(3).EmptyDict().Mark().Str("pred");
  w.Array({17, 3}, "f8", "<", false, test::RawOf(std::vector<double>(51, 1.0)));
  w.Str("name").Str("camera").SetItems().Stop();
  ASSERT_NO_THROW(Parse(w));
  for (std::size_t cut = 0; cut < w.bytes.size(); ++cut) {
    const std::string msg = test::InputErrorOf([&] { ParsePickle(std::span(w.bytes).first(cut), "cut.pkl"); });
    EXPECT_THAT(msg, HasSubstr("cut.pkl")) << "cut at " << cut;
  }
}

TEST(Pickle, MalformedStructure) {
  PickleWriter a;
  a.Proto(2).Int(1).Append().Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(a); }), HasSubstr("stack underflow"));
  PickleWriter b;
  b.Proto(2).Get(7).Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(b); }), HasSubstr("memo entry 7 was never stored"));
  PickleWriter c;
  c.Proto(2).Int(1).Tuple().Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(c); }), HasSubstr("no MARK"));
  PickleWriter d;
  d.Proto(2).EmptyDict().EmptyList().Int(1).SetItem().Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(d); }), HasSubstr("unhashable dict key of type list"));
  PickleWriter e;  // array data length disagrees with shape
  e.Proto(2).Array({4}, "f8", "<", false, ByteVec(24, 0)).Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(e); }), HasSubstr("ndarray data has 24 bytes, shape and dtype <f8 need 32"));
  PickleWriter f;
  f.Proto(2).Int(1).Build().Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(f); }), HasSubstr("stack underflow"));
}

TEST(Pickle, ShapeOverflowRefused) {
  PickleWriter w;
  w.Proto(2).ArrayBegin().ShapeTuple({std::int64_t{1} << 62, std::int64_t{1} << 62}).DType("f8", "<").Bool(false)
      .Bytes("").ArrayEnd().Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(w); }), HasSubstr("overflows"));
  PickleWriter n;
  n.Proto(2).ArrayBegin().ShapeTuple({-1}).DType("f8", "<").Bool(false).Bytes("").ArrayEnd().Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(n); }), HasSubstr("negative array dimension"));
}

TEST(Pickle, RecursionBombRefused) {
  constexpr int kDepth = 50000;
  PickleWriter lists;
  lists.Proto(2);
  for (int i = 0; i < kDepth; ++i) lists.EmptyList();
  for (int i = 1; i < kDepth; ++i) lists.Append();
  lists.Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(lists); }), HasSubstr("nests deeper than 200 levels"));

  PickleWriter tuples;
  tuples.Proto(2).EmptyTuple();
  for (int i = 0; i < kDepth; ++i) tuples.Tuple1();
  tuples.Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(tuples); }), HasSubstr("nests deeper"));

  // Deep garbage that is popped off the stack must not blow up the destructor either.
  PickleWriter garbage;
  garbage.Proto(2).EmptyTuple();
  for (int i = 0; i < kDepth; ++i) garbage.Tuple1();
  garbage.Pop().None().Stop();
  EXPECT_TRUE(Parse(garbage).IsNone());

  // Deep tuple keys are refused instead of recursing.
  PickleWriter keys;
  keys.Proto(2).EmptyDict().EmptyTuple();
  for (int i = 0; i < 100; ++i) keys.Tuple1();
  keys.None().SetItem().Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(keys); }), HasSubstr("unhashable"));
}

TEST(Pickle, CycleRefused) {
  PickleWriter w;
  w.Proto(2).EmptyList().Put(0).Get(0).Append().Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(w); }), HasSubstr("reference cycle"));
}

TEST(Pickle, QuadraticCopyingBounded) {
  // list(x) on one 1000-item list, 20000 times: refused by the work limit, quickly.
  PickleWriter w;
  w.Proto(2).Global("builtins", "list").Put(0).EmptyList().Mark();
  for (int i = 0; i < 1000; ++i) w.Int(1);
  w.Appends().Put(1).Pop().Pop();
  for (int i = 0; i < 20000; ++i) w.Get(0).Get(1).Tuple1().Reduce().Pop();
  w.None().Stop();
  EXPECT_THAT(test::InputErrorOf([&] { Parse(w); }), HasSubstr("resource limit"));
}

TEST(Pickle, MissingFileNamesPath) {
  EXPECT_THAT(test::InputErrorOf([] { ReadPickle("/nonexistent/dir/cameras.pkl"); }),
              HasSubstr("/nonexistent/dir/cameras.pkl: file not found"));
}

TEST(Pickle, ReadFromFile) {
  test::TempDir dir;
  PickleWriter w;
  w.Proto(3).Str("hello").Stop();
  EXPECT_EQ(ReadPickle(dir.Write("s.pkl", w.bytes)).AsStr(), "hello");
}

}  // namespace
}  // namespace rpt::io
