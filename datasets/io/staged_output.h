// SPDX-License-Identifier: MIT
// Outputs built under a temporary name beside their target and renamed over it only when complete,
// so neither a reader nor an interrupted run ever sees a half-written file or a half-replaced
// folder. Every temporary is registered; RemoveTemporariesForExit (called by the interrupt handler,
// cli/interrupt.h) removes those still present. Temporaries are named `<target>.tmp-<pid>-<n>`; one
// is left behind only when the process is killed with SIGKILL (or the machine fails): delete it.
#pragma once

#include <filesystem>
#include <string>

namespace rpt::io {

// A file written under a temporary name in the target's folder, then renamed over the target by
// Commit(). Destroyed without Commit(), the temporary is removed and the target stays as it was.
// A target that exists and is not a regular file (/dev/full, /dev/stdout, a FIFO) is written in
// place: it cannot be replaced by a rename.
class StagedFile {
 public:
  // Creates the (empty) temporary; throws InputError naming the target when it cannot.
  explicit StagedFile(const std::filesystem::path& target);
  ~StagedFile();
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  const std::filesystem::path& path() const { return temporary_; }  // where to write
  const std::filesystem::path& target() const { return target_; }
  // Flushes the temporary to disk and renames it over the target; throws InputError naming the target.
  void Commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temporary_;
  bool pending_ = false;  // a registered temporary exists
};

// A folder whose new contents are built in a sibling (`<folder>.tmp-<pid>-<n>`) and swapped in as a
// whole by Commit() (one atomic exchange of the two names where the file system supports it, else
// two renames): the folder holds either its complete old or its complete new contents. Entries of
// the old folder are carried over into the new one first (hard links; the new files replace them),
// so files other commands keep there (another shard's tables, a report) survive. When the folder is
// the current directory or holds it, the swap is impossible: files are then replaced one by one
// in place (each still atomic) and in_place() is true.
class StagedFolder {
 public:
  explicit StagedFolder(const std::filesystem::path& target);  // throws InputError naming the folder
  ~StagedFolder();
  StagedFolder(const StagedFolder&) = delete;
  StagedFolder& operator=(const StagedFolder&) = delete;

  const std::filesystem::path& path() const { return staging_; }  // where to write the files
  const std::filesystem::path& target() const { return target_; }
  bool in_place() const { return staging_ == target_; }
  void Commit();  // throws InputError naming the folder
  // `message` with the staging folder's name replaced by the folder's: errors name the real output.
  std::string NamedAsTarget(std::string message) const;

 private:
  std::filesystem::path target_;
  std::filesystem::path staging_;
  bool pending_ = false;
};

// A file the process writes for its own use and never keeps (rpt bench's HDF5 round trip): created
// empty and registered as `<name_like>.tmp-<pid>-<n>` (so Ctrl-C removes it like the temporaries
// above) and removed by the destructor on every other way out, an exception included.
class ScratchFile {
 public:
  // Creates the (empty) file; throws InputError naming it when it cannot.
  explicit ScratchFile(const std::filesystem::path& name_like);
  ~ScratchFile();
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Removes every registered temporary (files and folders) and returns how many it removed. Keeps
// the registry locked for good, so no thread creates or commits a temporary afterwards: call it
// only right before the process exits.
int RemoveTemporariesForExit();

}  // namespace rpt::io
