// The PCD stream between plumb-import --pcd and readPcd: a round trip keeps the layout, the
// viewpoint and the records (which stay in the stream's bytes); a damaged stream (cut short,
// lying counts, a field beyond the record, records that do not match the size) is an error.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "io/pcd/pcd_stream.hpp"
#include "support/piped_bytes.hpp"

using namespace plumb;

namespace {

/// Two points of x y z float + intensity u16 (point_step 14).
PcdLayout twoPointLayout() {
  PcdLayout l;
  l.width = 2;
  l.height = 1;
  l.point_step = 14;
  l.fields = {{"x", 0, pcd_type::kFloat32, 1}, {"y", 4, pcd_type::kFloat32, 1}, {"z", 8, pcd_type::kFloat32, 1},
              {"intensity", 12, pcd_type::kUint16, 1}};
  l.viewpoint = {1, 2, 3, 0.5, 0.5, 0.5, 0.5};
  return l;
}

std::vector<std::uint8_t> records(std::size_t n) {
  std::vector<std::uint8_t> r(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = static_cast<std::uint8_t>(i * 7);
  return r;
}

std::string encode(const PcdLayout& l, const std::vector<std::uint8_t>& points) {
  return test::pipedBytes([&](int fd) { return pcd_stream::writeCloud(fd, l, points); });
}

}  // namespace

TEST(PcdStream, RoundTripKeepsLayoutViewpointAndRecordsInPlace) {
  const PcdLayout l = twoPointLayout();
  const auto points = records(28);
  const std::string bytes = encode(l, points);
  const auto out = pcd_stream::decode(bytes);
  const auto& c = std::get<pcd_stream::Cloud>(out);
  EXPECT_EQ(c.layout.width, 2u);
  EXPECT_EQ(c.layout.point_step, 14u);
  EXPECT_EQ(c.layout.viewpoint, l.viewpoint);
  ASSERT_EQ(c.layout.fields.size(), 4u);
  EXPECT_EQ(c.layout.fields[3].name, "intensity");
  EXPECT_EQ(c.layout.fields[3].offset, 12u);
  EXPECT_EQ(c.layout.fields[3].datatype, pcd_type::kUint16);
  ASSERT_EQ(c.points.size(), 28u);
  EXPECT_EQ(std::memcmp(c.points.data(), points.data(), 28), 0);
  // No copy: the records are read where they lie in the stream.
  EXPECT_GE(reinterpret_cast<const char*>(c.points.data()), bytes.data());
  EXPECT_LT(reinterpret_cast<const char*>(c.points.data()), bytes.data() + bytes.size());
}

TEST(PcdStream, FailureKeepsMessageAndLocation) {
  helper_stream::Failure f{"PCL could not read the binary data", {}};
  f.where.line = 12;
  f.where.byte_offset = 345;
  f.where.element = "data";
  const auto out = pcd_stream::decode(test::pipedBytes([&](int fd) { return pcd_stream::writeFailure(fd, f); }));
  const auto& r = std::get<helper_stream::Failure>(out);
  EXPECT_EQ(r.message, f.message);
  EXPECT_EQ(r.where.line.value_or(0), 12u);
  EXPECT_EQ(r.where.byte_offset.value_or(0), 345u);
  EXPECT_EQ(r.where.element, "data");
}

TEST(PcdStream, TruncatedStreamsAreErrors) {
  const std::string good = encode(twoPointLayout(), records(28));
  for (std::size_t cut : {std::size_t{0}, std::size_t{7}, std::size_t{13}, std::size_t{20}, good.size() / 2,
                          good.size() - 5, good.size() - 1})
    EXPECT_THROW(pcd_stream::decode(good.substr(0, cut)), std::runtime_error) << cut;
  EXPECT_THROW(pcd_stream::decode(good + "x"), std::runtime_error);  // bytes after END!
}

TEST(PcdStream, LyingCountsAreErrors) {
  const std::string good = encode(twoPointLayout(), records(28));
  std::string fields = good;
  fields[8 + 4 + 1 + 12 + 3] = '\x7f';  // top byte of the field count (after magic, version, kind, sizes)
  EXPECT_THROW(pcd_stream::decode(fields), std::runtime_error);
  std::string point_bytes = good;
  const std::size_t count_at = good.size() - 4 - 28 - 8;  // the u64 before the records and END!
  point_bytes[count_at + 7] = '\x7f';
  EXPECT_THROW(pcd_stream::decode(point_bytes), std::runtime_error);
  PcdLayout wider = twoPointLayout();
  wider.width = 3;  // 3 points declared, 2 sent
  EXPECT_THROW(pcd_stream::decode(encode(wider, records(28))), std::runtime_error);
  PcdLayout huge = twoPointLayout();
  huge.width = huge.height = 0xFFFFFFFFu;  // 2^64 - 2^33 + 1 points: no overflow into a match
  EXPECT_THROW(pcd_stream::decode(encode(huge, records(28))), std::runtime_error);
}

TEST(PcdStream, FieldsOutsideTheRecordAreErrors) {
  PcdLayout beyond = twoPointLayout();
  beyond.fields[3].offset = 13;  // a u16 at 13..15 in a record of 14 bytes
  try {
    pcd_stream::decode(encode(beyond, records(28)));
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("field 'intensity' (offset 13"), std::string::npos) << e.what();
  }
  PcdLayout counted = twoPointLayout();
  counted.fields[0].count = 0x40000001u;  // 4 x count wraps a 32-bit product to 4
  EXPECT_THROW(pcd_stream::decode(encode(counted, records(28))), std::runtime_error);
  PcdLayout unknown = twoPointLayout();
  unknown.fields[1].datatype = 9;
  EXPECT_THROW(pcd_stream::decode(encode(unknown, records(28))), std::runtime_error);
}

TEST(PcdStream, FuzzSeedIsAValidStream) {
  // tests/fuzz/seeds/pcd/helper_stream.plumbpcd starts fuzz_pcd's decoder on a real stream.
  std::ifstream in(std::filesystem::path(PLUMB_SOURCE_DIR) / "tests/fuzz/seeds/pcd/helper_stream.plumbpcd",
                   std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto out = pcd_stream::decode(bytes);
  const auto& c = std::get<pcd_stream::Cloud>(out);
  EXPECT_EQ(c.layout.points(), 2u);
  ASSERT_EQ(c.layout.fields.size(), 3u);
  float z1;
  std::memcpy(&z1, c.points.data() + 12 + c.layout.fields[2].offset, 4);
  EXPECT_EQ(z1, 6.f);
}
