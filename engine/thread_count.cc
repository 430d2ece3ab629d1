// SPDX-License-Identifier: MIT
#include "engine/thread_count.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <thread>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "core/errors.h"

namespace rpt::engine {

int ClampThreads(int requested, long work) {
  if (requested < 0) throw ConfigError("--threads: " + std::to_string(requested) + " is negative (0 = automatic)");
  const int hardware = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
#ifdef _OPENMP
  const int automatic = omp_get_max_threads();
#else
  const int automatic = 1;
#endif
  int threads = requested > 0 ? requested : automatic;
  if (requested > hardware) {
    std::fprintf(stderr, "note: --threads %d is more than the %d hardware threads; using %d\n", requested, hardware,
                 hardware);
  }
  threads = std::min(threads, hardware);
  return static_cast<int>(std::clamp<long>(work, 1, threads));
}

}  // namespace rpt::engine
