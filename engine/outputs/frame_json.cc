// SPDX-License-Identifier: MIT
#include "engine/outputs/frame_json.h"

#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/utf8.h"
#include "datasets/io/json_output.h"
#include "engine/outputs/fixed_decimal.h"

namespace rpt::engine {
namespace {

void AppendNumber(double value, int decimals, std::string* out) {
  if (!std::isfinite(value)) {
    out->append("null");
    return;
  }
  // From 1e15 on a double has no digits after the point to give: the shortest exact form
  // ("1e+300"), not a 300-digit fixed number.
  if (std::fabs(value) >= 1e15) {
    char number[32];
    const auto end = std::to_chars(number, number + sizeof(number), value).ptr;
    out->append(number, end);
    return;
  }
  AppendFixedDecimal(value, decimals, out);
}

void AppendInt(long value, std::string* out) {
  char number[24];
  const auto end = std::to_chars(number, number + sizeof(number), value).ptr;
  out->append(number, end);
}

}  // namespace

void AppendJsonString(std::string_view text, std::string* out) {
  static constexpr char kHex[] = "0123456789abcdef";
  out->push_back('"');
  for (const char c : text) {
    switch (c) {
      case '"':
        out->append("\\\"");
        break;
      case '\\':
        out->append("\\\\");
        break;
      case '\b':
        out->append("\\b");
        break;
      case '\f':
        out->append("\\f");
        break;
      case '\n':
        out->append("\\n");
        break;
      case '\r':
        out->append("\\r");
        break;
      case '\t':
        out->append("\\t");
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          out->append("\\u00");
          out->push_back(kHex[(c >> 4) & 0xF]);
          out->push_back(kHex[c & 0xF]);
        } else {
          out->push_back(c);
        }
    }
  }
  out->push_back('"');
}

void AppendFrameJson(const FrameOutput& frame, const ExportOptions& options, std::string* out, int* replaced) {
  const Poses3D& persons = *frame.persons;
  out->append("{\"id\": ");
  if (IsValidUtf8(frame.input->id)) {
    AppendJsonString(frame.input->id, out);
  } else {
    out->append(io::DumpJson(nlohmann::json(frame.input->id), -1, replaced));
  }
  out->append(", \"time\": ");
  AppendNumber(frame.input->timestamp_s, 6, out);
  out->append(", \"persons\": [");
  for (int p = 0; p < persons.num_persons(); ++p) {
    const auto person = persons.Person(p);
    out->append(p ? ", [" : "[");
    for (int j = 0; j < persons.num_joints; ++j) {
      out->append(j ? ", [" : "[");
      if (!JointWritten(persons, p, j, options)) {
        out->append("null, null, null, 0");  // missing (score 0), or a filled joint not written
      } else {
        for (int row = 0; row < 4; ++row) {
          if (row) out->append(", ");
          AppendNumber(person(row, j), row < 3 ? 6 : 4, out);
        }
      }
      out->push_back(']');
    }
    out->push_back(']');
  }
  out->append("], \"track_ids\": [");
  for (int p = 0; p < persons.num_persons(); ++p) {
    if (p) out->append(", ");
    AppendInt(persons.track_ids[p], out);
  }
  out->append("], \"provenance\": [");
  for (int p = 0; p < persons.num_persons(); ++p) {
    out->append(p ? ", [" : "[");
    for (int j = 0; j < persons.num_joints; ++j) {
      if (j) out->push_back(',');
      AppendInt(static_cast<int>(persons.Provenance(p, j)), out);
    }
    out->push_back(']');
  }
  out->append("]}");
}

}  // namespace rpt::engine
