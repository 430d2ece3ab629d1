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

bool InstallMemoryReserve(std::size_t bytes) {
  void* block = std::malloc(bytes);
  if (block == nullptr) return false;
  std::free(reserve.exchange(block));
  std::set_new_handler(ReleaseReserveAndFail);
  return true;
}

}  // namespace rpt::cli
