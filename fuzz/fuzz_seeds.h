// SPDX-License-Identifier: MIT
// Seed inputs of every fuzz target, made at run time with the project's own writers
// (WriteLabels, WriteGenericDetections, the HDF5 cache writers) or written out by hand here:
// nothing is copied from ../shared/data or elsewhere. Each target gets at least one seed its
// reader accepts, so the fuzzers start from inputs that reach deep into the parsers.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace rpt::fuzz {

using Bytes = std::vector<std::uint8_t>;

// target name -> seed files (name, bytes).
std::map<std::string, std::vector<std::pair<std::string, Bytes>>> MakeFuzzSeeds();

}  // namespace rpt::fuzz
