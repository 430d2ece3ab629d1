// SPDX-License-Identifier: MIT
// io::StagedFile / io::StagedFolder: outputs appear complete or not at all, temporaries never stay.
#include "datasets/io/staged_output.h"

#include <fcntl.h>
#include <signal.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.h"
#include "datasets/io/json_output.h"
#include "datasets/io/text_file.h"

namespace rpt::io {
namespace {

namespace fs = std::filesystem;

std::string Read(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Names in `dir`, sorted.
std::vector<std::string> Entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

fs::path FreshDir(const std::string& name) {
  const fs::path dir = fs::path(testing::TempDir()) / ("rpt_staged_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(StagedFile, TargetChangesOnlyOnCommit) {
  const fs::path dir = FreshDir("file");
  WriteTextFile(dir / "a.txt", NamedBy::kUser, "old\n");
  {
    StagedFile staged(dir / "a.txt", NamedBy::kUser);
    std::ofstream(staged.path()) << "new\n";
    EXPECT_EQ(Read(dir / "a.txt"), "old\n");
    EXPECT_EQ(staged.path().parent_path(), dir);
    staged.Commit();
  }
  EXPECT_EQ(Read(dir / "a.txt"), "new\n");
  EXPECT_EQ(Entries(dir), std::vector<std::string>{"a.txt"});
  fs::remove_all(dir);
}

TEST(StagedFile, FailedWriteKeepsTheOldFileAndLeavesNoTemporary) {
  const fs::path dir = FreshDir("failed");
  WriteTextFile(dir / "a.txt", NamedBy::kUser, "old\n");
  EXPECT_THROW(WriteTextFile(dir / "a.txt", NamedBy::kUser,
                             [](std::ostream& out) {
                               out << "half of the new";
                               throw InputError("disk gone");
                             }),
               InputError);
  EXPECT_EQ(Read(dir / "a.txt"), "old\n");
  EXPECT_EQ(Entries(dir), std::vector<std::string>{"a.txt"});
  fs::remove_all(dir);
}

TEST(StagedFile, AFolderInTheWayIsAnErrorNamingTheFile) {
  const fs::path dir = FreshDir("folder_in_way");
  fs::create_directories(dir / "summary.json");
  try {
    WriteTextFile(dir / "summary.json", NamedBy::kUser, "{}");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "summary.json").string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(Entries(dir), std::vector<std::string>{"summary.json"});
  fs::remove_all(dir);
}

TEST(StagedFolder, SwapsInTheNewContentsAndKeepsOtherFiles) {
  const fs::path root = FreshDir("folder");
  const fs::path out = root / "run";
  WriteTextFile(out.string() + "-unused", NamedBy::kUser, "");  // a sibling that must not be touched
  fs::create_directories(out / "render");
  WriteTextFile(out / "summary.json", NamedBy::kUser, "old summary");
  WriteTextFile(out / "report.html", NamedBy::kUser, "kept");
  WriteTextFile(out / "render" / "frame.png", NamedBy::kUser, "kept too");
  {
    StagedFolder folder(out);
    ASSERT_FALSE(folder.in_place());
    WriteTextFile(folder.path() / "summary.json", NamedBy::kUser, "new summary");
    WriteTextFile(folder.path() / "run.json", NamedBy::kUser, "{}");
    EXPECT_EQ(Read(out / "summary.json"), "old summary");  // nothing changes before Commit
    EXPECT_FALSE(fs::exists(out / "run.json"));
    folder.Commit();
  }
  EXPECT_EQ(Read(out / "summary.json"), "new summary");
  EXPECT_EQ(Read(out / "run.json"), "{}");
  EXPECT_EQ(Read(out / "report.html"), "kept");
  EXPECT_EQ(Read(out / "render" / "frame.png"), "kept too");
  EXPECT_EQ(Entries(root), (std::vector<std::string>{"run", "run-unused"}));
  fs::remove_all(root);
}

TEST(StagedFolder, WithoutCommitTheOldFolderStaysAndTheStagingGoes) {
  const fs::path root = FreshDir("abandoned");
  fs::create_directories(root / "run");
  WriteTextFile(root / "run" / "summary.json", NamedBy::kUser, "old");
  {
    StagedFolder folder(root / "run");
    WriteTextFile(folder.path() / "summary.json", NamedBy::kUser, "new");
    EXPECT_EQ(Entries(root).size(), 2u);  // run and its staging sibling
  }
  EXPECT_EQ(Entries(root), std::vector<std::string>{"run"});
  EXPECT_EQ(Read(root / "run" / "summary.json"), "old");
  fs::remove_all(root);
}

TEST(StagedFolder, ANewFolderAppearsOnlyOnCommit) {
  const fs::path root = FreshDir("new");
  StagedFolder folder(root / "a" / "run");
  WriteTextFile(folder.path() / "run.json", NamedBy::kUser, "{}");
  EXPECT_FALSE(fs::exists(root / "a" / "run"));
  folder.Commit();
  EXPECT_EQ(Entries(root / "a"), std::vector<std::string>{"run"});
  EXPECT_EQ(Read(root / "a" / "run" / "run.json"), "{}");
  const std::string message = folder.NamedAsTarget("x: " + folder.path().string() + "/run.json: write failed");
  EXPECT_EQ(message, "x: " + (root / "a" / "run").string() + "/run.json: write failed");
  fs::remove_all(root);
}

// The current directory cannot be swapped away: its files are replaced one by one.
TEST(StagedFolder, TheCurrentDirectoryIsWrittenInPlace) {
  const fs::path root = FreshDir("cwd");
  const fs::path previous = fs::current_path();
  fs::current_path(root);
  {
    StagedFolder folder(".");
    EXPECT_TRUE(folder.in_place());
    WriteTextFile(folder.path() / "run.json", NamedBy::kUser, "{}");
    folder.Commit();
  }
  fs::current_path(previous);
  EXPECT_EQ(Entries(root), std::vector<std::string>{"run.json"});
  fs::remove_all(root);
}

TEST(StagedFolder, AFileInTheWayIsAnErrorNamingIt) {
  const fs::path root = FreshDir("file_in_way");
  WriteTextFile(root / "run", NamedBy::kUser, "a file");
  try {
    StagedFolder folder(root / "run");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find((root / "run").string()), std::string::npos) << e.what();
  }
  fs::remove_all(root);
}

// Issue 19: a link at the name (planted in a run folder from elsewhere) is replaced, never written
// through, whoever named the file; a FIFO is replaced in a folder rpt writes, written to when the user
// named it.
TEST(StagedFile, ALinkAtTheTargetIsReplacedNotWrittenThrough) {
  const fs::path dir = FreshDir("link_target");
  WriteTextFile(dir / "outside.txt", NamedBy::kUser, "precious");
  for (const NamedBy named_by : {NamedBy::kRpt, NamedBy::kUser}) {
    fs::create_symlink(dir / "outside.txt", dir / "summary.json");
    fs::create_symlink(dir / "absent.txt", dir / "dangling.json");
    fs::create_directories(dir / "folder");
    fs::create_symlink(dir / "folder", dir / "to_folder.json");
    for (const char* name : {"summary.json", "dangling.json", "to_folder.json"}) {
      WriteTextFile(dir / name, named_by, "new");
      EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir / name))) << name;
      EXPECT_EQ(Read(dir / name), "new");
      fs::remove(dir / name);
    }
    EXPECT_EQ(Read(dir / "outside.txt"), "precious");
    EXPECT_FALSE(fs::exists(dir / "absent.txt"));
    EXPECT_TRUE(fs::is_empty(dir / "folder"));
  }
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0644), 0);
  WriteTextFile(dir / "pipe", NamedBy::kRpt, "new");  // would block if written to
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(dir / "pipe")));
  fs::remove_all(dir);
}

