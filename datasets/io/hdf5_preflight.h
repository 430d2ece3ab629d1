// SPDX-License-Identifier: MIT
// Walks an HDF5 file's metadata in a child process before rpt reads it in its own.
//
// HDF5 1.10 (Debian 12) trusts addresses inside the file's metadata: a damaged group symbol table
// or local heap makes it crash (SIGSEGV in H5F__accum_read below H5G__stab_lookup) or read past
// its buffers (CVE-2025-2310) instead of reporting an error, and rpt cannot check every such
// structure itself without re-implementing the library's parser. So every HDF5 file rpt reads is
// first walked by a forked child: it opens every object reachable from the root (looking each up
// by name, as the readers do), every attribute (name, type, shape, value) and every dataset
// (type, shape, layout; the data itself of datasets that are not plain contiguous numbers:
// chunked, compressed, compact or variable-length strings). A child that dies, is killed by a
// sanitizer or does not finish within the time limit leaves rpt with a clear InputError instead
// of a crash or hang; a child that finishes (or meets an error the library reports) lets the
// reader go on, which then reports any error with the object's path.
//
// The walk costs a fork and the metadata reads; `rpt bench --io` times it beside the read it
// precedes (docs/robustness.md). A file of at most 1 MiB that passed is remembered by its bytes
// and not walked again; larger files are walked each time a reader opens them (a file rewritten
// within the same clock tick keeps its size and time stamp, so those are no key). Where fork() is
// not available or fails, the walk is skipped and the file is read as before.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>

namespace rpt::io {

inline constexpr std::chrono::seconds kHdf5PreflightLimit{60};

// On by default. Tests of the readers' own checks turn it off, so that those checks are tested
// without the walk behind them (process-wide).
void SetHdf5Preflight(bool enabled);
bool Hdf5PreflightEnabled();
// Forgets the small files that passed, so the next open walks again (`rpt bench --io` times walks).
void ForgetPassedHdf5Files();

// Throws InputError "<source>: the HDF5 library crashed (signal N) walking the file's metadata:
// the file is damaged" (or "did not finish ... within 60 s"). `inflate_limit`: the most data the
// walk may read from one dataset (the reader's decompression budget; larger datasets are left to
// the reader, which refuses them).
void PreflightHdf5(const std::string& source, const std::filesystem::path& path, std::uint64_t inflate_limit,
                   std::chrono::milliseconds limit = kHdf5PreflightLimit);

// The walk itself, in this process (the child's body). Returns true when it reached every
// object, false when the library reported an error on the way.
bool WalkHdf5Metadata(const std::filesystem::path& path, std::uint64_t inflate_limit);

}  // namespace rpt::io
