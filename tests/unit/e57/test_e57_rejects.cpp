// Broken files of shared/data/e57 are rejected with a FileError naming the file, the problem
// and where. Locations were obtained with tools/e57_inspect.py (bad CRC pages) and by reading
// the XML section (fileOffset / section id).
#include <gtest/gtest.h>

#include <cstdint>

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

// The broken files of shared/data/e57: what the message must say and where it must point.
struct BrokenFile {
  const char* file;
  const char* problem;   // a phrase the message must contain
  const char* element;   // FileLocation::element
  std::uint64_t offset;  // FileLocation::byte_offset
};
class E57BrokenFile : public ::testing::TestWithParam<BrokenFile> {};

TEST_P(E57BrokenFile, IsRejectedWithFileProblemAndPlace) {
  const auto path = sharedData(std::string("e57/") + GetParam().file);
  const FileError e = readError(path);
  expectContains(e.what(), path.filename().string());
  expectContains(e.what(), GetParam().problem);
  EXPECT_EQ(e.where().element, GetParam().element);
  EXPECT_EQ(e.where().byte_offset, GetParam().offset);
}

INSTANTIATE_TEST_SUITE_P(
    SharedData, E57BrokenFile,
    ::testing::Values(
        // Python (tools/e57_inspect.py): bad CRC on the first page.
        BrokenFile{"libe57format_self_bad-crc.e57", "checksum", "page 0", 0},
        // Python: bad CRC on page 33 (byte 33792), the page holding the XML section.
        BrokenFile{"corrupt_crc.e57", "checksum", "page 33", 33792},
        // The points' fileOffset (48) leads to a section id 182, not a compressed vector.
        BrokenFile{"libe57format_self_InvalidCVHeader.e57", "section id 182",
                   "/e57Root/data3D/0/points", 48},
        // fileOffset="0": the "section" is the file header ('A' of ASTM-E57 = 65).
        BrokenFile{"libe57format_self_ZeroPointsInvalid.e57", "section id 65",
                   "/e57Root/data3D/0/points", 0}));

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
