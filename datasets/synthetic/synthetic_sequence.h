// SPDX-License-Identifier: MIT
// A generated scene plus simulated detections as a dataset-independent Sequence, so synthetic
// data runs through exactly the same evaluation path as real datasets.
#pragma once

#include <cstdint>
#include <string>

#include "datasets/sequence.h"
#include "datasets/synthetic/detector_simulator.h"
#include "datasets/synthetic/scene.h"

namespace rpt::synthetic {

// Frame ids are "<name>_000000", ...; timestamps frame / fps; detections use the scene's joints;
// labels_2d are the simulator's view of the GT (which joints its occluders hid).
Sequence MakeSyntheticSequence(const Scene& scene, const DetectorOptions& detector, uint64_t seed,
                               const std::string& name = "synthetic");

}  // namespace rpt::synthetic
