// SPDX-License-Identifier: MIT
// rpt_fuzz_seeds OUT_DIR: writes the seed corpus of every fuzz target to OUT_DIR/<target>/
// (scripts/fuzz.sh runs it before fuzzing).
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "fuzz/fuzz_seeds.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: rpt_fuzz_seeds OUT_DIR\n");
    return 2;
  }
  const std::filesystem::path out = argv[1];
  for (const auto& [target, files] : rpt::fuzz::MakeFuzzSeeds()) {
    std::filesystem::create_directories(out / target);
    for (const auto& [name, bytes] : files) {
      std::ofstream file(out / target / name, std::ios::binary);
      file.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
      if (!file) {
        std::fprintf(stderr, "rpt_fuzz_seeds: cannot write %s\n", (out / target / name).c_str());
        return 1;
      }
    }
  }
  return 0;
}
