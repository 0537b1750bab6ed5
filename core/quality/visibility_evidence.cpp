#include "quality/visibility_evidence.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>

#include "quality/station_range_images.hpp"
#include "quality/structure_evidence.hpp"
#include "common/stopwatch.hpp"

namespace plumb {

const ParamSchema<VisibilityParams>& VisibilityParams::schema() {
  using P = VisibilityParams;
  static const auto s =
      ParamSchema<P>("visibility")
          .boolean(&P::enabled, "enabled", "Free-space check",
                   "Test the result against the space each scanner saw through")
          .real(&P::bin_deg, "bin", "Range image bin", "deg", 0.05, 5.0,
                "Angular bin of the per-station range images", true)
          .real(&P::min_margin, "margin", "Free-space margin", "m", 0.01, 2.0,
                "A point must lie this far in front of a measured surface to count as seen "
                "through")
          .real(&P::range_margin, "range-margin", "Range margin", "", 0.0, 0.2,
                "Margin growth per metre of range", true)
          .real(&P::station_cell, "station-cell", "Station cell", "m", 0.01, 20.0,
                "Sensor origins closer than this share a pseudo-station (MMS trajectories)", true)
          .integer(&P::max_stations, "max-stations", "Max stations", "", 1, 4096,
                   "Most pseudo-stations per dataset", true)
          .integer(&P::max_map_points, "max-map-points", "Max map points", "", 1000, 1e8,
                   "Points used to build the range images (bounds memory)", true)
          .integer(&P::max_test_points, "max-test-points", "Max tested points", "", 100, 1e7,
                   "Points tested against the other side's free space", true)
          .real(&P::min_sensor_distance, "min-sensor-distance", "Min sensor distance", "m", 0.0,
                5.0, "Returns closer to their sensor are not used", true)
          .real(&P::min_cos_incidence, "min-cos-incidence", "Min incidence cosine", "", 0.01, 1.0,
                "Scan to model: the margin along a ray grows as 1/cos(incidence) down to this",
                true)
          .boolean(&P::structural_only, "structural-only", "Structural elements only",
                   "Scan to model: only walls, slabs, roofs, columns, beams and stairs stop a "
                   "ray (not windows, doors, furniture)",
                   true)
          .integer(&P::min_visible, "min-visible", "Min visible points", "", 1, 1e6,
                   "Fewer visible points: the evidence is inconclusive", true)
          .real(&P::fail_ratio, "fail-ratio", "Fail contradiction ratio", "", 0.0, 1.0,
                "Above this fraction of visible points in seen-through space the registration "
                "fails as contradicted")
          .real(&P::warn_ratio, "warn-ratio", "Warn contradiction ratio", "", 0.0, 1.0,
                "Above this fraction the result is flagged for a visual check")
          .real(&P::structure_min_area, "structure-min-area", "Structure plane area", "m2", 0.1,
                1000.0, "Planes at least this large are judged one by one (walls, floors)", true)
          .integer(&P::structure_min_points, "structure-min-points", "Structure plane points", "",
                   1, 1e6, "A plane is judged with at least this many sighted points", true)
          .real(&P::structure_plane_fraction, "structure-plane-fraction",
                "Unexplained plane fraction", "", 0.0, 1.0,
                "A plane with more of its sighted points unexplained is unexplained", true)
          .real(&P::structure_min_judged_area, "structure-min-judged", "Min judged structure",
                "m2", 0.0, 1e6, "Less judged plane area: the structure figure is inconclusive",
                true)
          .real(&P::structure_fail_ratio, "structure-fail", "Fail unexplained structure", "", 0.0,
                1.0, "Above this share of the judged large-plane area unexplained the "
                "registration fails as contradicted")
          .real(&P::structure_warn_ratio, "structure-warn", "Warn unexplained structure", "", 0.0,
                1.0, "Above this share the result is flagged for a visual check");
  return s;
}

namespace {

/// Regular sample of the tested points, without those next to their own sensor.
std::vector<std::size_t> testedPoints(const PointCloud& c, const std::optional<Eigen::Vector3d>& vp,
                                      const VisibilityParams& p) {
  auto idx = regularSample(c.size(), static_cast<std::size_t>(p.max_test_points));
  const bool origins = c.hasSensorOrigins();
  if (!origins && !vp) return idx;
  std::erase_if(idx, [&](std::size_t i) {
    const Eigen::Vector3d o =
        origins ? Eigen::Vector3d(c.offset + c.sensor_origins[i].cast<double>()) : *vp;
    return (c.world(i) - o).norm() < p.min_sensor_distance;
  });
  return idx;
}

}  // namespace

void tallySightings(const std::vector<Sighting>& s, VisibilityEvidence& e) {
  e.tested = s.size();
  for (Sighting v : s) {
    if (v == Sighting::Consistent) ++e.consistent;
    if (v == Sighting::Contradicting) ++e.contradicting;
  }
  e.visible = e.consistent + e.contradicting;
  if (e.visible > 0) {
    e.contradiction_ratio = static_cast<double>(e.contradicting) / static_cast<double>(e.visible);
    e.agreement_ratio = static_cast<double>(e.consistent) / static_cast<double>(e.visible);
  }
  if (e.tested > 0)
    e.expected_overlap = static_cast<double>(e.visible) / static_cast<double>(e.tested);
}

VisibilityEvidence freeSpaceEvidence(const StationRangeImages& images, const PointCloud& tested,
                                     const std::optional<Eigen::Vector3d>& tested_viewpoint,
                                     const RigidTransform& to_observer, const VisibilityParams& p,
                                     TestedSightings* detail) {
  const auto t0 = std::chrono::steady_clock::now();
  VisibilityEvidence e;
  if (!images.available()) {
    e.missing_reason = "no sensor origins (no station poses, trajectory or viewpoint)";
    return e;
  }
  e.available = true;
  e.stations = images.stations();
  const auto idx = testedPoints(tested, tested_viewpoint, p);
  std::vector<Sighting> sightings(idx.size(), Sighting::NoEvidence);
  // Each point's sighting is independent and written to its own slot: thread-count invariant.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, idx.size(), 512),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k < r.end(); ++k)
                        sightings[k] = images.classify(to_observer.apply(tested.world(idx[k])));
                    });
  tallySightings(sightings, e);
  if (detail) *detail = TestedSightings{idx, std::move(sightings), false};
  e.seconds = secondsSince(t0);
  return e;
}