TEST(StagedFile, KeepExtensionEndsTheTemporaryInTheTargetsExtension) {
  const fs::path dir = FreshDir("extension");
  StagedFile staged(dir / "cam.mp4", NamedBy::kRpt, /*keep_extension=*/true);
  EXPECT_EQ(staged.path().extension(), ".mp4");
  EXPECT_EQ(staged.path().filename().string().rfind("cam.mp4.tmp-" + std::to_string(::getpid()) + "-", 0), 0u);
  std::ofstream(staged.path()) << "video";
  staged.Commit();
  EXPECT_EQ(Entries(dir), std::vector<std::string>{"cam.mp4"});
  fs::remove_all(dir);
}

// The user's --out link: the folder it points to is replaced and the link kept; a link to nothing
// is an error and nothing is created.
TEST(StagedFolder, ALinkNamedAsTheFolderIsResolvedOnce) {
  const fs::path root = FreshDir("out_link");
  fs::create_directories(root / "disk" / "run");
  WriteTextFile(root / "disk" / "run" / "summary.json", NamedBy::kUser, "old");
  fs::create_directory_symlink(root / "disk" / "run", root / "out");
  {
    StagedFolder folder(root / "out");
    EXPECT_EQ(folder.target(), fs::canonical(root / "disk" / "run"));
    EXPECT_EQ(folder.path().parent_path(), fs::canonical(root / "disk"));
    WriteTextFile(folder.path() / "summary.json", NamedBy::kRpt, "new");
    folder.Commit();
  }
  EXPECT_TRUE(fs::is_symlink(root / "out"));
  EXPECT_EQ(Read(root / "out" / "summary.json"), "new");
  EXPECT_EQ(Entries(root / "disk"), std::vector<std::string>{"run"});
  fs::create_directory_symlink(root / "missing", root / "dangling");
  EXPECT_THROW(StagedFolder(root / "dangling"), InputError);
  EXPECT_FALSE(fs::exists(root / "missing"));
  EXPECT_EQ(Entries(root), (std::vector<std::string>{"dangling", "disk", "out"}));
  fs::remove_all(root);
}

