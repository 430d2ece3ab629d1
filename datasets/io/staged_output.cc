// SPDX-License-Identifier: MIT
#include "datasets/io/staged_output.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"
#include "core/printable_text.h"

namespace rpt::io {
namespace {

namespace fs = std::filesystem;

// Every temporary that exists right now. Creating, committing and discarding a temporary happen
// under the lock, so RemoveTemporariesForExit (which keeps the lock) sees each one either not yet
// created or registered, and never a half-done rename.
struct Registry {
  std::mutex mutex;
  std::vector<fs::path> paths;
  long next_number = 0;
};

Registry& TheRegistry() {
  static Registry* registry = new Registry;  // never destroyed: the interrupt thread may use it during exit
  return *registry;
}

void Unregister(Registry& registry, const fs::path& path) {
  auto& paths = registry.paths;
  paths.erase(std::remove(paths.begin(), paths.end(), path), paths.end());
}

// `<target>.tmp-<pid>-<n>`, followed by the target's extension when asked (call with the lock held).
// A name near the file system's limit (255 bytes) is shortened first (at a UTF-8 character
// boundary), so any name that may exist can be written.
fs::path NextTemporaryName(Registry& registry, const fs::path& target, bool keep_extension = false) {
  const std::string suffix = ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(registry.next_number++) +
                             (keep_extension ? target.extension().string() : std::string());
  std::string name = target.filename().string();
  constexpr size_t kNameMax = 255;
  if (name.size() + suffix.size() > kNameMax) {
    size_t keep = suffix.size() < kNameMax ? kNameMax - suffix.size() : 0;
    while (keep > 0 && (static_cast<unsigned char>(name[keep]) & 0xC0) == 0x80) --keep;  // not inside a character
    name.resize(keep);
  }
  return target.parent_path() / (name + suffix);
}

// The descriptor a name stands for when it is one of this process's own open files: `-`,
// /dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N, /proc/<our pid>/fd/N, or a link (chain)
// to one of those; -1 otherwise. Writing to such a name must go to the descriptor: renaming over
// it would replace a system link (/dev/stdout) with a file, and opening it anew would truncate a
// log that stdout is redirected to.
int OwnDescriptor(const fs::path& name) {
  if (name == "-") return 1;
  const std::string self_fd = "/proc/" + std::to_string(::getpid()) + "/fd/";
  fs::path at = name;
  for (int hops = 0; hops < 40; ++hops) {
    const std::string text = at.lexically_normal().string();
    if (text == "/dev/stdout") return 1;
    if (text == "/dev/stderr") return 2;
    for (const std::string& prefix : {std::string("/dev/fd/"), std::string("/proc/self/fd/"),
                                     std::string("/proc/thread-self/fd/"), self_fd}) {
      if (text.size() > prefix.size() && text.compare(0, prefix.size(), prefix) == 0 &&
          text.find_first_not_of("0123456789", prefix.size()) == std::string::npos && text.size() - prefix.size() < 9) {
        return std::stoi(text.substr(prefix.size()));
      }
    }
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(at, ec))) return -1;
    const fs::path next = fs::read_symlink(at, ec);
    if (ec) return -1;
    at = next.is_absolute() ? next : at.parent_path() / next;
  }
  return -1;
}

bool IsDeviceOrFifo(const fs::file_status& status) {
  return fs::is_character_file(status) || fs::is_block_file(status) || fs::is_fifo(status);
}

std::string ErrnoText() { return std::strerror(errno); }

}  // namespace

