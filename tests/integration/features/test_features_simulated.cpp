// Feature extraction against the simulator's exact truth (issue 5 acceptance).
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "features/facades/opening_detection.hpp"
#include "features/mesh_edges/mesh_edges.hpp"
#include "features/planes/plane_extraction.hpp"
#include "features/segments/segment_detection.hpp"
#include "simulated_scans.hpp"
#include "simulation/presets.hpp"

namespace plumb {
namespace {

bool planeMatches(const PlanarPolygon& p, const TruthPlane& t) {
  const double c = p.normal.dot(t.normal);
  const double d = c > 0 ? p.offset : -p.offset;
  return std::abs(c) >= std::cos(M_PI / 180.0) && std::abs(d - t.offset) <= 0.02;
}

/// Truth wall faces larger than 2 m2 that the scan actually observed (>= 300 points within
/// 1 cm of the plane and inside the face's element bounds is approximated by the plane test).
std::vector<const TruthPlane*> observedWalls(const BuildingTruth& truth, const PointCloud& cloud) {
  std::vector<const TruthPlane*> out;
  for (const auto& t : truth.planes) {
    if (t.element_type != "IfcWall" || t.area <= 2.0 || (t.face != "interior" && t.face != "exterior")) continue;
    std::size_t n = 0;
    for (std::size_t i = 0; i < cloud.size(); i += 4)
      if (cloud.positions[i].allFinite() && std::abs(t.normal.dot(cloud.world(i)) - t.offset) < 0.01) ++n;
    if (n * 4 >= 2000) out.push_back(&t);
  }
  return out;
}

double wallRecall(const BuildingTruth& truth, const PointCloud& cloud, const std::vector<PlanarPolygon>& planes,
                  std::size_t& total) {
  const auto walls = observedWalls(truth, cloud);
  total = walls.size();
  std::size_t found = 0;
  for (const auto* t : walls) {
    bool ok = false;
    for (const auto& p : planes) ok = ok || planeMatches(p, *t);
    found += ok;
    if (!ok) std::cout << "  missed wall n=" << t->normal.transpose() << " d=" << t->offset << " area=" << t->area << "\n";
  }
  return walls.empty() ? 0.0 : double(found) / double(walls.size());
}

TEST(FeaturesSimulated, IndoorTlsWallPlanesMatchTruth) {
  for (const char* name : {"two-rooms", "house", "non-manhattan"}) {
    SCOPED_TRACE(name);
    const auto b = generateBuilding(buildingPreset(name));
    const PointCloud cloud = test::indoorTls(b, 0.5);
    const auto r = extractPlanes(cloud, {});
    std::size_t total = 0;
    const double recall = wallRecall(b.truth, cloud, r.planes, total);
    std::cout << name << ": " << cloud.size() << " points, " << r.planes.size() << " polygons in " << r.seconds
              << " s, wall recall " << recall << " of " << total << "\n";
    EXPECT_GE(total, 4u);
    EXPECT_GE(recall, 0.95);
  }
}

TEST(FeaturesSimulated, OutdoorMmsFacadesAndOpeningsMatchTruth) {
  // Opening recall is measured over both presets together (22 exterior openings).
  std::size_t all_truth = 0, all_found = 0;
  for (const char* name : {"two-rooms", "house"}) {
    SCOPED_TRACE(name);
    const auto b = generateBuilding(buildingPreset(name));
    const PointCloud cloud = test::outdoorMms(b);
    const auto planes = extractPlanes(cloud, {});
    std::size_t total = 0;
    const double recall = wallRecall(b.truth, cloud, planes.planes, total);
    std::cout << name << " MMS: " << cloud.size() << " points, detector " << detectorName(planes.detector_used)
              << ", " << planes.planes.size() << " polygons in " << planes.seconds << " s, wall recall " << recall
              << " of " << total << "\n";
    EXPECT_GE(recall, 0.95);
    const auto o = detectOpenings(cloud, planes.planes, {});
    EXPECT_TRUE(o.ray_tracing_ran);
    EXPECT_FALSE(o.interior_points.empty());
    // Recall of the exterior openings: 4 corners within 5 cm, in order.
    std::size_t truth_n = 0, found = 0;
    for (const auto& t : b.truth.openings) {
      if (t.face != "exterior") continue;
      ++truth_n;
      bool ok = false;
      for (const auto& d : o.openings) {
        double e = 0;
        for (int c = 0; c < 4; ++c) e = std::max(e, (d.corners[c] - t.corners[c]).norm());
        ok = ok || e <= 0.05;
      }
      found += ok;
      if (!ok) std::cout << "  missed opening " << t.element_type << " at " << t.corners[0].transpose() << "\n";
    }
    std::cout << name << " MMS openings: " << o.openings.size() << " detected, " << found << " / " << truth_n
              << " truth matched, " << o.interior_points.size() << " interior points\n";
    ASSERT_GT(truth_n, 0u);
    all_truth += truth_n;
    all_found += found;
  }
  EXPECT_GE(double(all_found), 0.9 * double(all_truth)) << all_found << " / " << all_truth;
}

TEST(FeaturesSimulated, IndoorOpeningsFromRaysLeavingThroughWindowsAndWallHoles) {
  // Interior faces of the ground-floor openings, seen by the indoor stations; recall over both
  // presets together (24 openings).
  std::size_t all_truth = 0, all_found = 0;
  for (const char* name : {"two-rooms", "house"}) {
    SCOPED_TRACE(name);
    const auto b = generateBuilding(buildingPreset(name));
    const PointCloud cloud = test::indoorTls(b, 0.25);
    const auto planes = extractPlanes(cloud, {});
    const auto o = detectOpenings(cloud, planes.planes, {});
    EXPECT_TRUE(o.ray_tracing_ran);
    std::size_t truth_n = 0, found = 0;
    for (const auto& t : b.truth.openings) {
      if (t.face != "interior" || t.storey != 0) continue;
      ++truth_n;
      double best = 1e9;
      for (const auto& d : o.openings) {
        double e = 0;
        for (int c = 0; c < 4; ++c) e = std::max(e, (d.corners[c] - t.corners[c]).norm());
        best = std::min(best, e);
      }
      found += best <= 0.05;
      if (best > 0.05) std::cout << "  missed " << t.element_type << " at " << t.corners[0].transpose() << " (" << best << " m)\n";
    }
    std::cout << name << " indoor openings: " << o.openings.size() << " detected, " << found << " / " << truth_n
              << " truth matched\n";
    all_truth += truth_n;
    all_found += found;
  }
  ASSERT_GT(all_truth, 0u);
  EXPECT_GE(double(all_found), 0.9 * double(all_truth)) << all_found << " / " << all_truth;
}

TEST(FeaturesSimulated, BimSharpEdgesAreExactlyTheTruthEdges) {
  for (const auto& name : buildingPresetNames()) {
    if (name == "big-office") continue;  // benchmark size
    SCOPED_TRACE(name);
    const auto b = generateBuilding(buildingPreset(name));
    const auto r = extractSharpEdges(test::meshWithoutGlass(b));
    EXPECT_EQ(r.segments.size(), b.truth.sharp_edges.size());
    std::size_t matched = 0;
    for (const auto& t : b.truth.sharp_edges) {
      bool ok = false;
      for (const auto& s : r.segments)
        ok = ok || ((s.a - t.a).norm() < 1e-9 && (s.b - t.b).norm() < 1e-9) ||
             ((s.a - t.b).norm() < 1e-9 && (s.b - t.a).norm() < 1e-9);
      matched += ok;
    }
    EXPECT_EQ(matched, b.truth.sharp_edges.size());
  }
}

/// Max distance of the segment's endpoints to the truth edge's LINE (position accuracy), when
/// both endpoints also lie within `extent_tol` of the truth segment (no long overshoot).
double lineDistanceIfOnEdge(const Segment3D& s, const Segment3D& t, double extent_tol) {
  if (std::max(test::pointSegmentDistance(s.a, t), test::pointSegmentDistance(s.b, t)) > extent_tol) return 1e9;
  const Eigen::Vector3d d = t.direction();
  auto perp = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d r = p - t.a;
    return (r - r.dot(d) * d).norm();
  };
  return std::max(perp(s.a), perp(s.b));
}

TEST(FeaturesSimulated, ScanSegmentsLieOnTruthEdges) {
  for (const char* name : {"two-rooms", "house"}) {
    SCOPED_TRACE(name);
    const auto b = generateBuilding(buildingPreset(name));
    const PointCloud cloud = test::indoorTls(b, 0.25);
    const auto r = detectSegments(cloud);
    // A segment is on a truth edge when it runs along it within 2 cm (perpendicular) and its
    // ends stay within 5 cm of the edge's ends; "strict" also requires every point of the
    // segment within 2 cm of the truth segment.
    std::size_t good = 0, strict = 0;
    std::vector<double> dist;
    for (const auto& s : r.segments) {
      double best = 1e9, best_strict = 1e9;
      for (const auto& t : b.truth.sharp_edges) {
        best = std::min(best, lineDistanceIfOnEdge(s, t, 0.05));
        best_strict = std::min(best_strict, std::max(test::pointSegmentDistance(s.a, t), test::pointSegmentDistance(s.b, t)));
      }
      dist.push_back(best);
      good += best <= 0.02;
      strict += best_strict <= 0.02;
    }
    std::sort(dist.begin(), dist.end());
    std::cout << name << ": " << cloud.size() << " points, " << r.segments.size() << " segments in " << r.seconds
              << " s, " << good << " along a truth edge within 2 cm (" << strict
              << " with ends within 2 cm too), median distance " << (dist.empty() ? -1 : dist[dist.size() / 2])
              << " m\n";
    ASSERT_GE(r.segments.size(), 12u);
    EXPECT_GE(double(good), 0.9 * double(r.segments.size()));
  }
}

}  // namespace
}  // namespace plumb
