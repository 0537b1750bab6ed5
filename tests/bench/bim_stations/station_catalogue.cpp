#include "station_catalogue.hpp"

#include <algorithm>
#include <cstdio>
#include <functional>
#include <random>

#include "room_stations.hpp"
#include "simulation/scan_scene.hpp"
#include "stair_zones.hpp"

namespace plumb::bimst {

namespace {

StationType classify(const Footprint& f, bool stair, const CatalogueParams& p) {
  if (stair) return StationType::Stair;
  if (f.area_m2 > p.hall_min_area || f.open_rays >= p.hall_min_open_rays) return StationType::Hall;
  if (f.elongation > p.corridor_min_elongation && f.short_side_m < p.corridor_max_width)
    return StationType::Corridor;
  if (f.area_m2 < p.room_max_area) return StationType::Room;
  return StationType::Other;
}

/// Every enclosed candidate of the grid, classified; `tested` counts the grid points.
std::vector<CatalogueStation> enclosedCandidates(const BimModel& model, const std::string& name,
                                                 const CatalogueParams& p, int& tested) {
  ScanSceneOptions opt;
  opt.ground = false;
  const ScanScene scene(model, {}, opt);
  const RayCaster& caster = scene.caster();
  const Bounds b = model.mesh.bounds();
  const auto dirs = verdict::sphereDirections(p.sphere_rays);
  const auto stairs = stairBounds(model);
  std::vector<CatalogueStation> out;
  tested = 0;
  for (double x = b.min.x() + 0.5 * p.grid_step; x < b.max.x(); x += p.grid_step)
    for (double y = b.min.y() + 0.5 * p.grid_step; y < b.max.y(); y += p.grid_step)
      for (const auto& pos : verdict::floorsBelow(caster, x, y, b.max.z() + 1.0, p.height)) {
        ++tested;
        const double c = verdict::clearance(caster, pos, dirs);
        if (c < p.min_clearance) continue;
        CatalogueStation s{name, StationType::Other, pos, measureFootprint(caster, pos, p.height, p.footprint), c};
        s.type = classify(s.footprint, nearStair(stairs, pos, p.height, p.stair_reach, p.stair_floor_margin), p);
        out.push_back(s);
      }
  return out;
}

/// Up to per_type of `all` of type t, drawn in a seeded random order, min_separation apart.
std::vector<CatalogueStation> draw(const std::vector<CatalogueStation>& all, StationType t,
                                   const CatalogueParams& p) {
  std::vector<CatalogueStation> of;
  for (const auto& s : all)
    if (s.type == t) of.push_back(s);
  std::mt19937_64 rng(p.seed ^ std::hash<std::string>{}(all.empty() ? "" : all[0].model) ^ (std::uint64_t(t) << 32));
  std::shuffle(of.begin(), of.end(), rng);
  std::vector<CatalogueStation> out;
  for (const auto& s : of) {
    if (int(out.size()) >= p.per_type) break;
    const bool apart = std::all_of(out.begin(), out.end(), [&](const CatalogueStation& q) {
      return (q.position - s.position).norm() >= p.min_separation;
    });
    if (apart) out.push_back(s);
  }
  return out;
}

}  // namespace

CatalogueResult buildCatalogue(const BimModel& model, const std::string& name, const CatalogueParams& p) {
  CatalogueResult r;
  r.model = name;
  r.stair_elements = int(stairBounds(model).size());
  r.enclosed = enclosedCandidates(model, name, p, r.candidates);
  for (StationType t : benchTypes())
    for (auto& s : draw(r.enclosed, t, p)) r.chosen.push_back(s);
  return r;
}

namespace {

void printStation(const CatalogueStation& s) {
  std::printf("  [catalogue] %-28s %-8s (%7.2f, %7.2f, %6.2f)  area %6.1f m2  elongation %5.2f  "
              "width %5.2f m  open rays %3d  clearance %.2f m\n",
              s.model.c_str(), typeName(s.type), s.position.x(), s.position.y(), s.position.z(),
              s.footprint.area_m2, s.footprint.elongation, s.footprint.short_side_m, s.footprint.open_rays,
              s.clearance);
}

}  // namespace

void printCatalogue(const CatalogueResult& c, bool all) {
  int count[5] = {0, 0, 0, 0, 0};
  for (const auto& s : c.enclosed) ++count[int(s.type)];
  std::printf("  [catalogue] %s: %d grid points, %zu enclosed (room %d, corridor %d, hall %d, stair %d, "
              "other %d), %d stair elements\n",
              c.model.c_str(), c.candidates, c.enclosed.size(), count[0], count[1], count[2], count[3],
              count[4], c.stair_elements);
  for (const auto& s : all ? c.enclosed : c.chosen) printStation(s);
  std::fflush(stdout);
}

}  // namespace plumb::bimst
