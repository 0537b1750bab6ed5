// Opening extents against the simulator's exact truth rectangles, on the house preset: the
// indoor TLS stations (one per ground-floor room, 0.5 deg, 3 mm, as the registration
// acceptance scans them) and the outdoor MMS loop (house and two-rooms). Every detected opening that matches a truth
// opening (same wall face, overlapping) must have its 4 corners within 5 cm of the truth, doors
// included (their top edge and their bottom at the floor); recall is reported and bounded.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "features/facades/opening_detection.hpp"
#include "features/planes/plane_extraction.hpp"
#include "simulated_scans.hpp"
#include "simulation/presets.hpp"

namespace plumb {
namespace {

constexpr double kTolerance = 0.05;  // m, per corner

struct Match {
  const Opening* detected = nullptr;
  double error = 1e9;  ///< max corner distance, m
};

/// The detected opening on the same face as t (centre within 25 cm of t's rectangle, normal
/// parallel) with the smallest max corner error.
Match bestMatch(const TruthOpening& t, const std::vector<Opening>& found) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& k : t.corners) c += 0.25 * k;
  const double half_w = 0.5 * (t.corners[1] - t.corners[0]).norm();
  const double half_h = 0.5 * (t.corners[3] - t.corners[0]).norm();
  const Eigen::Vector3d along = (t.corners[1] - t.corners[0]).normalized();
  Match m;
  for (const auto& d : found) {
    Eigen::Vector3d dc = Eigen::Vector3d::Zero();
    for (const auto& k : d.corners) dc += 0.25 * k;
    const Eigen::Vector3d r = dc - c;
    if (std::abs(r.dot(t.face_normal)) > 0.1 || std::abs(r.dot(along)) > half_w ||
        std::abs(r.z()) > half_h)
      continue;
    double e = 0;
    for (int k = 0; k < 4; ++k) e = std::max(e, (d.corners[k] - t.corners[k]).norm());
    if (e < m.error) m = {&d, e};
  }
  return m;
}

struct Tally {
  std::size_t truth = 0, detected = 0, within = 0;
  double worst = 0;
};

Tally check(const char* label, const BuildingTruth& truth, const std::vector<Opening>& found,
            const char* face, int storey) {
  Tally tally;
  for (const auto& t : truth.openings) {
    if (t.face != face || (storey >= 0 && t.storey != storey)) continue;
    ++tally.truth;
    const Match m = bestMatch(t, found);
    if (!m.detected) {
      std::printf("  %s: missed %s at (%.2f %.2f %.2f)\n", label, t.element_type.c_str(),
                  t.corners[0].x(), t.corners[0].y(), t.corners[0].z());
      continue;
    }
    ++tally.detected;
    tally.within += m.error <= kTolerance;
    tally.worst = std::max(tally.worst, m.error);
    std::printf("  %s: %-9s bottom z %.3f (truth %.3f) top z %.3f (truth %.3f) max corner error %.3f m\n",
                label, t.element_type.c_str(), m.detected->corners[0].z(), t.corners[0].z(),
                m.detected->corners[2].z(), t.corners[2].z(), m.error);
    EXPECT_LE(m.error, kTolerance) << label << " " << t.element_type << " at "
                                   << t.corners[0].transpose();
  }
  std::printf("%s: %zu truth openings, %zu detected (recall %.2f), %zu within %.0f cm, worst %.3f m\n",
              label, tally.truth, tally.detected,
              tally.truth ? double(tally.detected) / double(tally.truth) : 0.0, tally.within,
              kTolerance * 100, tally.worst);
  return tally;
}

TEST(OpeningsTruth, HouseIndoorTlsOpeningsHaveTheirTrueExtent) {
  const auto b = generateBuilding(buildingPreset("house"));
  PointCloud cloud = test::indoorTls(b, 0.5, 3.0);
  cloud.removeNonFinite();
  const auto planes = extractPlanes(cloud, {});
  const auto o = detectOpenings(cloud, planes.planes, {});
  ASSERT_TRUE(o.ray_tracing_ran);
  const Tally t = check("house indoor TLS", b.truth, o.openings, "interior", 0);
  ASSERT_GT(t.truth, 0u);
  EXPECT_GE(double(t.detected), 0.9 * double(t.truth));
  // The entrance door seen from the hall: full height, bottom at the floor.
  std::size_t doors = 0;
  for (const auto& tr : b.truth.openings)
    if (tr.element_type == "IfcDoor" && tr.face == "interior" && tr.storey == 0) {
      const Match m = bestMatch(tr, o.openings);
      doors += m.detected != nullptr && m.error <= kTolerance;
    }
  EXPECT_GE(doors, 1u);
}

TEST(OpeningsTruth, OutdoorMmsOpeningsHaveTheirTrueExtent) {
  // The house, and two-rooms (its door: the wall's inner face, seen through the opposite
  // façade's windows, once passed for the lintel).
  for (const char* name : {"house", "two-rooms"}) {
    SCOPED_TRACE(name);
    const auto b = generateBuilding(buildingPreset(name));
    PointCloud cloud = test::outdoorMms(b);
    cloud.removeNonFinite();
    const auto planes = extractPlanes(cloud, {});
    const auto o = detectOpenings(cloud, planes.planes, {});
    ASSERT_TRUE(o.ray_tracing_ran);
    const std::string label = std::string(name) + " outdoor MMS";
    const Tally t = check(label.c_str(), b.truth, o.openings, "exterior", -1);
    ASSERT_GT(t.truth, 0u);
    EXPECT_GE(double(t.detected), 0.9 * double(t.truth));
  }
}

}  // namespace
}  // namespace plumb
