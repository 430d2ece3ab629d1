// SPDX-License-Identifier: MIT
// Outputs built under a temporary name beside their target and renamed over it only when complete,
// so neither a reader nor an interrupted run ever sees a half-written file or a half-replaced
// folder. Every temporary is registered; RemoveTemporariesForExit (called by the interrupt handler,
// cli/interrupt.h) removes those still present. Temporaries are named `<target>.tmp-<pid>-<n>`; one
// is left behind only when the process is killed with SIGKILL (or the machine fails): delete it.
//
// Nothing is ever written through a link: a link (or a hard link carried over from an old folder)
// at the name of a file rpt writes is replaced by the new file, and what it points to stays as it
// was; folders rpt creates inside an output folder replace links the same way (CreateFolderInside).
// A run folder received from someone else (a tarball) therefore cannot make rpt write outside it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace rpt::io {

// Who named a file rpt writes; it decides what happens to a device or FIFO found at the name. Links
// to anything else are never written through, whoever named the file.
enum class NamedBy {
  kRpt,   // a file rpt names inside an output folder (a run, sweep or render folder, RUN_DIR/report.html):
          // whatever is at the name (a link, a FIFO, a device) is replaced by the new file
  kUser,  // the path the user gave for the file itself (--out FILE, --junit FILE): a device or FIFO
          // there, or a link to one (/dev/null, /dev/full, a named pipe), is written to in place; one of
          // the process's own open files (`-`, /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N, or a
          // link to one) gets the complete file written to that descriptor by Commit(), whatever it is
          // (a pipe, a terminal, a log file stdout is redirected to: appended there, never truncated)
};

// Why a write to `file` failed, for "write failed (<reason>)": strerror of `saved_errno` when it is
// an error a write gives (no space, quota, file too large, I/O, read-only, permission); otherwise
// (a stream's failure leaves errno to whatever call came last: "No such file or directory" was said
// of a full disk) "No space left on device" when the file's file system has no free block left,
// "File too large" when the file has reached the process's file size limit (ulimit -f), else
// "reason unknown".
std::string WriteFailureReason(const std::filesystem::path& file, int saved_errno);

// A file written under a temporary name in the target's folder, then renamed over the target by
// Commit(). Destroyed without Commit(), the temporary is removed and the target stays as it was.
// A link at the target is replaced (the file it points to is not touched); so is a device or FIFO
// unless the user named the file (NamedBy::kUser: written in place, a rename cannot replace it).
class StagedFile {
 public:
  // Creates the (empty) temporary; throws InputError naming the target when it cannot. With
  // `keep_extension` the temporary's name also ends in the target's extension
  // (`cam.mp4.tmp-<pid>-<n>.mp4`), for writers that choose the format by it (OpenCV).
  StagedFile(const std::filesystem::path& target, NamedBy named_by, bool keep_extension = false);
  ~StagedFile();
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;

  const std::filesystem::path& path() const { return temporary_; }  // where to write
  const std::filesystem::path& target() const { return target_; }
  // Flushes the temporary to disk and renames it over the target; throws InputError naming the target.
  void Commit();

 private:
  void CopyToDescriptor() const;

  std::filesystem::path target_;
  std::filesystem::path temporary_;
  int descriptor_ = -1;   // the process's own file the target names (NamedBy::kUser), else -1
  bool pending_ = false;  // a registered temporary exists
};

// A folder whose new contents are built in a sibling (`<folder>.tmp-<pid>-<n>`) and swapped in as a
// whole by Commit() (one atomic exchange of the two names where the file system supports it, else
// two renames): the folder holds either its complete old or its complete new contents. Entries of
// the old folder are carried over into the new one first (hard links; the new files replace them),
// so files other commands keep there (another shard's tables, a report) survive. When the folder is
// the current directory or holds it, the swap is impossible: files are then replaced one by one
// in place (each still atomic) and in_place() is true.
//
// The folder named by the user may be a link to a folder: the folder it points to is replaced (the
// link is resolved once, at the start, and stays; target() is the resolved folder); a link to nothing
// is an InputError. A write-protected old folder (no write permission on it or on a folder inside
// it, or, for root, no owner write bit) is an InputError before anything is created: rpt does not
// replace what its owner protected, and could not remove the old contents after the swap.
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

// Creates `root / relative` folder by folder below `root` (an existing folder, e.g. a StagedFolder's
// path()) and returns it. A link, FIFO or device at the name of a folder to create is replaced by
// the folder, never followed, so nothing is created outside `root`; a regular file there is an
// InputError naming it. `relative` must be relative and free of "." and ".." (std::logic_error).
std::filesystem::path CreateFolderInside(const std::filesystem::path& root, const std::filesystem::path& relative);

// A file the process writes for its own use and never keeps (rpt bench's HDF5 round trip, the parts
// of predictions.json): created
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

// Creates the missing folders above a file the user names for a command's output (`rpt convert
// --labels-out new/labels.json`), as --out creates its folder; throws InputError naming the file.
// The destructor removes the folders it created, while they are empty, unless Keep() was called:
// a command that fails leaves no empty folders behind.
class ParentFolders {
 public:
  explicit ParentFolders(const std::filesystem::path& file);
  ~ParentFolders();
  ParentFolders(const ParentFolders&) = delete;
  ParentFolders& operator=(const ParentFolders&) = delete;
  void Keep() { created_.clear(); }

 private:
  std::vector<std::filesystem::path> created_;  // outermost first
};

// Temporaries of a killed rpt found beside (or, for a folder, inside) an output named for a
// StagedFolder or a user-named StagedFile: one warning line each ("<path>: left by an rpt process
// that was killed ..."), for the command to print; they are never removed (another machine's rpt
// on a shared folder may own one).
std::vector<std::string> StaleTemporaryWarnings();

// Removes every registered temporary (files and folders) and returns how many it removed. Keeps
// the registry locked for good, so no thread creates or commits a temporary afterwards: call it
// only right before the process exits.
int RemoveTemporariesForExit();

}  // namespace rpt::io
