#include <gtest/gtest.h>

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