TEST(StagedFolder, AWriteProtectedFolderIsRefusedBeforeAnythingIsCreated) {
  const fs::path root = FreshDir("protected");
  fs::create_directories(root / "run" / "render");
  WriteTextFile(root / "run" / "summary.json", NamedBy::kUser, "old");
  for (const fs::path& protect : {root / "run", root / "run" / "render"}) {
    ::chmod(protect.c_str(), 0555);
    try {
      StagedFolder folder(root / "run");
      ADD_FAILURE() << "no error for " << protect;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(protect.string() + ": write-protected"), std::string::npos) << e.what();
    }
    ::chmod(protect.c_str(), 0755);
    EXPECT_EQ(Entries(root), std::vector<std::string>{"run"});
  }
  EXPECT_EQ(Read(root / "run" / "summary.json"), "old");
  fs::remove_all(root);
}

// Carried-over links stay links (never followed); FIFOs are not carried over.
TEST(StagedFolder, CarriesLinksAsLinksAndDropsFifos) {
  const fs::path root = FreshDir("carry");
  fs::create_directories(root / "run");
  WriteTextFile(root / "outside.txt", NamedBy::kUser, "precious");
  fs::create_symlink(root / "outside.txt", root / "run" / "notes.txt");
  fs::create_symlink(root / "outside.txt", root / "run" / "summary.json");
  ASSERT_EQ(::mkfifo((root / "run" / "pipe").c_str(), 0644), 0);
  {
    StagedFolder folder(root / "run");
    ASSERT_FALSE(folder.in_place());
    WriteTextFile(folder.path() / "summary.json", NamedBy::kRpt, "new");
    folder.Commit();
  }
  EXPECT_EQ(Entries(root / "run"), (std::vector<std::string>{"notes.txt", "summary.json"}));
  EXPECT_TRUE(fs::is_symlink(root / "run" / "notes.txt"));
  EXPECT_EQ(Read(root / "run" / "summary.json"), "new");
  EXPECT_EQ(Read(root / "outside.txt"), "precious");
  fs::remove_all(root);
}

