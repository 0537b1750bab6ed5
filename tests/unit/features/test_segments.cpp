#include <gtest/gtest.h>

#include "features/segments/segment_detection.hpp"
#include "synthetic_scenes.hpp"

namespace plumb {
namespace {

double pointSegmentDistance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double t = std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return (a + t * d - p).norm();
}

/// The 12 room edges and the 4 window edges (world).
std::vector<Segment3D> truthEdges(const test::RoomSpec& s, const Eigen::Vector3d& off) {
  std::vector<Segment3D> e;
  for (int axis = 0; axis < 3; ++axis)
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j) {
        const int b = (axis + 1) % 3, c = (axis + 2) % 3;
        Segment3D seg;
        seg.a[axis] = s.min[axis];
        seg.b[axis] = s.max[axis];
        seg.a[b] = seg.b[b] = i ? s.max[b] : s.min[b];
        seg.a[c] = seg.b[c] = j ? s.max[c] : s.min[c];
        seg.a += off;
        seg.b += off;
        e.push_back(seg);
      }
  const auto& w = test::kWindow;
  const double x = s.max.x();
  const Eigen::Vector3d c[4] = {{x, w[0], w[2]}, {x, w[1], w[2]}, {x, w[1], w[3]}, {x, w[0], w[3]}};
  for (int k = 0; k < 4; ++k) e.push_back({c[k] + off, c[(k + 1) % 4] + off, 0});
  return e;
}

double distanceToTruth(const Segment3D& s, const std::vector<Segment3D>& truth) {
  double best = 1e9;
  for (const auto& t : truth)
    best = std::min(best, std::max(pointSegmentDistance(s.a, t.a, t.b), pointSegmentDistance(s.b, t.a, t.b)));
  return best;
}

TEST(Segments, RoomEdgesAreFoundWithinTwoCentimetres) {
  test::RoomSpec spec;
  spec.outside = false;
  const PointCloud cloud = test::makeRoom(spec);
  const auto r = detectSegments(cloud);
  ASSERT_GE(r.patches.size(), 6u);
  const auto truth = truthEdges(spec, Eigen::Vector3d::Zero());
  // Every room edge is covered (over 80% of its length) by a detected segment within 2 cm.
  for (std::size_t t = 0; t < 12; ++t) {
    double covered = 0;
    for (const auto& s : r.segments)
      if (std::max(pointSegmentDistance(s.a, truth[t].a, truth[t].b), pointSegmentDistance(s.b, truth[t].a, truth[t].b)) < 0.02)
        covered = std::max(covered, s.length());
    EXPECT_GT(covered, 0.8 * truth[t].length()) << "edge " << t;
  }
  // And every detected segment lies on a truth edge: room edges (plane intersections) within
  // 2 cm; window edges (no reveal here, so bounded by the last wall sample) within one
  // sample spacing.
  const std::vector<Segment3D> room(truth.begin(), truth.begin() + 12), window(truth.begin() + 12, truth.end());
  std::size_t good = 0;
  for (const auto& s : r.segments)
    good += distanceToTruth(s, room) < 0.02 || distanceToTruth(s, window) < spec.spacing;
  EXPECT_EQ(good, r.segments.size()) << good << " / " << r.segments.size();
}

TEST(Segments, Deterministic) {
  test::RoomSpec spec;
  spec.outside = false;
  spec.spacing = 0.05;
  const PointCloud cloud = test::makeRoom(spec);
  const auto a = detectSegments(cloud), b = detectSegments(cloud);
  ASSERT_EQ(a.segments.size(), b.segments.size());
  for (std::size_t k = 0; k < a.segments.size(); ++k) {
    EXPECT_EQ(a.segments[k].a, b.segments[k].a);
    EXPECT_EQ(a.segments[k].b, b.segments[k].b);
  }
}

}  // namespace
}  // namespace plumb
