// The steps of parseHeader alone, each on a header built field by field: the error each one
// gives names the field's byte offset, and the counts follow the LAS_FACTS section 2 rule.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "common/error.hpp"
#include "io/las/las_header.hpp"

using namespace plumb;
using namespace plumb::las;

namespace {

const std::filesystem::path kFile = "steps.las";

/// Runs f, which must throw a FileError whose message contains `text`, at `byte` of the header.
template <class F>
void expectHeaderError(F&& f, const std::string& text, std::uint64_t byte) {
  try {
    f();
  } catch (const FileError& e) {
    EXPECT_NE(e.message().find(text), std::string::npos) << e.message();
    ASSERT_TRUE(e.where().byte_offset.has_value()) << e.what();
    EXPECT_EQ(*e.where().byte_offset, byte) << e.what();
    EXPECT_EQ(e.where().element, "LAS header");
    return;
  }
  ADD_FAILURE() << "no FileError, expected '" << text << "'";
}

/// A valid LAS 1.2 format 1 header, points right after it.
LasHeader header12() {
  LasHeader h;
  h.version_minor = 2;
  h.header_size = kHeaderSize12;
  h.offset_to_points = kHeaderSize12;
  h.format_byte = 1;
  h.record_length = 28;
  return h;
}

}  // namespace

TEST(LasHeaderSteps, SignatureThenTheSizeOfALas12Header) {
  const std::vector<std::uint8_t> bad{'L', 'A', 'S', 0x01, 0, 0};
  expectHeaderError([&] { checkSignatureAndSize(bad, 6, kFile); }, "signature is 'LAS?' instead of 'LASF'", 0);
  std::vector<std::uint8_t> short_header(226, 0);
  std::memcpy(short_header.data(), "LASF", 4);
  expectHeaderError([&] { checkSignatureAndSize(short_header, 5000, kFile); },
                    "the file has 5000 bytes, a LAS header needs at least 227", 226);
  short_header.push_back(0);
  EXPECT_NO_THROW(checkSignatureAndSize(short_header, 5000, kFile));
}

TEST(LasHeaderSteps, FieldsLoadWhereSerializeHeaderStoresThem) {
  LasHeader h = header12();
  h.version_minor = 4;
  h.header_size = kHeaderSize14;
  h.file_source_id = 77;
  h.global_encoding = 0x11;
  h.system_identifier = "scanner";
  h.creation_year = 2024;
  h.vlr_count = 3;
  h.legacy_count = 12;
  h.legacy_by_return = {1, 2, 3, 4, 5};
  h.scale = {0.01, 0.001, 0.0001};
  h.offset = {100, 200, 300};
  h.min = {-1, -2, -3};
  h.max = {4, 5, 6};  // stored max before min per axis: a swap would show here
  h.evlr_start = 9999;
  h.count64 = 12;
  const std::vector<std::uint8_t> bytes = serializeHeader(h);
  LasHeader r = loadHeaderFields(bytes.data());
  EXPECT_EQ(r.file_source_id, 77);
  EXPECT_EQ(r.global_encoding, 0x11);
  EXPECT_EQ(r.system_identifier, "scanner");
  EXPECT_EQ(r.creation_year, 2024);
  EXPECT_EQ(r.vlr_count, 3u);
  EXPECT_EQ(r.legacy_by_return, h.legacy_by_return);
  EXPECT_EQ(r.scale, h.scale);
  EXPECT_EQ(r.offset, h.offset);
  EXPECT_EQ(r.min, h.min);
  EXPECT_EQ(r.max, h.max);
  EXPECT_EQ(r.evlr_start, 0u) << "1.4 fields are loaded by loadVersionFields only";
  loadVersionFields(r, bytes.data());
  EXPECT_EQ(r.evlr_start, 9999u);
  EXPECT_EQ(r.count64, 12u);
}

TEST(LasHeaderSteps, VersionAndHeaderSize) {
  LasHeader h = header12();
  EXPECT_NO_THROW(checkVersionAndHeaderSize(h, 227, 227, kFile));
  h.version_major = 2;
  expectHeaderError([&] { checkVersionAndHeaderSize(h, 227, 227, kFile); }, "unsupported LAS version 2.2", 24);
  h = header12();
  h.version_minor = 3;  // 1.3 needs 235 bytes
  expectHeaderError([&] { checkVersionAndHeaderSize(h, 400, 400, kFile); },
                    "header size 227 is below the 235 bytes LAS 1.3 requires", 94);
  h.version_minor = 4;
  h.header_size = kHeaderSize14;
  expectHeaderError([&] { checkVersionAndHeaderSize(h, 300, 1000, kFile); },
                    "header size 375 runs past the end of the file (1000 bytes)", 94);
}