// The pid of a process that has ended (forked, exited, waited for).
pid_t EndedPid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

// Temporaries of a killed run beside a folder and inside it, and beside a file the user named, are
// said (not removed); those of a running process (ours), other names, and names that only look like
// temporaries are not.
TEST(StaleTemporaryWarnings, NameTheTemporariesOfKilledRuns) {
  const fs::path dir = FreshDir("stale");
  const std::string dead = std::to_string(EndedPid());
  const std::string alive = std::to_string(::getppid());
  fs::create_directories(dir / "out");
  fs::create_directories(dir / ("out.tmp-" + dead + "-0"));
  for (const std::string& name : std::vector<std::string>{"out/predictions.json.tmp-" + dead + "-3", "out/cam.mp4.tmp-" + dead + "-4.mp4",
                                  "out/summary.json.tmp-" + alive + "-1", std::string("out/notes.tmp-x-1"), "out/a.tmp-" + dead,
                                  "outer.tmp-" + dead + "-0", "labels.json.tmp-" + dead + "-2", "other.json.tmp-" + dead + "-2"}) {
    std::ofstream(dir / name) << "x";
  }
  {
    StagedFolder folder(dir / "out");
    StagedFile file(dir / "labels.json", NamedBy::kUser);
  }
  const std::vector<std::string> warnings = StaleTemporaryWarnings();
  std::vector<std::string> named;
  for (const std::string& w : warnings) {
    if (w.rfind(dir.string(), 0) == 0) named.push_back(w.substr(dir.string().size() + 1, w.find(": ") - dir.string().size() - 1));
  }
  std::sort(named.begin(), named.end());
  EXPECT_EQ(named, (std::vector<std::string>{"labels.json.tmp-" + dead + "-2", "out.tmp-" + dead + "-0",
                                             "out/cam.mp4.tmp-" + dead + "-4.mp4",
                                             "out/predictions.json.tmp-" + dead + "-3"}));
  ASSERT_FALSE(warnings.empty());
  EXPECT_NE(warnings.front().find("left by an rpt that was killed while writing (no process " + dead + " runs here)"),
            std::string::npos)
      << warnings.front();
  EXPECT_TRUE(fs::exists(dir / ("out.tmp-" + dead + "-0"))) << "said, never removed";
  fs::remove_all(dir);
}

