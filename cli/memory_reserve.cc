// SPDX-License-Identifier: MIT
#include "cli/memory_reserve.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace rpt::cli {
namespace {

std::atomic<void*> reserve{nullptr};

// operator new calls this when an allocation fails: the reserve goes back to the system and the
// allocation fails as it would have. Later failures find no reserve and just throw.
void ReleaseReserveAndFail() {
  std::free(reserve.exchange(nullptr));
  throw std::bad_alloc();
}

}  // namespace

void InstallMemoryReserve(std::size_t bytes) {
  std::free(reserve.exchange(std::malloc(bytes)));
  std::set_new_handler(ReleaseReserveAndFail);
}

}  // namespace rpt::cli
