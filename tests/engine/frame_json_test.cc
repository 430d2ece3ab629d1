// SPDX-License-Identifier: MIT
// One frame as JSON (engine/outputs/frame_json.h): times and coordinates with their fixed decimals,
// and numbers too large for any decimal in their shortest exact form.
#include "engine/outputs/frame_json.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

namespace rpt::engine {
namespace {

std::string FrameText(double time_s, double x) {
  SequenceFrame input;
  input.id = "f";
  input.timestamp_s = time_s;
  Poses3D persons;
  persons.Clear(1);
  auto person = persons.AddPerson();
  person.col(0) << x, 2.0, 3.0, 1.0;
  const FrameStats stats;
  std::string out;
  AppendFrameJson(FrameOutput{0, &input, &persons, &stats}, ExportOptions{}, &out);
  return out;
}

TEST(FrameJson, FixedDecimalsAndHugeNumbersInTheirShortestForm) {
  const std::string normal = FrameText(0.04, 1.25);
  EXPECT_NE(normal.find("\"time\": 0.040000,"), std::string::npos) << normal;
  EXPECT_NE(normal.find("[[1.250000, 2.000000, 3.000000, 1.0000]]"), std::string::npos) << normal;
  // A live stream's absurd time was written as a 309-digit fixed number.
  const std::string huge = FrameText(1e308, -3e15);
  EXPECT_NE(huge.find("\"time\": 1e+308,"), std::string::npos) << huge;
  EXPECT_NE(huge.find("[[-3e+15, "), std::string::npos) << huge;
  EXPECT_EQ(nlohmann::json::parse(huge)["time"].get<double>(), 1e308);
  EXPECT_NE(FrameText(999999999999999.0, 0).find("\"time\": 999999999999999.000000,"), std::string::npos)
      << "below 1e15: fixed decimals";
}

}  // namespace
}  // namespace rpt::engine
