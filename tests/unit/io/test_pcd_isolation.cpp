// readPcd runs PCL's reader in the plumb-import helper (issue 12): what it reads equals the
// in-process read (our checks, PCL, the conversion) on every PCD we have; a crash, a hang past
// the time limit, a missing helper and a cancel end in a FileError or Canceled while the
// caller carries on. The helper fails on purpose through PLUMB_IMPORT_HELPER_FAULT (honoured
// only by plumb-import).
#include <gtest/gtest.h>

#include <stdlib.h>

#include <chrono>
#include <cstring>
#include <string>

#include "common/error.hpp"
#include "io/io.hpp"
#include "io/pcd/helper/pcd_pcl_reader.hpp"
#include "io/pcd/pcd_io.hpp"
#include "support/scoped_env.hpp"
#include "support/test_support.hpp"

using namespace plumb;

namespace {

using test::ScopedEnv;

template <class T, class A>
bool sameBytes(const std::vector<T, A>& a, const std::vector<T, A>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// Every column bit for bit (NaN grid holes included), the grid, the offset, the metadata.
void expectSame(const Dataset& a, const Dataset& b) {
  EXPECT_EQ(a.metadata, b.metadata);
  EXPECT_EQ(a.format, b.format);
  ASSERT_EQ(a.scans.size(), 1u);
  ASSERT_EQ(b.scans.size(), 1u);
  const PointCloud &x = a.scans[0].cloud, &y = b.scans[0].cloud;
  EXPECT_EQ(a.scans[0].name, b.scans[0].name);
  EXPECT_EQ(x.offset, y.offset);
  EXPECT_TRUE(sameBytes(x.positions, y.positions));
  EXPECT_TRUE(sameBytes(x.position_residuals, y.position_residuals));
  EXPECT_TRUE(sameBytes(x.normals, y.normals));
  EXPECT_TRUE(sameBytes(x.colors, y.colors));
  EXPECT_TRUE(sameBytes(x.intensity, y.intensity));
  EXPECT_TRUE(x.row == y.row && x.column == y.column);
  EXPECT_EQ(x.grid_rows, y.grid_rows);
  EXPECT_EQ(x.grid_columns, y.grid_columns);
  ASSERT_EQ(x.scalar_fields.size(), y.scalar_fields.size());
  for (std::size_t i = 0; i < x.scalar_fields.size(); ++i) {
    EXPECT_EQ(x.scalar_fields[i].name, y.scalar_fields[i].name);
    EXPECT_TRUE(sameBytes(x.scalar_fields[i].values, y.scalar_fields[i].values)) << x.scalar_fields[i].name;
  }
}

/// The shared captures and scans, the fuzz seeds (ascii, binary, double + normals + a
/// multi-valued field, organized compressed) and the regressions that read.
std::vector<std::filesystem::path> everyPcd() {
  std::vector<std::filesystem::path> files;
  const std::filesystem::path source = std::filesystem::path(PLUMB_SOURCE_DIR) / "tests";
  for (const auto& dir : {test::sharedData("pcd"), source / "fuzz/seeds/pcd", source / "unit/pcd/regressions"})
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".pcd" && e.path().string().find(".error.") == std::string::npos)
        files.push_back(e.path());
  return files;
}

/// The FileError readPcd throws for `path` (fails the test if it reads).
std::string readError(const std::filesystem::path& path) {
  try {
    readPcd(path);
    ADD_FAILURE() << path << " read, expected an error";
  } catch (const FileError& e) {
    EXPECT_EQ(e.file(), path);
    return e.what();
  }
  return {};
}

const std::filesystem::path kRoom = test::sharedData("pcd/room_scan1.pcd");

}  // namespace

TEST(PcdIsolation, HelperReadEqualsInProcessReadOnEveryPcd) {
  const auto files = everyPcd();
  EXPECT_GE(files.size(), 11u);  // 7 shared + 4 seeds
  for (const auto& f : files) {
    SCOPED_TRACE(f.string());
    expectSame(readPcd(f), readPcdInProcess(f));
  }
}

