// Column<T> (core/model/column.hpp): a std::vector whose large blocks are 2 MiB-aligned
// mappings; values survive growth across the small/large boundary, copies and moves, and
// resize(n, value) still fills.
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
