#include "simulation/building_layout.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace plumb::sim {

std::vector<double> planLines(const std::vector<double>& sizes) {
  std::vector<double> lines{0.0};
  for (double s : sizes) lines.push_back(lines.back() + s);
  return lines;
}

Eigen::Vector3d BuildingLayout::planeNormal(int axis) const {
  // Gradients of u = x - y cot(a) and v = y / sin(a); z is z.
  if (axis == 0) return Eigen::Vector3d(sin_a, -cos_a, 0.0);
  if (axis == 1) return Eigen::Vector3d::UnitY();
  return Eigen::Vector3d::UnitZ();
}

double BuildingLayout::planeScale(int axis) const { return axis == 2 ? 1.0 : sin_a; }

namespace {

Box makeBox(double u0, double u1, double v0, double v1, double z0, double z1) {
  Box b;
  b.lo = {u0, v0, z0};
  b.hi = {u1, v1, z1};
  return b;
}

struct Planner {
  const BuildingSpec& s;
  std::vector<double> U, V;
  double half_ext, half_int;
  long C, R;

  explicit Planner(const BuildingSpec& spec, double sin_a)
      : s(spec), U(planLines(spec.column_widths)), V(planLines(spec.row_depths)),
        half_ext(spec.exterior_wall_thickness / (2 * sin_a)),
        half_int(spec.interior_wall_thickness / (2 * sin_a)),
        C(static_cast<long>(spec.columns())), R(static_cast<long>(spec.rows())) {}

  // Half thickness of the wall on u-line i in row r (0 when there is none).
  double halfU(long i, long r) const {
    if (r < 0 || r >= R) return 0.0;
    const bool a = s.isRoom(i - 1, r), b = s.isRoom(i, r);
    return a && b ? half_int : (a != b ? half_ext : 0.0);
  }
  double halfV(long j, long c) const {
    if (c < 0 || c >= C) return 0.0;
    const bool a = s.isRoom(c, j - 1), b = s.isRoom(c, j);
    return a && b ? half_int : (a != b ? half_ext : 0.0);
  }
  // Largest half thickness of the walls crossing the node (u-line i, v-line j).
  double nodeHalfV(long i, long j) const { return std::max(halfV(j, i - 1), halfV(j, i)); }
  double nodeHalfU(long i, long j) const { return std::max(halfU(i, j - 1), halfU(i, j)); }

