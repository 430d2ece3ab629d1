// SPDX-License-Identifier: MIT
// The libFuzzer entry point of one format: compiled once per target with RPT_FUZZ_TARGET set to
// the target's name (fuzz/CMakeLists.txt), so each format is its own executable rpt_fuzz_<name>.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz/fuzz_targets.h"

namespace {

const rpt::fuzz::FuzzTarget& Target() {
  static const rpt::fuzz::FuzzTarget* target = [] {
    const rpt::fuzz::FuzzTarget* found = rpt::fuzz::FindFuzzTarget(RPT_FUZZ_TARGET);
    if (found == nullptr) {
      std::fprintf(stderr, "rpt fuzzer: unknown target '%s'\n", RPT_FUZZ_TARGET);
      std::abort();
    }
    return found;
  }();
  return *target;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Input errors are the expected answer to bad bytes; any other exception escapes and aborts.
  rpt::fuzz::RunFuzzTarget(Target(), {data, size});
  return 0;
}
