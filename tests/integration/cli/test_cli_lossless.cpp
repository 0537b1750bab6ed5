// plumb-cli conversions and writes that used to lose data silently (issue 12): converting a
// file onto itself, LAS -> LAS fields, NaN points counted, field names with spaces, register
// outputs checked before the run, and an interrupted write leaving no temporary file.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <thread>

#include "support/cli_runner.hpp"
#include "support/test_support.hpp"

extern char** environ;

namespace fs = std::filesystem;
using plumb::test::CliResult;
using plumb::test::plumbCli;
using plumb::test::readAll;
using plumb::test::scratchDir;
using plumb::test::writeAll;

namespace {

const char* kTinyPly =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
    "property float z\nend_header\n0 0 0\n1 0 0\n0 1 nan\n";

/// Files in `dir` whose name holds ".tmp-" (AtomicFileWriter's temporary files).
std::size_t temporaryFiles(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string().find(".tmp-") != std::string::npos;
  return n;
}

TEST(CliLossless, ConvertRefusesToOverwriteItsInput) {
  const auto dir = scratchDir("cli_convert_same");
  writeAll(dir / "a.ply", kTinyPly);
  fs::create_symlink("a.ply", dir / "link.ply");
  fs::create_hard_link(dir / "a.ply", dir / "hard.ply");
  for (const char* args : {"convert a.ply a.ply", "convert a.ply ./a.ply", "convert ./a.ply link.ply",
                           "convert link.ply a.ply", "convert a.ply hard.ply", "convert hard.ply a.ply"}) {
    const CliResult r = plumbCli(dir, args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_NE(r.err.find("is the input file itself"), std::string::npos) << args << ": " << r.err;
    EXPECT_EQ(readAll(dir / "a.ply"), kTinyPly) << args;
  }
  EXPECT_TRUE(fs::is_symlink(dir / "link.ply"));
}

TEST(CliLossless, ConvertToLasBeyondItsIntegerRangeIsAnError) {
  // A 1e308 translation cannot be stored in LAS's scaled 32-bit integers: an error naming the
  // file, exit 1, and no file written (on main: a LAS with 0 points and exit 0).
  const auto dir = scratchDir("cli_convert_las_range");
  writeAll(dir / "a.ply", kTinyPly);
  writeAll(dir / "T.json", R"({"matrix": [[1,0,0,1e308],[0,1,0,0],[0,0,1,0],[0,0,0,1]]})");
  const CliResult r = plumbCli(dir, "convert a.ply far.las --transform T.json");
  EXPECT_EQ(r.exit_code, 1) << r.out << r.err;
  EXPECT_NE(r.err.find("far.las"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "far.las"));
}

TEST(CliLossless, ConvertCountsNanPointsItDrops) {
  const auto dir = scratchDir("cli_convert_nan");
  writeAll(dir / "a.ply", kTinyPly);
  const CliResult r = plumbCli(dir, "convert a.ply b.las");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("(2 points, 1 dropped, 1 scan(s))"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("note: 1 points with a non-finite (NaN) position were not written"),
            std::string::npos) << r.out;
}

TEST(CliLossless, LasToLasKeepsEveryStandardField) {
  const auto dir = scratchDir("cli_convert_las_fields");
  const std::string py = std::string("python3 ") + PLUMB_LAS_FIELDS_PY;
  ASSERT_EQ(std::system((py + " make '" + (dir / "in.las").string() + "'").c_str()), 0);
  const CliResult r = plumbCli(dir, "convert in.las out.las");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"in", "out"})
    ASSERT_EQ(std::system((py + " dump '" + (dir / (std::string(f) + ".las")).string() + "' > '" +
                           (dir / (std::string(f) + ".txt")).string() + "'").c_str()), 0);
  EXPECT_EQ(readAll(dir / "out.txt"), readAll(dir / "in.txt"));
}

// Through E57 too: the LAS attributes travel as Plumb's E57 extension fields.
TEST(CliLossless, LasToE57ToLasKeepsEveryStandardField) {
  const auto dir = scratchDir("cli_convert_las_e57_fields");
  const std::string py = std::string("python3 ") + PLUMB_LAS_FIELDS_PY;
  ASSERT_EQ(std::system((py + " make '" + (dir / "in.las").string() + "'").c_str()), 0);
  CliResult r = plumbCli(dir, "convert in.las mid.e57");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = plumbCli(dir, "convert mid.e57 out.las");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"in", "out"})
    ASSERT_EQ(std::system((py + " dump '" + (dir / (std::string(f) + ".las")).string() + "' > '" +
                           (dir / (std::string(f) + ".txt")).string() + "'").c_str()), 0);
  EXPECT_EQ(readAll(dir / "out.txt"), readAll(dir / "in.txt"));
}

