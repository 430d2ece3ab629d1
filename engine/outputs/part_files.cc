// SPDX-License-Identifier: MIT
#include "engine/outputs/part_files.h"

#include <cerrno>
#include <cstring>

#include "core/errors.h"
#include "datasets/io/staged_output.h"
#include "datasets/io/text_file.h"

namespace rpt::engine {

PartFiles::PartFiles(std::filesystem::path target, int num_sequences)
    : target_(std::move(target)), parts_(static_cast<size_t>(num_sequences)) {}

PartFiles::~PartFiles() {
  for (Part& part : parts_) part.out.close();  // before the scratch files go
}

std::ostream& PartFiles::Open(int sequence) {
  Part& part = parts_[sequence];
  std::filesystem::path name_like = target_;
  name_like += ".part-" + std::to_string(sequence);
  // A new scratch file (never an existing name, so never through a link), removed with the parts.
  part.scratch = std::make_unique<io::ScratchFile>(name_like);
  part.path = part.scratch->path();
  part.out.open(part.path, std::ios::binary | std::ios::trunc);
  if (!part.out) throw InputError(part.path.string() + ": cannot open for writing: " + std::strerror(errno));
  return part.out;
}

void PartFiles::Close(int sequence) {
  Part& part = parts_[sequence];
  part.out.flush();
  // Named as the file it is a part of (the part's scratch name is nothing the user knows).
  if (!part.out) throw InputError(target_.string() + ": write failed (" + io::WriteFailureReason(part.path, errno) + ")");
  part.out.close();
}

void PartFiles::Join(const std::string& head, const std::string& tail) {
  io::WriteTextFile(target_, io::NamedBy::kRpt, [&](std::ostream& out) {
    out << head;
    for (const Part& part : parts_) {
      if (part.path.empty()) continue;
      std::ifstream in(part.path, std::ios::binary);
      if (!in) throw InputError(part.path.string() + ": cannot read back: " + std::strerror(errno));
      if (in.peek() != std::ifstream::traits_type::eof()) out << in.rdbuf();
    }
    out << tail;
  });
  for (Part& part : parts_) {
    if (part.path.empty()) continue;
    std::error_code ec;
    std::filesystem::remove(part.path, ec);
    part.path.clear();
  }
}

}  // namespace rpt::engine
