// SPDX-License-Identifier: MIT
#include "engine/outputs/csv_export.h"

#include <cmath>
#include <cstdio>

#include "engine/outputs/results_writer.h"
#include "engine/outputs/text_escaping.h"
#include "engine/outputs/fixed_decimal.h"

namespace rpt::engine {

CsvExport::CsvExport(std::filesystem::path path, int num_sequences, ExportOptions options)
    : options_(std::move(options)), parts_(std::move(path), num_sequences), sequences_(num_sequences) {}

void CsvExport::BeginSequence(int sequence, const SequenceHeader& header, const JointNames& output_joints) {
  Sequence& s = sequences_[sequence];
  s.name = CsvField(header.name);
  s.joints.clear();
  for (const std::string& joint : output_joints) s.joints.push_back(CsvField(joint));
  s.frames = 0;
  parts_.Open(sequence);
}

void CsvExport::Frame(const FrameOutput& frame) {
  Sequence& s = sequences_[frame.sequence];
  std::ostream& out = parts_.Out(frame.sequence);
  const long frame_idx = s.frames++;
  const Poses3D& persons = *frame.persons;
  if (persons.num_persons() == 0) return;
  // What every row of the frame starts with.
  std::string prefix = s.name + "," + std::to_string(frame_idx) + "," + CsvField(frame.input->id) + ",";
  if (std::isfinite(frame.input->timestamp_s)) AppendFixedDecimal(frame.input->timestamp_s, 6, &prefix);
  prefix += ",";
  std::string numbers;
  for (int p = 0; p < persons.num_persons(); ++p) {
    const auto person = persons.Person(p);
    for (int j = 0; j < persons.num_joints; ++j) {
      if (!JointWritten(persons, p, j, options_)) continue;
      numbers.clear();
      for (int k = 0; k < 4; ++k) {  // printf's "%.6f,%.6f,%.6f,%.4f," in the C locale, whatever LC_NUMERIC says
        AppendFixedDecimal(person(k, j), k < 3 ? 6 : 4, &numbers);
        numbers += ',';
      }
      out << prefix << persons.track_ids[p] << "," << s.joints[j] << "," << numbers
          << ProvenanceName(persons.Provenance(p, j)) << "\n";
    }
  }
}

void CsvExport::EndSequence(int sequence) { parts_.Close(sequence); }

void CsvExport::Finish() {
  parts_.Join("sequence,frame,frame_id,time_s,track_id,joint,x_m,y_m,z_m,score,provenance\n", "");
}

}  // namespace rpt::engine
