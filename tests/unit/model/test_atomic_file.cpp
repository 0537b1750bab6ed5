#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <stdexcept>

#include "common/atomic_file.hpp"
#include "common/error.hpp"
#include "common/progress.hpp"
#include "support/test_support.hpp"

using namespace plumb;

TEST(AtomicFile, FailedWriteKeepsExistingFile) {
  const auto dir = test::scratchDir("atomic_file");
  const auto target = dir / "out.txt";
  test::writeAll(target, "precious");
  EXPECT_THROW(writeFileAtomically(target,
                                   [](std::ostream& out) {
                                     out << "half";
                                     throw std::runtime_error("disk on fire");
                                   }),
               std::runtime_error);
  EXPECT_EQ(test::readAll(target), "precious");
  // No temporary file left behind.
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1u);
  writeFileAtomically(target, [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(test::readAll(target), "new");
}

TEST(AtomicFile, UnwritableDirectoryIsAClearError) {
  try {
    writeFileAtomically("/nonexistent-dir/out.ply", [](std::ostream&) {});
    FAIL();
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/out.ply"), std::string::npos);
  }
}

namespace {
unsigned modeOf(const std::filesystem::path& p) {
  struct stat st {};
  EXPECT_EQ(::stat(p.c_str(), &st), 0);
  return st.st_mode & 07777;
}

std::size_t entries(const std::filesystem::path& dir) {
  std::size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}
}  // namespace

TEST(AtomicFile, ReplacingKeepsThePermissions) {
  const auto dir = test::scratchDir("atomic_file_mode");
  const auto target = dir / "secret.txt";
  test::writeAll(target, "old");
  ASSERT_EQ(::chmod(target.c_str(), 0600), 0);
  writeFileAtomically(target, [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(test::readAll(target), "new");
  EXPECT_EQ(modeOf(target), 0600u);
  ASSERT_EQ(::chmod(target.c_str(), 0640), 0);
  writeFileAtomically(target, [](std::ostream& out) { out << "newer"; });
  EXPECT_EQ(modeOf(target), 0640u);
}

TEST(AtomicFile, ReadOnlyTargetIsRefused) {
  const auto dir = test::scratchDir("atomic_file_readonly");
  const auto target = dir / "frozen.txt";
  test::writeAll(target, "keep");
  ASSERT_EQ(::chmod(target.c_str(), 0444), 0);
  try {
    writeFileAtomically(target, [](std::ostream& out) { out << "new"; });
    FAIL() << "a read-only file was replaced";
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("read-only"), std::string::npos) << e.what();
  }
  EXPECT_THROW(checkWritableTarget(target), FileError);
  EXPECT_EQ(test::readAll(target), "keep");
  EXPECT_EQ(entries(dir), 1u);  // no temporary file left
}

TEST(AtomicFile, SymlinkIsWrittenThrough) {
  const auto dir = test::scratchDir("atomic_file_symlink");
  std::filesystem::create_directories(dir / "data");
  test::writeAll(dir / "data" / "real.txt", "old");
  ASSERT_EQ(::chmod((dir / "data" / "real.txt").c_str(), 0600), 0);
  std::filesystem::create_symlink("data/real.txt", dir / "link.txt");  // relative link
  writeFileAtomically(dir / "link.txt", [](std::ostream& out) { out << "new"; });
  EXPECT_TRUE(std::filesystem::is_symlink(dir / "link.txt"));
  EXPECT_EQ(std::filesystem::read_symlink(dir / "link.txt"), "data/real.txt");
  EXPECT_EQ(test::readAll(dir / "data" / "real.txt"), "new");
  EXPECT_EQ(modeOf(dir / "data" / "real.txt"), 0600u);
  EXPECT_EQ(entries(dir / "data"), 1u);
  EXPECT_EQ(entries(dir), 2u);
}

TEST(AtomicFile, SignalRemovesLiveTemporaryFilesAndReraises) {
  // An interrupted CLI: Ctrl-C (SIGINT), kill (SIGTERM) and a closed terminal (SIGHUP).
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) {
    const auto dir = test::scratchDir("atomic_file_signal_" + std::to_string(signal));
    test::writeAll(dir / "out.txt", "old");
    const pid_t pid = ::fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {  // child: a write in progress, then the signal
      removeTemporaryFilesOnSignals();
      AtomicFileWriter w(dir / "out.txt");
      w.stream() << "half" << std::flush;
      std::raise(signal);
      ::_exit(0);  // not reached: the default action terminates
    }
    int status = 0;
    ASSERT_EQ(::waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(status)) << strsignal(signal);
    EXPECT_EQ(WTERMSIG(status), signal);
    EXPECT_EQ(test::readAll(dir / "out.txt"), "old") << strsignal(signal);
    EXPECT_EQ(entries(dir), 1u) << strsignal(signal);
  }
}

TEST(Progress, SubRangesAndCancel) {
  double last = -1;
  Progress root([&](double f, std::string_view) { last = f; });
  Progress half = root.sub(0.5, 1.0);
  half.report(0.5, "stage");
  EXPECT_DOUBLE_EQ(last, 0.75);
  EXPECT_EQ(root.stage(), "stage");
  Progress quarter = half.sub(0.0, 0.5);
  quarter.report(1.0);
  EXPECT_DOUBLE_EQ(root.fraction(), 0.75);
  EXPECT_NO_THROW(quarter.check());
  root.cancel();
  EXPECT_TRUE(quarter.canceled());
  EXPECT_THROW(quarter.check(), Canceled);
}
