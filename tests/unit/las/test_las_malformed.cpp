// Malformed LAS input: every defect is a FileError naming the file, the problem and the byte
// offset; nothing crashes and nothing allocates for absurd counts.
#include <gtest/gtest.h>

#include <string>

#include "common/error.hpp"
#include "io/las/las_reader.hpp"
#include "las_test_util.hpp"
#include "support/test_support.hpp"

namespace plumb {
namespace {

using test::las::bytesOf;
using test::las::poke;

// Reads `b` from memory and returns the FileError it must raise.
FileError errorOf(const std::vector<std::uint8_t>& b) {
  try {
    (void)readLasBuffer(b, "broken.las");
  } catch (const FileError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.las"), std::string::npos) << e.what();
    return e;
  }
  ADD_FAILURE() << "no FileError";
  return FileError("none", "none");
}

void expectError(const std::vector<std::uint8_t>& b, const std::string& words,
                 std::optional<std::uint64_t> offset) {
  const FileError e = errorOf(b);
  EXPECT_NE(e.message().find(words), std::string::npos) << e.what();
  if (offset) {
    ASSERT_TRUE(e.where().byte_offset.has_value()) << e.what();
    EXPECT_EQ(*e.where().byte_offset, *offset) << e.what();
  }
}

TEST(LasMalformed, EmptyAndBadSignature) {
  expectError({}, "not a LAS file", 0);
  auto b = bytesOf("las/simple1_1.las");
  b[3] = 'X';
  expectError(b, "signature is 'LASX'", 0);
}

TEST(LasMalformed, TruncatedHeader) {
  auto b = bytesOf("las/simple1_1.las");
  b.resize(100);
  expectError(b, "truncated LAS header", 100);
  auto c = bytesOf("las/test1_4.las");  // 1.4 needs 375 header bytes
  c.resize(300);
  expectError(c, "header size 375 runs past the end of the file", 94);
}

TEST(LasMalformed, TruncatedPointsAndAbsurdCounts) {
  auto b = bytesOf("las/simple1_1.las");  // 1.1: count at 107
  b.resize(b.size() / 2);
  expectError(b, "header declares 1065 points", 107);
  auto c = bytesOf("las/simple1_1.las");
  poke<std::uint32_t>(c, 107, 0xFFFFFFFFu);
  expectError(c, "header declares 4294967295 points", 107);
  auto d = bytesOf("las/autzen-bmx-2010.las");  // 1.4, legacy 0: 64-bit count at 247
  poke<std::uint64_t>(d, 247, 1ull << 60);
  expectError(d, "header declares 1152921504606846976 points", 247);
}

TEST(LasMalformed, LazIsRecognisedAndRefusedWithHowToDecompress) {
  auto b = bytesOf("las/autzen-bmx-2010.las");
  b[104] = 7 | 0x80;  // LASzip sets bit 7 of the point format
  const FileError e = errorOf(b);
  EXPECT_NE(e.message().find("LAZ-compressed"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("laszip"), std::string::npos) << e.what();
  EXPECT_NE(e.message().find("las2las"), std::string::npos) << e.what();
  EXPECT_EQ(e.where().byte_offset.value_or(0), 104u);
  // The LASzip VLR alone (bit clear) is refused too.
  auto v = bytesOf("las/autzen-bmx-2010.las");  // VLR 1 at 375: user id at 377, record id 393
  std::memset(v.data() + 377, 0, 16);
  std::memcpy(v.data() + 377, "laszip encoded", 14);
  poke<std::uint16_t>(v, 393, 22204);
  expectError(v, "LAZ-compressed", 375);
  // And a .laz name, whatever the content.
  const auto dir = test::scratchDir("las_laz");
  test::writeAll(dir / "x.laz", test::readAll(test::sharedData("las/simple1_1.las")));
  try {
    (void)readLas(dir / "x.laz");
    ADD_FAILURE() << "a .laz file was read";
  } catch (const FileError& err) {
    EXPECT_NE(std::string(err.what()).find("laszip"), std::string::npos);
  }
}

TEST(LasMalformed, HeaderFields) {
  auto v = bytesOf("las/simple1_1.las");
  v[24] = 2;
  expectError(v, "unsupported LAS version 2.1", 24);
  auto h = bytesOf("las/simple1_1.las");
  poke<std::uint16_t>(h, 94, 100);
  expectError(h, "header size 100 is below the 227", 94);
  auto f = bytesOf("las/simple1_1.las");
  f[104] = 11;
  expectError(f, "unknown point data record format 11", 104);
  auto r = bytesOf("las/simple1_1.las");
  poke<std::uint16_t>(r, 105, 20);  // format 1 needs 28
  expectError(r, "point record length 20 is shorter than the 28", 105);
  auto s = bytesOf("las/simple1_1.las");
  poke<double>(s, 139, 0.0);  // Y scale
  expectError(s, "scale factor of Y is 0", 139);
  auto o = bytesOf("las/simple1_1.las");
  poke<std::uint32_t>(o, 96, 0x7FFFFFFF);
  expectError(o, "offset to point data 2147483647 is past the end", 96);
  auto i = bytesOf("las/simple1_1.las");
  poke<std::uint32_t>(i, 96, 100);
  expectError(i, "is inside the header", 96);
}

TEST(LasMalformed, VlrsAndEvlrs) {
  auto n = bytesOf("las/autzen-bmx-2010.las");  // 1 VLR of 841 bytes at 375, points at 1270
  poke<std::uint32_t>(n, 100, 2);
  expectError(n, "VLR header runs past the start of the point data", 1270);
  auto l = bytesOf("las/autzen-bmx-2010.las");
  poke<std::uint16_t>(l, 375 + 20, 900);
  expectError(l, "runs past the start of the point data", 375);
  auto e = bytesOf("las/1_4_w_evlr.las");  // EVLR at 32305, 16 bytes
  poke<std::uint64_t>(e, 235, 1000);
  expectError(e, "start of first EVLR (1000)", 235);
  auto x = bytesOf("las/1_4_w_evlr.las");
  poke<std::uint64_t>(x, 32305 + 20, 1ull << 40);
  expectError(x, "EVLR 'pylastest' 42 of 1099511627776 bytes runs past the end", 32305);
  auto c = bytesOf("las/1_4_w_evlr.las");
  poke<std::uint32_t>(c, 243, 5);
  expectError(c, "EVLR header runs past the end of the file", 32305 + 60 + 16);
}

TEST(LasMalformed, ExtraBytesDescriptorBeyondTheRecord) {
  auto b = bytesOf("las/extrabytes.las");  // descriptors at 375+54; first is ushort[3]
  b[375 + 54 + 2] = 30;                    // double[3] = 24 bytes, then 7+2+4+8 more > 27
  expectError(b, "does not fit the 27 extra bytes", std::nullopt);
  auto t = bytesOf("las/extrabytes.las");
  t[375 + 54 + 2] = 31;
  expectError(t, "invalid data type 31", 375 + 54);
}

TEST(LasMalformed, EveryTruncationIsAnErrorOrAValidPrefix) {
  // A cheap deterministic fuzz: every prefix of a real file (step 7 bytes) either reads or
  // raises FileError; none crashes, none reads more points than the header declares.
  const auto full = bytesOf("las/1_4_w_evlr.las");
  std::size_t errors = 0;
  for (std::size_t n = 0; n < full.size(); n += 7) {
    std::vector<std::uint8_t> b(full.begin(), full.begin() + n);
    try {
      const Dataset d = readLasBuffer(b, "prefix.las");
      EXPECT_LE(d.pointCount(), 1000u);
    } catch (const FileError&) {
      ++errors;
    }
  }
  EXPECT_GT(errors, full.size() / 7 - 2);  // only the complete file (EVLR included) reads
}

}  // namespace
}  // namespace plumb
