// SPDX-License-Identifier: MIT
// rpt.datasets.Frame: one frame with the header of its sequence (shared, not copied per frame).
#pragma once

#include <memory>

#include "datasets/sequence.h"

namespace rpt::python {

struct Frame {
  std::shared_ptr<const SequenceHeader> sequence;
  SequenceFrame frame;
};

}  // namespace rpt::python