  // Axis-generic views: axis 0 = u-lines (walls along v), axis 1 = v-lines (walls along u).
  const std::vector<double>& lines(int axis) const { return axis == 0 ? U : V; }
  long cells(int axis) const { return axis == 0 ? C : R; }  ///< cells between the lines of axis
  bool room(int axis, long across, long along) const {
    return axis == 0 ? s.isRoom(across, along) : s.isRoom(along, across);
  }
  double half(int axis, long line, long cell) const { return axis == 0 ? halfU(line, cell) : halfV(line, cell); }
  // Half thickness of the walls crossing `line` of axis at node `node` of the other axis.
  double nodeHalfAlong(int axis, long line, long node) const {
    return axis == 0 ? nodeHalfV(line, node) : nodeHalfU(node, line);
  }
};

// Centres of n equal slots of [a, b] that can each hold `width` plus margins.
std::vector<double> slotCentres(double a, double b, double width, double spacing) {
  const double length = b - a;
  int n = std::max(1, static_cast<int>(std::floor(length / spacing)));
  while (n > 0 && length / n < width + 0.3) --n;
  std::vector<double> centres;
  for (int k = 0; k < n; ++k) centres.push_back(a + (k + 0.5) * length / n);
  return centres;
}

void addOpening(BuildingLayout& L, const LayoutWall& w, int wall_index, double a0, double a1,
                double z0, double z1, bool door, int storey, int number) {
  LayoutOpening o;
  o.door = door;
  o.wall = wall_index;
  o.storey = storey;
  o.name = std::string(door ? "door-" : "window-") + std::to_string(storey) + "-" + std::to_string(number);
  const int along = 1 - w.axis;
  o.box.lo[w.axis] = w.line - w.half;
  o.box.hi[w.axis] = w.line + w.half;
  o.box.lo[along] = a0;
  o.box.hi[along] = a1;
  o.box.lo.z() = z0;
  o.box.hi.z() = z1;
  L.openings.push_back(o);
}

std::vector<Eigen::Vector2d> footprint(const Planner& p) {
  // Directed boundary edges of the room cells (counter-clockwise around each cell).
  std::map<std::pair<long, long>, std::pair<long, long>> next;
  for (long r = 0; r < p.R; ++r)
    for (long c = 0; c < p.C; ++c) {
      if (!p.s.isRoom(c, r)) continue;
      if (!p.s.isRoom(c, r - 1)) next[{c, r}] = {c + 1, r};
      if (!p.s.isRoom(c + 1, r)) next[{c + 1, r}] = {c + 1, r + 1};
      if (!p.s.isRoom(c, r + 1)) next[{c + 1, r + 1}] = {c, r + 1};
      if (!p.s.isRoom(c - 1, r)) next[{c, r + 1}] = {c, r};
    }
  // Outer ring: start at the lowest-then-leftmost node (a convex corner of the outer ring).
  std::pair<long, long> start{1L << 30, 1L << 30};
  for (const auto& [a, b] : next)
    if (a.second < start.second || (a.second == start.second && a.first < start.first)) start = a;
  std::vector<std::pair<long, long>> ring{start};
  for (auto cur = next.at(start); cur != start; cur = next.at(cur)) ring.push_back(cur);
  // Keep corners only, then offset each corner outwards by the exterior half thickness.
  std::vector<Eigen::Vector2d> out;
  const std::size_t n = ring.size();
  for (std::size_t k = 0; k < n; ++k) {
    const auto& a = ring[(k + n - 1) % n];
    const auto& b = ring[k];
    const auto& c = ring[(k + 1) % n];
    const Eigen::Vector2d d1(b.first - a.first, b.second - a.second);
    const Eigen::Vector2d d2(c.first - b.first, c.second - b.second);
    if (d1.x() * d2.y() - d1.y() * d2.x() == 0) continue;  // collinear
    // Outward normal of a counter-clockwise edge direction d is (d.y, -d.x).
    const Eigen::Vector2d n1 = Eigen::Vector2d(d1.y(), -d1.x()).normalized();
    const Eigen::Vector2d n2 = Eigen::Vector2d(d2.y(), -d2.x()).normalized();
    out.push_back(Eigen::Vector2d(p.U[static_cast<std::size_t>(b.first)], p.V[static_cast<std::size_t>(b.second)]) +
                  p.half_ext * (n1 + n2));
  }
  return out;
}

/// The wall of storey `st` on line `i` of `axis` in cell `r` of the other axis (half thickness
/// `h` > 0), between z0 and z1; it reaches into the walls crossing its end nodes.
LayoutWall makeWall(const Planner& p, int axis, long i, long r, double h, int st, double z0, double z1) {
  const auto& cross = p.lines(1 - axis);
  LayoutWall w;
  w.axis = axis;
  w.line = p.lines(axis)[static_cast<std::size_t>(i)];
  w.half = h;
  w.storey = st;
  const bool before = p.room(axis, i - 1, r), after = p.room(axis, i, r);
  w.outside_sign = before && after ? 0 : (before ? +1 : -1);
  const double a0 = cross[static_cast<std::size_t>(r)] - p.nodeHalfAlong(axis, i, r);
  const double a1 = cross[static_cast<std::size_t>(r + 1)] + p.nodeHalfAlong(axis, i, r + 1);
  w.box = axis == 0 ? makeBox(w.line - h, w.line + h, a0, a1, z0, z1) : makeBox(a0, a1, w.line - h, w.line + h, z0, z1);
  w.name = "wall-" + std::to_string(st) + (axis == 0 ? "-u" : "-v") + std::to_string(i) +
           (axis == 0 ? "-r" : "-c") + std::to_string(r);
  return w;
}

void addWalls(BuildingLayout& L, const BuildingSpec& spec, const Planner& p) {
  const double H = spec.storey_height, ts = spec.slab_thickness;
  for (int st = 0; st < spec.storeys; ++st) {
    const double z0 = st * H + ts, z1 = (st + 1) * H;
    // Walls on u-lines (axis 0, run along v), then on v-lines (axis 1, run along u).
    for (int axis = 0; axis < 2; ++axis)
      for (long i = 0; i <= p.cells(axis); ++i)
        for (long r = 0; r < p.cells(1 - axis); ++r)
          if (const double h = p.half(axis, i, r); h != 0.0) L.walls.push_back(makeWall(p, axis, i, r, h, st, z0, z1));
  }
}

/// Numbers the openings as they are added; the entrance door is the first exterior ground
/// floor segment on v-line 0.
struct OpeningCount {
  int windows = 0, doors = 0;
  bool entrance_done = false;
};

/// A door of the spec's size centred on [span0, span1] of wall `wi`, from its floor.
void addDoor(BuildingLayout& L, const BuildingSpec& spec, int wi, double span0, double span1,
             OpeningCount& count) {
  const LayoutWall w = L.walls[static_cast<std::size_t>(wi)];
  const double floor_z = w.box.lo.z();
  const double c = 0.5 * (span0 + span1);
  addOpening(L, w, wi, c - spec.door_width / 2, c + spec.door_width / 2, floor_z,
             floor_z + spec.door_height, true, w.storey, count.doors++);
}

void addWallOpenings(BuildingLayout& L, const BuildingSpec& spec, const Planner& p, int wi,
                     OpeningCount& count) {
  const LayoutWall w = L.walls[static_cast<std::size_t>(wi)];
  const int along = 1 - w.axis;
  // Clear span between the walls crossing the segment's end nodes.
  const double span0 = w.box.lo[along] + 2 * p.half_ext;  // conservative
  const double span1 = w.box.hi[along] - 2 * p.half_ext;
  const double floor_z = w.box.lo.z();
  if (w.outside_sign != 0) {
    const bool entrance = !count.entrance_done && w.storey == 0 && w.axis == 1 && w.line == 0.0;
    if (entrance) {
      count.entrance_done = true;
      addDoor(L, spec, wi, span0, span1, count);
      return;
    }
    for (double c : slotCentres(span0, span1, spec.window_width, spec.window_spacing))
      addOpening(L, w, wi, c - spec.window_width / 2, c + spec.window_width / 2,
                 floor_z + spec.sill_height, floor_z + spec.sill_height + spec.window_height,
                 false, w.storey, count.windows++);
  } else if (spec.interior_doors && span1 - span0 >= spec.door_width + 0.3) {
    addDoor(L, spec, wi, span0, span1, count);
  }
}

/// Windows in exterior segments, doors in interior ones, one entrance door.
void addOpenings(BuildingLayout& L, const BuildingSpec& spec, const Planner& p) {
  OpeningCount count;
  count.entrance_done = !spec.entrance_door;
  for (int wi = 0; wi < static_cast<int>(L.walls.size()); ++wi) addWallOpenings(L, spec, p, wi, count);
}

/// Ground floor, one per storey above, roof. Cover rooms and wall footprints.
void addSlabs(BuildingLayout& L, const BuildingSpec& spec, const Planner& p) {
  const double H = spec.storey_height, ts = spec.slab_thickness;
  for (int level = 0; level <= spec.storeys; ++level) {
    LayoutPart slab;
    slab.name = level == 0 ? "ground-slab" : (level == spec.storeys ? "roof-slab" : "slab-" + std::to_string(level));
    const double z0 = level * H, z1 = level * H + ts;
    for (long r = 0; r < p.R; ++r)
      for (long c = 0; c < p.C; ++c)
        if (spec.isRoom(c, r))
          slab.boxes.push_back(makeBox(p.U[static_cast<std::size_t>(c)], p.U[static_cast<std::size_t>(c + 1)],
                                       p.V[static_cast<std::size_t>(r)], p.V[static_cast<std::size_t>(r + 1)], z0, z1));
    for (const auto& w : L.walls)
      if (w.storey == 0) {
        Box b = w.box;
        b.lo.z() = z0;
        b.hi.z() = z1;
        slab.boxes.push_back(b);
      }
    L.slabs.push_back(slab);
  }
}

/// The random furniture generator (one sequence for the whole building).
struct FurnitureRandom {
  std::mt19937_64 rng;
  std::uniform_real_distribution<double> unit{0.0, 1.0};
};

/// Up to spec.furniture_per_room random boxes on the floor (at fz) of the free area
/// [u0, u1] x [v0, v1] of a room.
void furnishRoom(BuildingLayout& L, const BuildingSpec& spec, double u0, double u1, double v0,
                 double v1, double fz, FurnitureRandom& random) {
  auto& [rng, unit] = random;
  const Eigen::Vector2d centre(0.5 * (u0 + u1), 0.5 * (v0 + v1));
  std::vector<Box> placed;
  for (int attempt = 0; attempt < 40 && static_cast<int>(placed.size()) < spec.furniture_per_room; ++attempt) {
    const double w = 0.5 + unit(rng), d = 0.4 + 0.6 * unit(rng), h = 0.4 + 0.8 * unit(rng);
    if (u1 - u0 < w || v1 - v0 < d) continue;
    const double bu = u0 + unit(rng) * (u1 - u0 - w), bv = v0 + unit(rng) * (v1 - v0 - d);
    Box b = makeBox(bu, bu + w, bv, bv + d, fz, fz + h);
    // Keep 1 m around the room centre free, and 0.3 m between pieces.
    const bool near_centre = bu - 1.0 < centre.x() && bu + w + 1.0 > centre.x() &&
                             bv - 1.0 < centre.y() && bv + d + 1.0 > centre.y();
    bool overlaps = false;
    for (const auto& o : placed)
      overlaps |= b.lo.x() < o.hi.x() + 0.3 && o.lo.x() < b.hi.x() + 0.3 &&
                  b.lo.y() < o.hi.y() + 0.3 && o.lo.y() < b.hi.y() + 0.3;
    if (near_centre || overlaps) continue;
    placed.push_back(b);
    LayoutPart part;
    part.boxes.push_back(b);
    part.name = "furniture-" + std::to_string(L.furniture.size());
    L.furniture.push_back(part);
  }
}

/// Random boxes in each room, away from the room centre (scanner stations).
void addFurniture(BuildingLayout& L, const BuildingSpec& spec, const Planner& p) {
  FurnitureRandom random{std::mt19937_64(spec.seed)};
  const double margin = p.half_ext + 0.3;
  for (int st = 0; st < spec.storeys && spec.furniture_per_room > 0; ++st)
    for (long r = 0; r < p.R; ++r)
      for (long c = 0; c < p.C; ++c) {
        if (!spec.isRoom(c, r)) continue;
        const double u0 = p.U[static_cast<std::size_t>(c)] + margin, u1 = p.U[static_cast<std::size_t>(c + 1)] - margin;
        const double v0 = p.V[static_cast<std::size_t>(r)] + margin, v1 = p.V[static_cast<std::size_t>(r + 1)] - margin;
        furnishRoom(L, spec, u0, u1, v0, v1, st * spec.storey_height + spec.slab_thickness, random);
      }
}

}  // namespace

BuildingLayout layoutBuilding(const BuildingSpec& spec) {
  BuildingLayout L;
  const double a = spec.axis_angle_deg * M_PI / 180.0;
  L.cos_a = std::abs(spec.axis_angle_deg - 90.0) < 1e-12 ? 0.0 : std::cos(a);
  L.sin_a = std::abs(spec.axis_angle_deg - 90.0) < 1e-12 ? 1.0 : std::sin(a);
  const Planner p(spec, L.sin_a);
  addWalls(L, spec, p);
  addOpenings(L, spec, p);
  addSlabs(L, spec, p);
  addFurniture(L, spec, p);
  L.footprint_uv = footprint(p);
  return L;
}

}  // namespace plumb::sim
