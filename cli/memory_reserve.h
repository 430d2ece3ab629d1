// SPDX-License-Identifier: MIT
// Out of memory without std::terminate. When an allocation fails, the exception unwinds through
// destructors, and some of them allocate (nlohmann::json frees a deep value through a heap stack):
// failing there, inside a noexcept destructor, aborted the process (exit 134) instead of printing
// "out of memory". A reserve of address space is taken at start and given back at the first failed
// allocation, just before std::bad_alloc is thrown, so the unwinding and the error message have
// memory to run on.
#pragma once

#include <cstddef>

namespace rpt::cli {

// Reserves `bytes` (not touched: it costs address space, not resident memory) and installs the
// new-handler that releases it and throws std::bad_alloc. Call once, first thing in main(). False
// when the reserve itself cannot be had: the process is at its memory limit before doing anything,
// and any allocation could end in std::terminate (the caller stops with an error).
bool InstallMemoryReserve(std::size_t bytes);

}  // namespace rpt::cli