TEST(CliLossless, FieldNamesWithSpacesRoundTrip) {
  const auto dir = scratchDir("cli_field_names");
  writeAll(dir / "a.csv", "x,y,z,my field\n1,2,3,4.5\n5,6,7,8.5\n");
  for (const char* args : {"convert a.csv b.ply", "convert b.ply c.xyz", "convert c.xyz d.ply --ascii"}) {
    const CliResult r = plumbCli(dir, args);
    ASSERT_EQ(r.exit_code, 0) << args << ": " << r.err;
  }
  EXPECT_NE(readAll(dir / "b.ply").find("property float my_field\n"), std::string::npos);
  const std::string d = readAll(dir / "d.ply");
  EXPECT_NE(d.find("property float my_field\n"), std::string::npos) << d;
  EXPECT_NE(d.find("1 2 3 4.5\n"), std::string::npos) << d;
}

TEST(CliLossless, RegisterChecksEveryOutputBeforeRunning) {
  const auto dir = scratchDir("cli_register_outputs");
  writeAll(dir / "s.ply", kTinyPly);
  writeAll(dir / "t.ply", kTinyPly);
  CliResult r = plumbCli(dir, "register s.ply t.ply --transform t.json -o out.nope");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("extension '.nope'"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "t.json"));
  writeAll(dir / "locked.json", "old");
  fs::permissions(dir / "locked.json", fs::perms::owner_read);
  r = plumbCli(dir, "register s.ply t.ply --transform t.json --report locked.json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("read-only"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "t.json"));
  EXPECT_EQ(readAll(dir / "locked.json"), "old");
}

TEST(CliLossless, WritesAreFsyncedBeforeAndAfterTheRename) {
  // strace is a test dependency (packaging/dev.sh installs it).
  ASSERT_EQ(std::system("command -v strace > /dev/null 2>&1"), 0) << "strace not installed";
  const auto dir = scratchDir("cli_fsync");
  writeAll(dir / "a.ply", kTinyPly);
  // LeakSanitizer cannot run under ptrace: off for this traced run (sanitizer tree only).
  const std::string cmd = "cd '" + dir.string() + "' && ASAN_OPTIONS=detect_leaks=0 strace -f -e trace=fsync,rename,openat -o trace.txt '" +
                          PLUMB_CLI_PATH + "' convert a.ply b.xyz > /dev/null";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  // Order of the calls that matter: open temp, fsync, rename over b.xyz, open ".", fsync.
  std::istringstream trace(readAll(dir / "trace.txt"));
  std::string order;
  for (std::string l; std::getline(trace, l);) {
    if (l.find("fsync(") != std::string::npos) order += " fsync";
    else if (l.find("rename(\".b.xyz.tmp-") != std::string::npos && l.find("\"b.xyz\") = 0") != std::string::npos) order += " rename";
    else if (l.find("O_DIRECTORY") != std::string::npos && l.find("\".\"") != std::string::npos) order += " dir";
  }
  EXPECT_NE(order.find("fsync rename dir fsync"), std::string::npos) << order;
}

/// A binary PLY of n points at the origin (written fast: the records are zero bytes).
void writeZeroPly(const fs::path& path, std::size_t n) {
  std::ofstream out(path, std::ios::binary);
  out << "ply\nformat binary_little_endian 1.0\nelement vertex " << n
      << "\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  const std::string block(12 << 16, '\0');
  for (std::size_t done = 0; done < n; done += 1 << 16)
    out.write(block.data(), static_cast<std::streamsize>(12 * std::min<std::size_t>(1 << 16, n - done)));
}

/// Runs `plumb-cli convert` of a 6-million-point PLY to XYZ over an existing file and sends
/// `signal` once the temporary file exists: the CLI must die of that signal, remove its
/// temporary file and leave the old output as it was.
void interruptConvert(int signal) {
  const auto dir = scratchDir("cli_signal_" + std::to_string(signal));
  writeZeroPly(dir / "big.ply", 6'000'000);
  writeAll(dir / "out.xyz", "old\n");
  const std::string in = (dir / "big.ply").string(), out = (dir / "out.xyz").string();
  const char* argv[] = {PLUMB_CLI_PATH, "convert", in.c_str(), out.c_str(), nullptr};
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, PLUMB_CLI_PATH, &actions, nullptr, const_cast<char**>(argv), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  // Wait until the temporary file exists (the write has started), then interrupt.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (temporaryFiles(dir) == 0 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ASSERT_EQ(temporaryFiles(dir), 1u) << "the write never started";
  ASSERT_EQ(kill(pid, signal), 0);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "plumb-cli finished before the signal; status " << status;
  EXPECT_EQ(WTERMSIG(status), signal);
  EXPECT_EQ(temporaryFiles(dir), 0u);
  EXPECT_EQ(readAll(dir / "out.xyz"), "old\n");
}

TEST(CliLossless, SigtermDuringAWriteRemovesTheTemporaryFile) { interruptConvert(SIGTERM); }
TEST(CliLossless, SigintDuringAWriteRemovesTheTemporaryFile) { interruptConvert(SIGINT); }
TEST(CliLossless, SighupDuringAWriteRemovesTheTemporaryFile) { interruptConvert(SIGHUP); }

}  // namespace
