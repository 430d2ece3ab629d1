// SPDX-License-Identifier: MIT
// One part file per sequence beside a target file, joined in sequence order when the run is
// complete: how the streaming exports (predictions.csv, ...) write sequences that run on
// different threads at once without holding their frames.
#pragma once

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "datasets/io/staged_output.h"

namespace rpt::engine {

class PartFiles {
 public:
  PartFiles(std::filesystem::path target, int num_sequences);
  ~PartFiles();  // removes the parts left
  PartFiles(const PartFiles&) = delete;
  PartFiles& operator=(const PartFiles&) = delete;

  // Creates the part of `sequence` (InputError naming it when it cannot).
  std::ostream& Open(int sequence);
  std::ostream& Out(int sequence) { return parts_[sequence].out; }
  // Flushes and closes it; InputError naming it when the writes failed.
  void Close(int sequence);
  // Writes the target: `head`, the parts in sequence order, `tail`; removes the parts.
  void Join(const std::string& head, const std::string& tail);

 private:
  struct Part {
    std::unique_ptr<io::ScratchFile> scratch;
    std::filesystem::path path;
    std::ofstream out;
  };
  std::filesystem::path target_;
  std::vector<Part> parts_;
};

}  // namespace rpt::engine
