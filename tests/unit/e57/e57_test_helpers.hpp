#pragma once
// Shared checks for test_e57.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "model/dataset.hpp"

namespace plumb::test {

inline bool hasField(const PointCloud& c, const std::string& name) {
  const auto f = c.fieldNames();
  return std::find(f.begin(), f.end(), name) != f.end();
}

/// Point count, bounds (scan frame, world coordinates) within `tol`, and fields present.
inline void expectScan(const Scan& s, std::size_t count, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                       const std::vector<std::string>& fields, double tol = 2e-6) {
  ASSERT_EQ(s.cloud.size(), count);
  s.cloud.validate(true);
  if (count > 0) {
    const Bounds b = s.cloud.bounds();
    for (int a = 0; a < 3; ++a) {
      EXPECT_NEAR(b.min[a], lo[a], tol) << "axis " << a;
      EXPECT_NEAR(b.max[a], hi[a], tol) << "axis " << a;
    }
  }
  std::vector<std::string> expected{"x", "y", "z"};
  expected.insert(expected.end(), fields.begin(), fields.end());
  std::vector<std::string> got = s.cloud.fieldNames();
  std::sort(expected.begin(), expected.end());
  std::sort(got.begin(), got.end());
  if (count > 0) {
    EXPECT_EQ(got, expected);
  }
}

}  // namespace plumb::test
