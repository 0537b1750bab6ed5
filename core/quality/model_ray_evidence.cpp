// Scan to model free-space test (VisibilityEvidence, modelRayEvidence): rays from the scan's
// sensors to its points, in the model frame, against the model's structural surfaces with the
// shared RayCaster (Embree when available).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <set>

#include "quality/station_range_images.hpp"
#include "quality/structure_evidence.hpp"
#include "quality/visibility_evidence.hpp"
#include "simulation/ray_caster.hpp"
#include "common/stopwatch.hpp"

namespace plumb {

namespace {

bool startsWith(const std::string& s, const char* prefix) {
  return s.rfind(prefix, 0) == 0;
}

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// Elements the laser cannot pass through and that are built as modelled. Windows, doors,
/// openings, curtain walls, railings, furniture, coverings and proxies are left out: glass is
/// seen through, doors stand open, furniture moves, and a missing one is no contradiction.
bool isStructural(const BimElement& e) {
  static constexpr std::array<const char*, 8> kTypes = {
      "IfcWall", "IfcSlab", "IfcRoof", "IfcColumn", "IfcBeam", "IfcStair", "IfcRamp",
      "IfcChimney"};
  const bool type = std::any_of(kTypes.begin(), kTypes.end(),
                                [&e](const char* t) { return startsWith(e.type, t); });
  const std::string name = lower(e.name);
  const bool glass = name.find("glass") != std::string::npos ||
                     name.find("glazing") != std::string::npos ||
                     name.find("window") != std::string::npos;
  return type && !glass;
}

/// Triangles that do not stop a ray: non-structural ones when the model names element types
/// (and params.structural_only), none otherwise (an OBJ mesh: every surface counts).
std::vector<bool> seeThroughTriangles(const BimModel& m, const VisibilityParams& p) {
  const bool typed = std::any_of(m.elements.begin(), m.elements.end(),
                                 [](const BimElement& e) { return !e.type.empty(); });
  if (!p.structural_only || !typed || m.triangle_element.size() != m.mesh.triangleCount())
    return {};
  std::vector<bool> structural(m.elements.size());
  for (std::size_t i = 0; i < m.elements.size(); ++i) structural[i] = isStructural(m.elements[i]);
  std::vector<bool> skip(m.mesh.triangleCount());
  for (std::size_t t = 0; t < skip.size(); ++t) {
    const auto e = m.triangle_element[t];
    skip[t] = e >= structural.size() || !structural[e];
  }
  return skip;
}

struct ScanRays {
  std::vector<Ray> rays;
  std::vector<double> ranges;  ///< sensor to measured point, m
  std::vector<std::size_t> index;  ///< the scan point of each ray
  std::size_t origins = 0;     ///< distinct sensor origins among the rays
};

/// Rays of a regular sample of the scan's points, moved into the model frame.
ScanRays sampleRays(const PointCloud& scan, const std::optional<Eigen::Vector3d>& viewpoint,
                    const RigidTransform& to_model, const VisibilityParams& p) {
  ScanRays out;
  const bool origins = scan.hasSensorOrigins();
  std::set<std::array<float, 3>> distinct;
  for (std::size_t i : regularSample(scan.size(), static_cast<std::size_t>(p.max_test_points))) {
    if (origins) {
      const Eigen::Vector3f& o = scan.sensor_origins[i];
      distinct.insert({o.x(), o.y(), o.z()});
    }
    const Eigen::Vector3d sensor =
        origins ? Eigen::Vector3d(scan.offset + scan.sensor_origins[i].cast<double>()) : *viewpoint;
    const Eigen::Vector3d o = to_model.apply(sensor);
    const Eigen::Vector3d d = to_model.apply(scan.world(i)) - o;
    const double r = d.norm();
    if (!(r >= p.min_sensor_distance) || !std::isfinite(r)) continue;
    out.rays.push_back({o, d / r});
    out.ranges.push_back(r);
    out.index.push_back(i);
  }
  out.origins = origins ? distinct.size() : 1;
  return out;
}

/// One ray against its first structural hit. The margin along the ray is the free-space
/// margin over the cosine of the incidence angle: a wall met at a grazing angle lies within a
/// few centimetres of the ray over a long stretch, so a small misalignment moves the crossing
/// far along it.
Sighting classifyRay(const Ray& ray, double range, const RayHit& hit, const RayCaster& caster,
                     const VisibilityParams& p) {
  if (!hit.hit()) return Sighting::NoEvidence;  // outside the model, or through an opening
  const double cosine = std::abs(ray.direction.dot(caster.triangleNormal(hit.triangle)));
  const double margin =
      (p.min_margin + p.range_margin * range) / std::max(cosine, p.min_cos_incidence);
  if (hit.distance < range - margin) return Sighting::Contradicting;
  if (hit.distance <= range + margin) return Sighting::Consistent;
  return Sighting::Occluded;  // measured in front of the model surface: clutter, furniture
}

/// For the structure figure: a point in front of every structural surface (Occluded) is
/// still explained when some model surface lies at it, within twice the margin along its ray
/// (a ceiling covering below the slab, a door, a window, furniture); otherwise the model is
/// empty where the scan measured a surface, and the point stays Occluded (unexplained).
std::vector<Sighting> explainedByAnySurface(const ScanRays& rays, std::vector<Sighting> s,
                                            const BimModel& model, const VisibilityParams& p) {
  const RayCaster any(model.mesh);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, s.size(), 512),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k < r.end(); ++k) {
                        if (s[k] != Sighting::Occluded) continue;
                        const Ray& ray = rays.rays[k];
                        const double w = 2.0 * (p.min_margin + p.range_margin * rays.ranges[k]);
                        const Ray near{ray.origin + (rays.ranges[k] - w) * ray.direction,
                                       ray.direction};
                        if (any.cast(near, 2.0 * w).hit()) s[k] = Sighting::Consistent;
                      }
                    });
  return s;
}

}  // namespace

VisibilityEvidence modelRayEvidence(const PointCloud& scan,
                                    const std::optional<Eigen::Vector3d>& viewpoint,
                                    const BimModel& model, const RigidTransform& to_model,
                                    const VisibilityParams& p, TestedSightings* detail) {
  const auto t0 = std::chrono::steady_clock::now();
  VisibilityEvidence e;
  e.what = "scan rays crossing model surfaces";
  if (!scan.hasSensorOrigins() && !viewpoint) {
    e.missing_reason = "the scan has no sensor origins (no station poses, trajectory or viewpoint)";
    return e;
  }
  if (scan.empty() || model.mesh.triangles.empty()) {
    e.missing_reason = "no points or no model triangles";
    return e;
  }
  const auto see_through = seeThroughTriangles(model, p);
  const RayCaster caster(model.mesh, see_through);
  const ScanRays rays = sampleRays(scan, viewpoint, to_model, p);
  std::vector<RayHit> hits;
  caster.castAll(rays.rays, hits, 1e30, p.min_sensor_distance);
  e.available = true;
  e.stations = rays.origins;
  std::vector<Sighting> sightings(rays.rays.size());
  for (std::size_t k = 0; k < sightings.size(); ++k)
    sightings[k] = classifyRay(rays.rays[k], rays.ranges[k], hits[k], caster, p);
  tallySightings(sightings, e);
  if (detail)
    *detail = TestedSightings{
        rays.index,
        see_through.empty() ? std::move(sightings)
                            : explainedByAnySurface(rays, std::move(sightings), model, p),
        true};
  e.seconds = secondsSince(t0);
  return e;
}

}  // namespace plumb
