// SPDX-License-Identifier: MIT
#include "engine/parallel_for.h"

#include <exception>
#include <mutex>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "engine/thread_count.h"

namespace rpt::engine {

int ParallelFor(int count, [[maybe_unused]] int threads, const std::function<void(int, bool)>& body) {
  std::exception_ptr error;
  std::mutex error_mutex;
  int used = 1;
#ifdef _OPENMP
  const int team = ClampThreads(threads, count);
  used = team;
#pragma omp parallel for schedule(dynamic) num_threads(team)
#endif
  for (int i = 0; i < count; ++i) {
    try {
#ifdef _OPENMP
      body(i, omp_get_thread_num() == 0);
#else
      body(i, true);
#endif
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
  return used;
}

}  // namespace rpt::engine
