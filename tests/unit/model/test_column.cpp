// Column<T> (core/model/column.hpp): a std::vector whose large blocks are 2 MiB-aligned
// mappings; values survive growth across the small/large boundary, copies and moves, and
// resize(n, value) still fills; resize(n) zeros new values like any vector, and only the
// readers' explicit resizeForOverwrite skips the zeroing.
#include <gtest/gtest.h>

#include <Eigen/Core>

#include <cstdint>

#include "model/column.hpp"
#include "model/point_cloud.hpp"

using namespace plumb;

namespace {

constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;

bool hugeAligned(const void* p) { return reinterpret_cast<std::uintptr_t>(p) % kHuge == 0; }

TEST(Column, LargeBlocksAreHugePageAligned) {
  Column<float> large(column_memory::kLargeBytes / sizeof(float));
  EXPECT_TRUE(hugeAligned(large.data()));
  Column<Eigen::Vector3f> positions(3'000'001);  // not a multiple of the page size
  EXPECT_TRUE(hugeAligned(positions.data()));
  positions.back() = {1.f, 2.f, 3.f};  // the last value is mapped
  EXPECT_EQ(positions.back(), Eigen::Vector3f(1.f, 2.f, 3.f));
}

TEST(Column, ValuesSurviveGrowthAcrossTheLargeBoundary) {
  Column<std::uint32_t> v;
  const std::uint32_t n = 3 * column_memory::kLargeBytes / sizeof(std::uint32_t);
  for (std::uint32_t i = 0; i < n; ++i) v.push_back(i * 2654435761u);  // heap, then mapped blocks
  ASSERT_EQ(v.size(), n);
  EXPECT_TRUE(hugeAligned(v.data()));
  for (std::uint32_t i = 0; i < n; i += 997) ASSERT_EQ(v[i], i * 2654435761u);
  v.resize(10);
  v.shrink_to_fit();  // back to a heap block
  EXPECT_EQ(v[9], 9u * 2654435761u);
}

TEST(Column, CopiesMovesAndFilledResize) {
  Column<float> a;
  a.resize(column_memory::kLargeBytes / sizeof(float) + 5, 0.5f);  // resize with a value fills
  EXPECT_EQ(a.front(), 0.5f);
  EXPECT_EQ(a.back(), 0.5f);
  Column<float> b = a;
  EXPECT_EQ(a, b);
  EXPECT_NE(a.data(), b.data());
  const float* data = b.data();
  Column<float> c = std::move(b);
  EXPECT_EQ(c.data(), data);  // a move keeps the block (the allocators compare equal)
  c.assign(3, 2.f);
  EXPECT_EQ(c, (Column<float>{2.f, 2.f, 2.f}));
}

TEST(Column, ResizeZerosNewValuesEvenInReusedCapacity) {
  // A shrink then a regrow reuses the capacity that still holds the old 7s: resize(n) must
  // hand back zeros, as std::vector does (it handed back the 7s before).
  Column<float> c(100, 7.f);
  c.resize(10);
  c.resize(100);
  for (std::size_t i = 10; i < 100; ++i) ASSERT_EQ(c[i], 0.f) << i;
  Column<Eigen::Vector3f> v(5, Eigen::Vector3f(1, 2, 3));
  v.resize(1);
  v.resize(5);
  EXPECT_EQ(v[4], Eigen::Vector3f::Zero());
}

TEST(Column, ResizeForOverwriteIsLocalToTheCall) {
  Column<std::uint32_t> c;
  resizeForOverwrite(c, 1000);
  ASSERT_EQ(c.size(), 1000u);
  for (std::uint32_t i = 0; i < 1000; ++i) c[i] = i + 1;  // a reader writes every value
  EXPECT_EQ(c[999], 1000u);
  EXPECT_FALSE(column_memory::overwrite_next_resize);  // the scope ended with the call
  c.resize(10);
  c.resize(1000);  // an ordinary resize afterwards zeros again
  for (std::size_t i = 10; i < 1000; ++i) ASSERT_EQ(c[i], 0u) << i;
}

TEST(Column, PointCloudColumnsUseIt) {
  PointCloud cloud;
  cloud.positions.resize(1'000'000);
  cloud.intensity.resize(2'000'000);  // 8 MB (1M floats, 4 MB, stay below 4 MiB: heap)
  cloud.colors.resize(2'000'000);
  EXPECT_TRUE(hugeAligned(cloud.positions.data()));
  EXPECT_TRUE(hugeAligned(cloud.intensity.data()));
  EXPECT_TRUE(hugeAligned(cloud.colors.data()));
}

}  // namespace