std::string WriteFailureReason(const fs::path& file, int saved_errno) {
  switch (saved_errno) {
    case ENOSPC: case EDQUOT: case EFBIG: case EIO: case EROFS: case EACCES: case EPERM: case EISDIR: case ENXIO:
    case EPIPE:
      return std::strerror(saved_errno);
    default:
      break;
  }
  struct statvfs space {};
  const fs::path folder = file.has_parent_path() ? file.parent_path() : fs::path(".");
  if (::statvfs(folder.c_str(), &space) == 0 && space.f_bavail == 0) return std::strerror(ENOSPC);
  // A file size limit (ulimit -f) the file has reached: the write that crossed it failed with EFBIG,
  // but errno is long overwritten when the stream's failure is noticed at its flush (or on the
  // thread that wrote it).
  struct rlimit limit {};
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  if (!ec && ::getrlimit(RLIMIT_FSIZE, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY &&
      size + 4096 > static_cast<std::uintmax_t>(limit.rlim_cur)) {  // writes stop at the limit, to the byte
    return std::strerror(EFBIG);
  }
  return "reason unknown";
}

namespace {

// Flushes a file's (or a folder's) data and entries to disk.
bool SyncToDisk(const fs::path& path, bool folder) {
  const int fd = ::open(path.c_str(), (folder ? O_RDONLY | O_DIRECTORY : O_RDONLY) | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0 || errno == EINVAL;  // EINVAL: the file system does not sync (e.g. some FUSE)
  ::close(fd);
  return ok;
}

// Does `folder` hold the current directory (or is it)? Then it cannot be swapped away.
bool HoldsCurrentDirectory(const fs::path& folder) {
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  const fs::path canonical = fs::canonical(folder, ec);
  if (ec) return false;
  return std::mismatch(canonical.begin(), canonical.end(), cwd.begin(), cwd.end()).first == canonical.end();
}

// Exchanges two existing paths atomically; false when the file system cannot.
bool ExchangePaths(const fs::path& a, const fs::path& b) {
#ifdef RENAME_EXCHANGE
  return ::renameat2(AT_FDCWD, a.c_str(), AT_FDCWD, b.c_str(), RENAME_EXCHANGE) == 0;
#else
  (void)a;
  (void)b;
  errno = EINVAL;
  return false;
#endif
}

// Creates `<target>.tmp-<pid>-<n>` (a name not yet taken), registers it, stores its name in
// `created` and returns it open for writing; throws InputError naming `target` when it cannot.
// O_EXCL never follows a link: a name taken by anything, a planted link included, is skipped.
int CreateRegisteredFile(const fs::path& target, fs::path* created, bool keep_extension = false) {
  Registry& registry = TheRegistry();
  std::lock_guard<std::mutex> lock(registry.mutex);
  for (;;) {
    *created = NextTemporaryName(registry, target, keep_extension);
    const int fd = ::open(created->c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd < 0 && errno == EEXIST) continue;
    if (fd < 0) throw InputError(target.string() + ": cannot open for writing (" + ErrnoText() + ")");
    registry.paths.push_back(*created);
    return fd;
  }
}

// Is `folder` writable for this process? For root (who may write anywhere) the owner's write bit
// says whether the owner protected it.
bool Writable(const fs::path& folder) {
  struct stat info {};
  if (::lstat(folder.c_str(), &info) != 0) return false;
  if (::geteuid() == 0) return (info.st_mode & S_IWUSR) != 0;
  return ::access(folder.c_str(), W_OK) == 0;
}

// Throws InputError when `folder` (or, `with_subfolders`, a folder inside it; links not followed) is
// write-protected.
void RefuseWriteProtected(const fs::path& folder, bool with_subfolders) {
  const auto refuse = [&](const fs::path& protected_folder) {
    throw InputError(protected_folder.string() + ": write-protected; rpt does not replace a write-protected " +
                     "output folder (make it writable, e.g. chmod -R u+w " + folder.string() +
                     ", or choose another output folder)");
  };
  if (!Writable(folder)) refuse(folder);
  if (!with_subfolders) return;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    if (it->is_directory(ec) && !it->is_symlink(ec) && !Writable(it->path())) refuse(it->path());
  }
  if (ec) throw InputError(folder.string() + ": cannot read the old output folder (" + ec.message() + ")");
}

void RemoveRegisteredFile(const fs::path& path) {
  Registry& registry = TheRegistry();
  std::lock_guard<std::mutex> lock(registry.mutex);
  std::error_code ec;
  fs::remove(path, ec);
  Unregister(registry, path);
}

// The process id of a temporary's name `<name>.tmp-<pid>-<n>[<extension>]` (`name` empty: any
// name), or 0 when `entry` is not one.
long TemporaryPid(const std::string& entry, const std::string& name) {
  size_t at = name.empty() ? entry.rfind(".tmp-") : name.size();
  if (at == std::string::npos || at == 0 || entry.compare(0, name.size(), name) != 0 ||
      entry.compare(at, 5, ".tmp-") != 0) {
    return 0;
  }
  at += 5;
  const size_t dash = entry.find('-', at);
  if (dash == std::string::npos || dash == at || dash - at > 9) return 0;
  const size_t number_end = entry.find_first_not_of("0123456789", dash + 1);
  if (number_end == dash + 1 || (number_end != std::string::npos && entry[number_end] != '.')) return 0;
  if (entry.find_first_not_of("0123456789", at) != dash) return 0;
  return std::stol(entry.substr(at, dash - at));
}

struct StaleNotes {
  std::mutex mutex;
  std::set<fs::path> paths;
};

StaleNotes& TheStaleNotes() {
  static StaleNotes* notes = new StaleNotes;
  return *notes;
}

// Notes the temporaries in `folder` (of `name`, or of any name when empty) whose process no longer
// runs on this machine: left by an rpt that was killed (SIGKILL, an out-of-memory kill, a crash).
void NoteStaleTemporaries(const fs::path& folder, const std::string& name) {
  std::error_code ec;
  fs::directory_iterator it(folder.empty() ? fs::path(".") : folder, ec);
  for (long seen = 0; !ec && it != fs::directory_iterator() && seen < 100000; it.increment(ec), ++seen) {
    const std::string entry = it->path().filename().string();
    const long pid = TemporaryPid(entry, name);
    if (pid <= 0 || pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;  // running (or not ours to ask)
    StaleNotes& notes = TheStaleNotes();
    const std::lock_guard<std::mutex> lock(notes.mutex);
    notes.paths.insert(folder / entry);
  }
}

}  // namespace

std::vector<std::string> StaleTemporaryWarnings() {
  StaleNotes& notes = TheStaleNotes();
  const std::lock_guard<std::mutex> lock(notes.mutex);
  std::vector<std::string> warnings;
  for (const fs::path& path : notes.paths) {
    const std::string name = path.filename().string();
    warnings.push_back(PrintableText(path.string(), LineBreaks::kEscape) +
                       ": a temporary left by an rpt that was killed while writing (no process " +
                       std::to_string(TemporaryPid(name, "")) +
                       " runs here); nothing reads it: delete it, unless an rpt on another machine writes there now");
  }
  return warnings;
}

StagedFile::StagedFile(const fs::path& target, NamedBy named_by, bool keep_extension) : target_(target) {
  std::error_code ec;
  if (named_by == NamedBy::kUser) descriptor_ = OwnDescriptor(target_);
  if (descriptor_ >= 0) {  // staged in the temporary folder, copied to the descriptor by Commit()
    if (::fcntl(descriptor_, F_GETFD) < 0) {
      throw InputError(target_.string() + ": cannot open for writing (file descriptor " + std::to_string(descriptor_) +
                       " is not open)");
    }
    fs::path folder = fs::temp_directory_path(ec);
    if (ec) folder = "/tmp";
    ::close(CreateRegisteredFile(folder / ("rpt-fd" + std::to_string(descriptor_) +
                                           (keep_extension ? target_.extension().string() : std::string())),
                                 &temporary_, keep_extension));
    pending_ = true;
    return;
  }
  const fs::file_status entry = fs::symlink_status(target_, ec);  // the name itself: a link is not followed
  if (fs::is_directory(entry)) throw InputError(target_.string() + ": is a folder, expected a file");
  if (named_by == NamedBy::kUser && fs::exists(entry) && !fs::is_regular_file(entry) &&
      IsDeviceOrFifo(fs::status(target_, ec))) {  // /dev/stdout, /dev/full, a FIFO: written in place
    temporary_ = target_;
    return;
  }
  if (named_by == NamedBy::kUser) NoteStaleTemporaries(target_.parent_path(), target_.filename().string());
  const int fd = CreateRegisteredFile(target_, &temporary_, keep_extension);
  if (fs::is_regular_file(entry)) ::fchmod(fd, static_cast<mode_t>(entry.permissions()) & 07777);  // keep the old mode
  ::close(fd);
  pending_ = true;
}

StagedFile::~StagedFile() {
  if (pending_) RemoveRegisteredFile(temporary_);
}

void StagedFile::Commit() {
  if (!pending_) return;  // written in place
  if (descriptor_ >= 0) {
    CopyToDescriptor();
    RemoveRegisteredFile(temporary_);
    pending_ = false;
    return;
  }
  if (!SyncToDisk(temporary_, /*folder=*/false)) {
    throw InputError(target_.string() + ": write failed (" + WriteFailureReason(temporary_, errno) + ")");
  }
  Registry& registry = TheRegistry();
  std::lock_guard<std::mutex> lock(registry.mutex);
  if (::rename(temporary_.c_str(), target_.c_str()) != 0) {
    throw InputError(target_.string() + ": cannot replace (" + ErrnoText() + ")");  // the destructor removes the temporary
  }
  Unregister(registry, temporary_);
  pending_ = false;
}

void StagedFile::CopyToDescriptor() const {
  const int in = ::open(temporary_.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (in < 0) throw InputError(target_.string() + ": write failed (" + ErrnoText() + ")");
  char buffer[1 << 16];
  for (;;) {
    const ssize_t got = ::read(in, buffer, sizeof buffer);
    if (got == 0) break;
    if (got < 0 && errno == EINTR) continue;
    for (ssize_t done = 0; got > 0 && done < got;) {
      const ssize_t put = ::write(descriptor_, buffer + done, static_cast<size_t>(got - done));
      if (put < 0 && errno == EINTR) continue;
      if (put <= 0) {
        const std::string error = ErrnoText();
        ::close(in);
        throw InputError(target_.string() + ": write failed (" + error + ")");
      }
      done += put;
    }
    if (got < 0) {
      const std::string error = ErrnoText();
      ::close(in);
      throw InputError(target_.string() + ": write failed (" + error + ")");
    }
  }
  ::close(in);
}

StagedFolder::StagedFolder(const fs::path& target) : target_(target) {
  std::error_code ec;
  if (target_.filename().empty()) target_ = target_.parent_path();  // "out/" -> "out"
  if (fs::is_symlink(fs::symlink_status(target_, ec))) {            // the user's link: the folder it points to
    const fs::path resolved = fs::canonical(target_, ec);
    if (ec) {
      throw InputError(target_.string() + ": is a link to a folder that does not exist (" + ec.message() +
                       "); rpt writes into the folder a link points to: create it or choose another output folder");
    }
    target_ = resolved;
  }
  const fs::file_status status = fs::status(target_, ec);
  if (fs::exists(status) && !fs::is_directory(status)) {
    throw InputError(target_.string() + ": exists and is not a folder");
  }
  // A killed run's staging folder beside this one, and its temporaries inside the old folder.
  NoteStaleTemporaries(target_.parent_path(), target_.filename().string());
  if (fs::is_directory(status)) NoteStaleTemporaries(target_, "");
  const fs::path absolute = fs::absolute(target_, ec).lexically_normal();
  if ((fs::exists(status) && HoldsCurrentDirectory(target_)) || !absolute.has_relative_path()) {
    if (fs::exists(status)) RefuseWriteProtected(target_, /*with_subfolders=*/false);
    staging_ = target_;  // in place
    return;
  }
  if (fs::exists(status))
    RefuseWriteProtected(target_, /*with_subfolders=*/true);  // the old contents go after the swap
  if (!absolute.parent_path().empty()) fs::create_directories(absolute.parent_path(), ec);
  if (ec) throw InputError(target_.string() + ": cannot create output folder: " + ec.message());
  Registry& registry = TheRegistry();
  std::lock_guard<std::mutex> lock(registry.mutex);
  for (;;) {
    staging_ = NextTemporaryName(registry, target_);
    if (::mkdir(staging_.c_str(), 0777) == 0) break;
    if (errno != EEXIST) throw InputError(target_.string() + ": cannot create output folder (" + ErrnoText() + ")");
  }
  registry.paths.push_back(staging_);
  pending_ = true;
  if (!fs::exists(status)) return;
  // Carry the old entries over (files as hard links, links as links: no writer follows them; FIFOs
  // and devices are not results and stay behind); should that fail (e.g. hard links not allowed),
  // fall back to in place.
  for (const fs::directory_entry& entry : fs::directory_iterator(target_, ec)) {
    const fs::file_status kind = entry.symlink_status(ec);
    if (!ec && !fs::is_regular_file(kind) && !fs::is_directory(kind) && !fs::is_symlink(kind))
      continue;  // FIFOs, devices: dropped
    fs::copy(entry.path(), staging_ / entry.path().filename(),
             fs::copy_options::recursive | fs::copy_options::create_hard_links | fs::copy_options::copy_symlinks, ec);
    if (ec) break;
  }
  if (ec) {
    fs::remove_all(staging_, ec);
    Unregister(registry, staging_);
    pending_ = false;
    staging_ = target_;
  }
}

StagedFolder::~StagedFolder() {
  if (!pending_) return;
  Registry& registry = TheRegistry();
  std::lock_guard<std::mutex> lock(registry.mutex);
  std::error_code ec;
  fs::remove_all(staging_, ec);
  Unregister(registry, staging_);
}

void StagedFolder::Commit() {
  if (!pending_) return;  // in place: every file was committed on its own
  if (!SyncToDisk(staging_, /*folder=*/true)) {
    throw InputError(target_.string() + ": cannot flush the new folder (" + ErrnoText() + ")");
  }
  Registry& registry = TheRegistry();
  std::lock_guard<std::mutex> lock(registry.mutex);
  std::error_code ec;
  if (!fs::exists(target_, ec)) {
    if (::rename(staging_.c_str(), target_.c_str()) != 0) {
      throw InputError(target_.string() + ": cannot create output folder (" + ErrnoText() + ")");
    }
    Unregister(registry, staging_);
    pending_ = false;
    return;
  }
  if (ExchangePaths(staging_, target_)) {  // staging_ now holds the old contents
    fs::remove_all(staging_, ec);
    Unregister(registry, staging_);
    pending_ = false;
    return;
  }
  // No atomic exchange here: move the old folder aside, the new one in, then drop the old one.
  // Killed in between, the old folder waits intact under its temporary name.
  const fs::path old = NextTemporaryName(registry, target_);
  if (::rename(target_.c_str(), old.c_str()) != 0) {
    throw InputError(target_.string() + ": cannot replace the output folder (" + ErrnoText() + ")");
  }
  registry.paths.push_back(old);
  if (::rename(staging_.c_str(), target_.c_str()) != 0) {
    const std::string error = ErrnoText();
    ::rename(old.c_str(), target_.c_str());
    Unregister(registry, old);
    throw InputError(target_.string() + ": cannot replace the output folder (" + error + ")");
  }
  Unregister(registry, staging_);
  pending_ = false;
  fs::remove_all(old, ec);
  Unregister(registry, old);
}

std::string StagedFolder::NamedAsTarget(std::string message) const {
  if (in_place()) return message;
  const std::string staging = staging_.string(), target = target_.string();
  for (size_t at = 0; (at = message.find(staging, at)) != std::string::npos; at += target.size()) {
    message.replace(at, staging.size(), target);
  }
  return message;
}

fs::path CreateFolderInside(const fs::path& root, const fs::path& relative) {
  if (relative.is_absolute()) throw std::logic_error("CreateFolderInside: " + relative.string() + " is not relative");
  fs::path folder = root;
  for (const fs::path& name : relative) {
    if (name == "." || name == ".." || name.empty()) {
      throw std::logic_error("CreateFolderInside: " + relative.string() + " holds " + QuoteName(name.string()));
    }
    folder /= name;
    std::error_code ec;
    const fs::file_status entry = fs::symlink_status(folder, ec);
    if (fs::is_directory(entry)) continue;
    if (fs::is_regular_file(entry)) throw InputError(folder.string() + ": exists and is not a folder");
    if (fs::exists(entry) && !fs::remove(folder, ec)) {  // a link, FIFO or device: replaced, never followed
      throw InputError(folder.string() + ": cannot replace (" + ec.message() + ")");
    }
    if (::mkdir(folder.c_str(), 0777) != 0) {
      throw InputError(folder.string() + ": cannot create output folder (" + ErrnoText() + ")");
    }
  }
  return folder;
}

ScratchFile::ScratchFile(const fs::path& name_like) { ::close(CreateRegisteredFile(name_like, &path_)); }

ScratchFile::~ScratchFile() { RemoveRegisteredFile(path_); }

ParentFolders::ParentFolders(const fs::path& file) {
  std::error_code ec;
  std::vector<fs::path> missing;  // innermost first
  for (fs::path parent = file.parent_path(); !parent.empty() && !fs::exists(parent, ec); parent = parent.parent_path()) {
    missing.push_back(parent);
    if (parent == parent.parent_path()) break;
  }
  for (auto it = missing.rbegin(); it != missing.rend(); ++it) {
    if (!fs::create_directory(*it, ec) && ec) {
      const fs::path parent = file.parent_path();
      throw InputError(file.string() + ": cannot create its folder " + parent.string() + " (" + ec.message() + ")");
    }
    created_.push_back(*it);
  }
}

ParentFolders::~ParentFolders() {
  for (auto it = created_.rbegin(); it != created_.rend(); ++it) {
    std::error_code ec;
    fs::remove(*it, ec);  // only an empty folder goes: one something was written into stays
  }
}

int RemoveTemporariesForExit() {
  Registry& registry = TheRegistry();
  registry.mutex.lock();  // kept: the process exits next
  int removed = 0;
  for (const fs::path& path : registry.paths) {
    std::error_code ec;
    if (fs::remove_all(path, ec) > 0) ++removed;
  }
  registry.paths.clear();
  return removed;
}

}  // namespace rpt::io