TEST(LasHeaderSteps, PointFormatRefusesLazAndShortRecordsAndWarnsOutsideItsVersion) {
  LasHeader h = header12();
  h.format_byte = 0x81;
  expectHeaderError([&] { checkPointFormat(h, kFile); }, "is LAZ-compressed (point format byte is 129", 104);
  h.format_byte = 11;
  expectHeaderError([&] { checkPointFormat(h, kFile); }, "unknown point data record format 11", 104);
  h.format_byte = 6;  // defined from LAS 1.4 on
  h.record_length = 30;
  checkPointFormat(h, kFile);
  ASSERT_EQ(h.warnings.size(), 1u);
  EXPECT_EQ(h.warnings[0], "point format 6 is not defined for LAS 1.2; read anyway");
  h.record_length = 29;
  expectHeaderError([&] { checkPointFormat(h, kFile); }, "point record length 29 is shorter than the 30 bytes", 105);
}

TEST(LasHeaderSteps, ScaleAndOffsetNameTheirAxisAndByte) {
  LasHeader h = header12();
  EXPECT_NO_THROW(checkScaleAndOffset(h, kFile));
  h.scale[2] = std::numeric_limits<double>::quiet_NaN();
  expectHeaderError([&] { checkScaleAndOffset(h, kFile); }, "scale factor of Z is nan", 131 + 16);
  h = header12();
  h.scale[0] = 0.0;
  expectHeaderError([&] { checkScaleAndOffset(h, kFile); }, "scale factor of X is 0 (must be finite", 131);
  h = header12();
  h.offset[1] = std::numeric_limits<double>::infinity();
  expectHeaderError([&] { checkScaleAndOffset(h, kFile); }, "offset of Y is not finite", 155 + 8);
}

TEST(LasHeaderSteps, OffsetToPointsLiesBetweenHeaderAndEndOfFile) {
  LasHeader h = header12();
  EXPECT_NO_THROW(checkOffsetToPoints(h, 227, kFile));
  h.offset_to_points = 200;
  expectHeaderError([&] { checkOffsetToPoints(h, 1000, kFile); }, "offset to point data 200 is inside the header (227", 96);
  h.offset_to_points = 2000;
  expectHeaderError([&] { checkOffsetToPoints(h, 1000, kFile); }, "is past the end of the file (1000 bytes)", 96);
}

TEST(LasHeaderSteps, PointCountRuleOfLas14) {
  LasHeader h = header12();
  h.legacy_count = 7;
  h.count64 = 9;  // ignored before 1.4
  EXPECT_EQ(choosePointCount(h), at::kLegacyCount);
  EXPECT_EQ(h.point_count, 7u);
  h.version_minor = 4;
  h.legacy_count = 0;
  EXPECT_EQ(choosePointCount(h), at::kCount64);
  EXPECT_EQ(h.point_count, 9u);
  EXPECT_TRUE(h.warnings.empty());
  h.legacy_count = 5;  // a non-zero legacy count that disagrees wins, with a warning
  EXPECT_EQ(choosePointCount(h), at::kLegacyCount);
  EXPECT_EQ(h.point_count, 5u);
  ASSERT_EQ(h.warnings.size(), 1u);
  EXPECT_NE(h.warnings[0].find("legacy point count 5 disagrees with the 64-bit count 9"), std::string::npos);
}

TEST(LasHeaderSteps, PointRecordsMustFitBeforeTheEvlrs) {
  LasHeader h = header12();
  h.version_minor = 4;
  h.offset_to_points = 375;
  h.record_length = 30;
  h.point_count = 10;  // 300 bytes
  EXPECT_NO_THROW(checkPointCount(h, at::kCount64, 675, kFile));
  h.evlr_count = 1;
  h.evlr_start = 600;  // EVLRs after 225 bytes of points
  expectHeaderError([&] { checkPointCount(h, at::kCount64, 675, kFile); },
                    "header declares 10 points of 30 bytes from byte 375, but only 225 bytes", at::kCount64);
  h.evlr_start = 5000;  // past the end: not a limit, the end of the file is
  EXPECT_NO_THROW(checkPointCount(h, at::kCount64, 675, kFile));
  expectHeaderError([&] { checkPointCount(h, at::kLegacyCount, 674, kFile); }, "only 299 bytes", at::kLegacyCount);
}
