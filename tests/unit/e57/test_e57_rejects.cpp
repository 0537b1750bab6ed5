// Broken files of shared/data/e57 are rejected with a FileError naming the file, the problem
// and where. Locations were obtained with tools/e57_inspect.py (bad CRC pages) and by reading
// the XML section (fileOffset / section id).
#include <gtest/gtest.h>

#include "common/error.hpp"
#include "io/e57/e57_reader.hpp"
#include "support/test_support.hpp"

using namespace plumb;
using plumb::test::sharedData;

namespace {
// Reads and returns the FileError (fails the test if none is thrown).
FileError readError(const std::filesystem::path& path) {
  try {
    readE57(path);
  } catch (const FileError& e) {
    return e;
  }
  ADD_FAILURE() << "no FileError for " << path;
  return FileError(path, "none");
}
void expectContains(const std::string& text, const std::string& part) {
  EXPECT_NE(text.find(part), std::string::npos) << "'" << part << "' not in: " << text;
}
}  // namespace

TEST(E57Rejects, BadCrcOnPage0) {
  const auto path = sharedData("e57/libe57format_self_bad-crc.e57");
  const FileError e = readError(path);
  expectContains(e.what(), path.string());
  expectContains(e.what(), "checksum");
  EXPECT_EQ(e.where().element, "page 0");
  EXPECT_EQ(e.where().byte_offset, 0u);
}

TEST(E57Rejects, CorruptCrcOnPage33) {
  // Python: bad CRC on page 33 (byte 33792), the page holding the XML section.
  const auto path = sharedData("e57/corrupt_crc.e57");
  const FileError e = readError(path);
  expectContains(e.what(), "corrupt_crc.e57");
  expectContains(e.what(), "checksum");
  EXPECT_EQ(e.where().element, "page 33");
  EXPECT_EQ(e.where().byte_offset, 33792u);
}

TEST(E57Rejects, InvalidCompressedVectorHeader) {
  const auto path = sharedData("e57/libe57format_self_InvalidCVHeader.e57");
  const FileError e = readError(path);
  expectContains(e.what(), "InvalidCVHeader.e57");
  expectContains(e.what(), "section id 182");
  EXPECT_EQ(e.where().element, "/e57Root/data3D/0/points");
  EXPECT_EQ(e.where().byte_offset, 48u);  // its fileOffset
}

TEST(E57Rejects, ZeroPointsWithoutSection) {
  // fileOffset="0": the "section" is the file header ('A' of ASTM-E57 = 65).
  const auto path = sharedData("e57/libe57format_self_ZeroPointsInvalid.e57");
  const FileError e = readError(path);
  expectContains(e.what(), "ZeroPointsInvalid.e57");
  expectContains(e.what(), "section id 65");
  EXPECT_EQ(e.where().element, "/e57Root/data3D/0/points");
  EXPECT_EQ(e.where().byte_offset, 0u);
}

TEST(E57Rejects, NotAnE57File) {
  const auto dir = plumb::test::scratchDir("e57_rejects");
  plumb::test::writeAll(dir / "text.e57", std::string(2048, 'x'));
  const FileError e = readError(dir / "text.e57");
  expectContains(e.what(), "not an E57 file");
}

TEST(E57Rejects, TruncatedFile) {
  const auto dir = plumb::test::scratchDir("e57_rejects_trunc");
  const std::string bytes = plumb::test::readAll(sharedData("e57/bunnyInt21.e57"));
  plumb::test::writeAll(dir / "cut.e57", bytes.substr(0, 100 * 1024));
  const FileError e = readError(dir / "cut.e57");
  expectContains(e.what(), "truncated");
  EXPECT_EQ(e.where().byte_offset, 16u);  // header filePhysicalLength
}

TEST(E57Rejects, MissingFile) {
  const FileError e = readError("/nonexistent/dir/x.e57");
  expectContains(e.what(), "cannot open");
}
