// SPDX-License-Identifier: MIT
// The libFuzzer entry point of every format: the environment variable RPT_FUZZ_TARGET names the
// target (fuzz/fuzz_targets.cc), e.g. RPT_FUZZ_TARGET=coco build-asan/fuzz/rpt_fuzz CORPUS
// (scripts/fuzz.sh runs each format this way).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "fuzz/fuzz_targets.h"

namespace {

const rpt::fuzz::FuzzTarget& Target() {
  static const rpt::fuzz::FuzzTarget* target = [] {
    const char* name = std::getenv("RPT_FUZZ_TARGET");
    const rpt::fuzz::FuzzTarget* found = name == nullptr ? nullptr : rpt::fuzz::FindFuzzTarget(name);
    if (found == nullptr) {
      std::fprintf(stderr, "rpt_fuzz: set RPT_FUZZ_TARGET to one of:");
      for (const rpt::fuzz::FuzzTarget& t : rpt::fuzz::FuzzTargets()) std::fprintf(stderr, " %s", t.name.c_str());
      std::fprintf(stderr, "%s%s%s\n", name ? " (got '" : "", name ? name : "", name ? "')" : "");
      std::exit(2);
    }
    return found;
  }();
  return *target;
}

}  // namespace

// Checks the target before fuzzing starts, so a wrong name fails at once.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
  Target();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // Input errors are the expected answer to bad bytes; any other exception escapes and aborts.
  rpt::fuzz::RunFuzzTarget(Target(), {data, size});
  return 0;
}
