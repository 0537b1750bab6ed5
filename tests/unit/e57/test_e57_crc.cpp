#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "io/e57/crc32c.hpp"

using namespace plumb::e57;

TEST(E57Crc, CheckValue) {
  // The CRC-32C check value from docs/E57_FORMAT.md §3.
  const char* s = "123456789";
  EXPECT_EQ(crc32cTable(s, 9), 0xE3069283u);
  EXPECT_EQ(crc32c(s, 9), 0xE3069283u);
}

TEST(E57Crc, HardwareAndTableAgree) {
  // This machine (x86-64 CI) has SSE4.2; the hardware path must be exercised here.
  ASSERT_TRUE(crc32cHardwareAvailable());
  std::mt19937 rng(7);
  std::vector<unsigned char> buf(5000);
  for (auto& b : buf) b = static_cast<unsigned char>(rng());
  for (std::size_t start : {0u, 1u, 3u, 7u})
    for (std::size_t len : {0u, 1u, 7u, 8u, 9u, 63u, 1020u, 4093u})
      EXPECT_EQ(crc32cHardware(buf.data() + start, len), crc32cTable(buf.data() + start, len))
          << "start " << start << " len " << len;
  EXPECT_EQ(crc32cHardware("123456789", 9), 0xE3069283u);
}