VisibilityEvidence freeSpaceEvidence(const PointCloud& observer,
                                     const std::optional<Eigen::Vector3d>& viewpoint,
                                     const PointCloud& tested,
                                     const std::optional<Eigen::Vector3d>& tested_viewpoint,
                                     const RigidTransform& to_observer,
                                     const VisibilityParams& p, TestedSightings* detail) {
  const auto t0 = std::chrono::steady_clock::now();
  VisibilityEvidence e;
  if (!observer.hasSensorOrigins() && !viewpoint) {
    e.missing_reason = "no sensor origins (no station poses, trajectory or viewpoint)";
    return e;
  }
  if (tested.empty() || observer.empty()) {
    e.missing_reason = "no points";
    return e;
  }
  const StationRangeImages images(observer, viewpoint, p);
  e = freeSpaceEvidence(images, tested, tested_viewpoint, to_observer, p, detail);
  e.seconds = secondsSince(t0);
  return e;
}

void summarizeVisibility(VisibilitySummary& s, const VisibilityParams& p) {
  s.contradiction_ratio = -1.0;
  for (const VisibilityEvidence* e : {&s.source_in_target, &s.target_in_source})
    if (e->conclusive(p))
      s.contradiction_ratio = std::max(s.contradiction_ratio, e->contradiction_ratio);
  s.expected_overlap = s.source_in_target.available ? s.source_in_target.expected_overlap : -1.0;
  s.unexplained_structure = -1.0;
  for (const VisibilityEvidence* e : {&s.source_in_target, &s.target_in_source})
    if (e->conclusive(p) && e->structure.conclusive(p))
      s.unexplained_structure =
          std::max(s.unexplained_structure, e->structure.unexplained_area_ratio);
}

}  // namespace plumb
