// SPDX-License-Identifier: MIT
// The generated scene of `rpt eval --dataset synthetic --param ...` (25 frames per second unless
// fps= says otherwise), as one Sequence with its simulated detections.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "engine/input.h"

namespace rpt::test {

inline Sequence SyntheticScene(const std::vector<std::string>& params) {
  engine::InputSpec spec;
  spec.dataset = "synthetic";
  spec.params = params;
  InputWarnings warnings;
  std::vector<Sequence> sequences = engine::LoadInput(spec, {}, &warnings);
  return std::move(sequences.at(0));
}

}  // namespace rpt::test