// The reason of a failed write when errno no longer holds it (a stream's failure noticed at its
// flush, after other calls): a file at the file size limit is "File too large"; otherwise the
// errno given, or "reason unknown". In a child process: the limit is the process's.
TEST(WriteFailureReason, AFileAtTheSizeLimitIsTooLargeWhateverErrnoSays) {
  const fs::path dir = FreshDir("reason");
  const pid_t child = ::fork();
  if (child == 0) {
    ::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{8192, 8192};
    if (::setrlimit(RLIMIT_FSIZE, &limit) != 0) ::_exit(10);
    { std::ofstream(dir / "big") << std::string(20000, 'x'); }
    { std::ofstream(dir / "small") << std::string(100, 'x'); }
    if (fs::file_size(dir / "big") != 8192) ::_exit(11);
    if (WriteFailureReason(dir / "big", 0) != "File too large") ::_exit(12);
    if (WriteFailureReason(dir / "big", ENOENT) != "File too large") ::_exit(13);
    if (WriteFailureReason(dir / "small", 0) != "reason unknown") ::_exit(14);
    if (WriteFailureReason(dir / "small", ENOSPC) != "No space left on device") ::_exit(15);
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "the check that failed: 10 setrlimit, 11 size, 12-15 the reasons in order";
  fs::remove_all(dir);
}

TEST(CreateFolderInside, ReplacesLinksAndStaysInside) {
  const fs::path root = FreshDir("inside");
  fs::create_directories(root / "out" / "kept");
  fs::create_directories(root / "elsewhere");
  fs::create_directory_symlink(root / "elsewhere", root / "out" / "seq");
  EXPECT_EQ(CreateFolderInside(root / "out", fs::path("seq") / "cam"), root / "out" / "seq" / "cam");
  EXPECT_TRUE(fs::is_directory(fs::symlink_status(root / "out" / "seq")));
  EXPECT_TRUE(fs::is_empty(root / "elsewhere"));
  EXPECT_EQ(CreateFolderInside(root / "out", "kept"), root / "out" / "kept");
  WriteTextFile(root / "out" / "file", NamedBy::kUser, "x");
  EXPECT_THROW(CreateFolderInside(root / "out", fs::path("file") / "cam"), InputError);
  EXPECT_THROW(CreateFolderInside(root / "out", fs::path("..") / "x"), std::logic_error);
  EXPECT_THROW(CreateFolderInside(root / "out", root / "abs"), std::logic_error);
  fs::remove_all(root);
}

TEST(ScratchFile, IsRemovedWhenAnExceptionLeavesItsScope) {
  const fs::path dir = FreshDir("scratch");
  fs::path path;
  EXPECT_THROW(
      {
        ScratchFile scratch(dir / "bench.h5");
        path = scratch.path();
        EXPECT_EQ(path.parent_path(), dir);
        EXPECT_EQ(path.filename().string().rfind("bench.h5.tmp-" + std::to_string(::getpid()) + "-", 0), 0u) << path;
        EXPECT_TRUE(fs::is_regular_file(path));
        std::ofstream(path) << "half";
        ScratchFile second(dir / "bench.h5");  // a name of its own
        EXPECT_NE(second.path(), path);
        throw InputError("write failed");
      },
      InputError);
  EXPECT_FALSE(path.empty());
  EXPECT_TRUE(Entries(dir).empty());
  fs::remove_all(dir);
}

TEST(ScratchFile, AMissingFolderIsAnErrorNamingIt) {
  const fs::path dir = FreshDir("scratch_missing");
  try {
    ScratchFile scratch(dir / "absent" / "bench.h5");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "absent" / "bench.h5").string()), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

TEST(RemoveTemporariesForExit, RemovesWhatIsBeingWritten) {
  // Run in a child: the registry stays locked afterwards, as in the process that exits.
  const fs::path root = FreshDir("exit");
  WriteTextFile(root / "kept.txt", NamedBy::kUser, "old");
  fs::create_directories(root / "run");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    StagedFile file(root / "kept.txt", NamedBy::kUser);
    std::ofstream(file.path()) << "half";
    StagedFolder folder(root / "run");
    std::ofstream(folder.path() / "summary.json") << "half";
    ScratchFile scratch(root / "scratch.h5");
    std::ofstream(scratch.path()) << "half";
    ::_exit(RemoveTemporariesForExit());
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 3);  // the file's and the folder's temporaries, the scratch file
  EXPECT_EQ(Entries(root), (std::vector<std::string>{"kept.txt", "run"}));
  EXPECT_EQ(Read(root / "kept.txt"), "old");
  EXPECT_TRUE(fs::is_empty(root / "run"));
  fs::remove_all(root);
}