TEST(PcdIsolation, ViewpointAndOrganizedGridComeThroughTheStream) {
  const auto dir = test::scratchDir("pcd_isolation_viewpoint");
  test::writeAll(dir / "vp.pcd",
                 "VERSION 0.7\nFIELDS x y z rgb label\nSIZE 4 4 4 4 2\nTYPE F F F U U\nCOUNT 1 1 1 1 1\nWIDTH 2\n"
                 "HEIGHT 2\nVIEWPOINT 1.5 -2 3 0.7071068 0 0.7071068 0\nPOINTS 4\nDATA ascii\n"
                 "1 2 3 16711680 7\nnan nan nan 0 0\n4 5 6 255 9\n7 8 9 65280 11\n");
  const Dataset d = readPcd(dir / "vp.pcd");
  expectSame(d, readPcdInProcess(dir / "vp.pcd"));
  const PointCloud& c = d.scans[0].cloud;
  ASSERT_EQ(c.size(), 4u);
  EXPECT_EQ(c.grid_rows, 2);
  EXPECT_TRUE(std::isnan(c.positions[1].x()));
  EXPECT_EQ(c.colors[0], (Rgb8{255, 0, 0}));
  ASSERT_NE(c.findScalarField("label"), nullptr);
  EXPECT_EQ(c.findScalarField("label")->values[3], 11.f);
  bool found = false;
  for (const auto& [key, value] : d.metadata)
    if (key == "viewpoint") found = value == "1.5 -2 3 0.707107 0 0.707107 0";
  EXPECT_TRUE(found);
}

TEST(PcdIsolation, HelperCrashIsAFileErrorAndTheCallerCarriesOn) {
  for (const auto& [fault, signal] : {std::pair{"segv", "SIGSEGV"}, std::pair{"abort", "SIGABRT"}}) {
    std::string msg;
    {
      ScopedEnv env("PLUMB_IMPORT_HELPER_FAULT", fault);
      msg = readError(kRoom);
      EXPECT_THROW(readFile(kRoom), FileError);  // the dispatcher the CLI and the GUI use
    }
    EXPECT_NE(msg.find("room_scan1.pcd"), std::string::npos) << msg;
    EXPECT_NE(msg.find(std::string("PCL crashed (") + signal), std::string::npos) << msg;
    EXPECT_NE(msg.find("Plumb itself is unaffected"), std::string::npos) << msg;
    EXPECT_EQ(readPcd(kRoom).pointCount(), 112586u);  // this process still reads
  }
}

TEST(PcdIsolation, HangStopsAtTheTimeLimit) {
  ScopedEnv fault("PLUMB_IMPORT_HELPER_FAULT", "hang");
  ScopedEnv timeout("PLUMB_IMPORT_TIMEOUT", "2");
  const auto start = std::chrono::steady_clock::now();
  const std::string msg = readError(kRoom);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(took, 2.0);
  EXPECT_LT(took, 6.0);
  EXPECT_NE(msg.find("room_scan1.pcd: reading this PCD file with PCL took longer than the time limit of 2 s"),
            std::string::npos) << msg;
  EXPECT_NE(msg.find("Plumb itself is unaffected"), std::string::npos) << msg;
  EXPECT_NE(msg.find("PLUMB_IMPORT_TIMEOUT"), std::string::npos) << msg;
}

TEST(PcdIsolation, CancelStopsTheHelper) {
  ScopedEnv fault("PLUMB_IMPORT_HELPER_FAULT", "hang");
  Progress progress;
  progress.cancel();
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THROW(readPcd(kRoom, &progress), Canceled);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 3.0);
}

TEST(PcdIsolation, MissingHelperIsAFileError) {
  ScopedEnv helper("PLUMB_IMPORT_HELPER", "/nonexistent/plumb-import");
  const std::string msg = readError(kRoom);
  EXPECT_NE(msg.find("room_scan1.pcd: cannot read PCD files: the helper program plumb-import is missing"),
            std::string::npos) << msg;
  EXPECT_NE(msg.find("/nonexistent/plumb-import"), std::string::npos) << msg;
}

TEST(PcdIsolation, HeaderErrorsStayPreciseWithoutTheHelper) {
  // Our checks run in Plumb first: a bad header is reported with its line even with no helper.
  ScopedEnv helper("PLUMB_IMPORT_HELPER", "/nonexistent/plumb-import");
  const auto dir = test::scratchDir("pcd_isolation_header");
  test::writeAll(dir / "h.pcd",
                 "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F Q\nWIDTH 1\nPOINTS 1\nDATA ascii\n1 2 3\n");
  const std::string msg = readError(dir / "h.pcd");
  EXPECT_NE(msg.find("field 'z' has an invalid TYPE/SIZE Q/4"), std::string::npos) << msg;
  EXPECT_NE(msg.find("line 7"), std::string::npos) << msg;
}

// Not built into the AddressSanitizer tree: there the helper sets no address-space limit.
#if !defined(__SANITIZE_ADDRESS__)
TEST(PcdIsolation, MemoryLimitIsAFileError) {
  ScopedEnv memory("PLUMB_IMPORT_MEMORY_MB", "32");
  const std::string msg = readError(test::sharedData("pcd/capture0001.pcd"));
  EXPECT_NE(msg.find("capture0001.pcd: reading this PCD file with PCL ran out of memory under the limit of 32 MiB"),
            std::string::npos) << msg;
  EXPECT_NE(msg.find("Plumb itself is unaffected"), std::string::npos) << msg;
}
#endif