TEST(StagedOutput, OwnOutputNamesWriteToTheDescriptor) {
  // In a child whose stdout is a log file with a line in it (as `rpt check --junit /dev/stdout > log`):
  // every name of the process's own stdout appends the whole file to the log; nothing is renamed
  // over a link, nothing is created in /dev or /proc, the log is not truncated.
  const fs::path dir = FreshDir("own_fd");
  const fs::path log = dir / "log";
  fs::create_symlink("/proc/self/fd/1", dir / "mystdout");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0 || ::dup2(fd, 1) < 0) ::_exit(90);
    if (::write(1, "before\n", 7) != 7 || ::chdir(dir.c_str()) != 0) ::_exit(91);
    // The system's /dev/stdout is such a link (to /proc/self/fd/1): `mystdout` stands for it, so
    // that a broken build fails this test without replacing the machine's /dev/stdout.
    try {
      for (const char* name : {"link", "/dev/fd/1", "-", "/proc/self/fd/1"}) {
        const fs::path target = std::string(name) == "link" ? dir / "mystdout" : fs::path(name);
        WriteTextFile(target, NamedBy::kUser, std::string(name) + "\n");
      }
      StagedFile unused(dir / "mystdout", NamedBy::kUser);  // not committed: nothing written
      std::ofstream(unused.path()) << "never\n";
    } catch (...) {
      ::_exit(92);
    }
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(Read(log), "before\nlink\n/dev/fd/1\n-\n/proc/self/fd/1\n");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir / "mystdout")));
  EXPECT_EQ(Entries(dir), (std::vector<std::string>{"log", "mystdout"}));
  // A descriptor that is not open is an error naming the file, before anything is written.
  try {
    StagedFile closed("/dev/fd/987", NamedBy::kUser);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/dev/fd/987: cannot open for writing (file descriptor 987 is not open)"),
              std::string::npos)
        << error.what();
  }
  // Named by rpt inside an output folder, such a link is replaced as every link is.
  WriteTextFile(dir / "mystdout", NamedBy::kRpt, "file\n");
  EXPECT_FALSE(fs::is_symlink(fs::symlink_status(dir / "mystdout")));
  EXPECT_EQ(Read(dir / "mystdout"), "file\n");
  fs::remove_all(dir);
}

TEST(StagedOutput, NamesNearTheLengthLimitAreWritten) {
  const fs::path dir = FreshDir("long_names");
  const std::string longest(255, 'N');
  std::string utf8;  // 254 bytes of two-byte characters: shortened at a character boundary
  while (utf8.size() < 254) utf8 += "\xc3\xa9";
  for (const std::string& name : {longest, utf8, std::string(245, 'F')}) {
    WriteTextFile(dir / name, NamedBy::kUser, "old");
    WriteTextFile(dir / name, NamedBy::kUser, "new");
    EXPECT_EQ(Read(dir / name), "new") << name.size();
  }
  const fs::path folder = dir / std::string(250, 'D');
  fs::create_directories(folder);
  {
    StagedFolder staged(folder);
    EXPECT_FALSE(staged.in_place());
    WriteTextFile(staged.path() / "summary.json", NamedBy::kRpt, "{}");
    staged.Commit();
  }
  EXPECT_EQ(Read(folder / "summary.json"), "{}");
  EXPECT_EQ(Entries(dir).size(), 4u);  // no temporary left
  fs::remove_all(dir);
}

TEST(JsonOutput, EscapesQuotesAndReplacesInvalidUtf8) {
  int replaced = 0;
  const nlohmann::ordered_json value = {{"joints", {"left \"wrist\"", "ok"}}, {"id", "frame\xff\xfe"}};
  const std::string text = DumpJson(value, -1, &replaced);
  EXPECT_EQ(replaced, 1);
  const nlohmann::json parsed = nlohmann::json::parse(text);
  EXPECT_EQ(parsed["joints"][0], "left \"wrist\"");
  EXPECT_EQ(parsed["id"], "frame\xef\xbf\xbd\xef\xbf\xbd");  // two U+FFFD
  replaced = 0;
  EXPECT_EQ(DumpJson(nlohmann::json("plain"), -1, &replaced), "\"plain\"");
  EXPECT_EQ(replaced, 0);
}

}  // namespace
}  // namespace rpt::io
