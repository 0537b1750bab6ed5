#include "simulation/building_generator.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

#include "simulation/building_layout.hpp"

namespace plumb {

std::vector<const TruthPlane*> BuildingTruth::planesWithFace(const std::string& face) const {
  std::vector<const TruthPlane*> out;
  for (const auto& p : planes)
    if (p.face == face) out.push_back(&p);
  return out;
}

namespace {

using sim::Box;
using sim::BuildingLayout;

enum class Kind { Wall, Slab, Opening, Furniture };

// The fine grid: sorted unique coordinates per axis (u, v, z) and one owner per cell.
struct CellGrid {
  std::array<std::vector<double>, 3> lines;
  std::vector<std::int32_t> owner;    // element index, -1 empty
  std::vector<std::int32_t> opening;  // element index of the opening an empty cell lies in

  std::array<long, 3> cells() const {
    return {static_cast<long>(lines[0].size()) - 1, static_cast<long>(lines[1].size()) - 1,
            static_cast<long>(lines[2].size()) - 1};
  }
  std::size_t index(long i, long j, long k) const {
    const auto n = cells();
    return (static_cast<std::size_t>(k) * static_cast<std::size_t>(n[1]) + static_cast<std::size_t>(j)) *
               static_cast<std::size_t>(n[0]) + static_cast<std::size_t>(i);
  }
  bool inside(long i, long j, long k) const {
    const auto n = cells();
    return i >= 0 && j >= 0 && k >= 0 && i < n[0] && j < n[1] && k < n[2];
  }
  bool solid(long i, long j, long k) const { return inside(i, j, k) && owner[index(i, j, k)] >= 0; }
  // Cell index range [first, last) whose centres lie inside [lo, hi] on axis a.
  std::pair<long, long> range(int a, double lo, double hi) const {
    const auto& l = lines[static_cast<std::size_t>(a)];
    long first = static_cast<long>(std::lower_bound(l.begin(), l.end(), lo - 1e-9) - l.begin());
    long last = static_cast<long>(std::lower_bound(l.begin(), l.end(), hi - 1e-9) - l.begin());
    return {first, last};
  }
  template <class F>
  void forBox(const Box& b, F&& f) {
    const auto [i0, i1] = range(0, b.lo.x(), b.hi.x());
    const auto [j0, j1] = range(1, b.lo.y(), b.hi.y());
    const auto [k0, k1] = range(2, b.lo.z(), b.hi.z());
    for (long k = k0; k < k1; ++k)
      for (long j = j0; j < j1; ++j)
        for (long i = i0; i < i1; ++i) f(index(i, j, k));
  }
};

std::vector<double> uniqueSorted(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  std::vector<double> out;
  for (double x : v)
    if (out.empty() || x - out.back() > 1e-7) out.push_back(x);
  return out;
}

struct Generator {
  const BuildingSpec& spec;
  BuildingLayout L;
  GeneratedBuilding out;
  CellGrid grid;
  std::vector<Kind> kinds;
  std::vector<int> layout_index;  // element -> index in its layout list
  std::vector<std::uint32_t> vertex_of;

  explicit Generator(const BuildingSpec& s) : spec(s), L(sim::layoutBuilding(s)) {}

  std::uint32_t addElement(const std::string& type, const std::string& name, Kind kind, int index) {
    out.model.elements.push_back({type, name, "plumb-sim-" + std::to_string(out.model.elements.size())});
    kinds.push_back(kind);
    layout_index.push_back(index);
    return static_cast<std::uint32_t>(out.model.elements.size() - 1);
  }

  Eigen::Vector3d world(long i, long j, long k) const {
    return L.toWorld({grid.lines[0][static_cast<std::size_t>(i)], grid.lines[1][static_cast<std::size_t>(j)],
                      grid.lines[2][static_cast<std::size_t>(k)]});
  }

  std::uint32_t vertex(long i, long j, long k) {
    const std::size_t key = (static_cast<std::size_t>(k) * grid.lines[1].size() + static_cast<std::size_t>(j)) *
                                grid.lines[0].size() + static_cast<std::size_t>(i);
    if (vertex_of[key] == UINT32_MAX) {
      vertex_of[key] = static_cast<std::uint32_t>(out.model.mesh.vertices.size());
      out.model.mesh.vertices.push_back(world(i, j, k));
    }
    return vertex_of[key];
  }

  void buildGrid() {
    std::array<std::vector<double>, 3> coords;
    auto addBox = [&](const Box& b) {
      for (int a = 0; a < 3; ++a) {
        coords[static_cast<std::size_t>(a)].push_back(b.lo[a]);
        coords[static_cast<std::size_t>(a)].push_back(b.hi[a]);
      }
    };
    for (const auto& w : L.walls) addBox(w.box);
    for (const auto& o : L.openings) addBox(o.box);
    for (const auto& s : L.slabs)
      for (const auto& b : s.boxes) addBox(b);
    for (int a = 0; a < 3; ++a) grid.lines[static_cast<std::size_t>(a)] = uniqueSorted(coords[static_cast<std::size_t>(a)]);
    const auto n = grid.cells();
    grid.owner.assign(static_cast<std::size_t>(n[0] * n[1] * n[2]), -1);
    grid.opening.assign(grid.owner.size(), -1);
    vertex_of.assign(grid.lines[0].size() * grid.lines[1].size() * grid.lines[2].size(), UINT32_MAX);

    for (std::size_t w = 0; w < L.walls.size(); ++w) {
      const auto e = addElement("IfcWall", L.walls[w].name, Kind::Wall, static_cast<int>(w));
      grid.forBox(L.walls[w].box, [&](std::size_t c) { if (grid.owner[c] < 0) grid.owner[c] = static_cast<std::int32_t>(e); });
    }
    for (std::size_t s = 0; s < L.slabs.size(); ++s) {
      const auto e = addElement("IfcSlab", L.slabs[s].name, Kind::Slab, static_cast<int>(s));
      for (const auto& b : L.slabs[s].boxes)
        grid.forBox(b, [&](std::size_t c) { if (grid.owner[c] < 0) grid.owner[c] = static_cast<std::int32_t>(e); });
    }
    for (std::size_t o = 0; o < L.openings.size(); ++o) {
      const auto& op = L.openings[o];
      const auto e = addElement(op.door ? "IfcDoor" : "IfcWindow", op.name, Kind::Opening, static_cast<int>(o));
      grid.forBox(op.box, [&](std::size_t c) {
        grid.owner[c] = -1;
        grid.opening[c] = static_cast<std::int32_t>(e);
      });
    }
    for (std::size_t f = 0; f < L.furniture.size(); ++f) {
      // Furniture stays off the grid (its lines would cut every wall): see addFurniture().
      addElement("IfcFurnishingElement", L.furniture[f].name, Kind::Furniture, static_cast<int>(f));
    }
  }

  std::string faceLabel(std::uint32_t element, int axis, int sign) const {
    const Kind kind = kinds[element];
    if (kind == Kind::Slab) return axis == 2 ? (sign > 0 ? "top" : "bottom") : "exterior";
    if (kind != Kind::Wall) return "other";
    const auto& w = L.walls[static_cast<std::size_t>(layout_index[element])];
    if (axis != w.axis) return "other";
    return w.outside_sign != 0 && sign == w.outside_sign ? "exterior" : "interior";
  }

  void buildMesh() {
    auto& mesh = out.model.mesh;
    const auto n = grid.cells();
    std::map<std::tuple<std::uint32_t, int, long, int>, std::size_t> plane_of;
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      for (long l = 0; l <= n[static_cast<std::size_t>(a)]; ++l)
        for (long jc = 0; jc < n[static_cast<std::size_t>(c)]; ++jc)
          for (long jb = 0; jb < n[static_cast<std::size_t>(b)]; ++jb) {
            std::array<long, 3> lo{}, hi{};
            lo[static_cast<std::size_t>(a)] = l - 1;
            hi[static_cast<std::size_t>(a)] = l;
            lo[static_cast<std::size_t>(b)] = hi[static_cast<std::size_t>(b)] = jb;
            lo[static_cast<std::size_t>(c)] = hi[static_cast<std::size_t>(c)] = jc;
            const bool s0 = grid.solid(lo[0], lo[1], lo[2]), s1 = grid.solid(hi[0], hi[1], hi[2]);
            if (s0 == s1) continue;
            const int sign = s0 ? +1 : -1;  // outward normal along +a when the solid is below
            const auto& solid = s0 ? lo : hi;
            const auto& empty = s0 ? hi : lo;
            auto element = static_cast<std::uint32_t>(grid.owner[grid.index(solid[0], solid[1], solid[2])]);
            if (grid.inside(empty[0], empty[1], empty[2]) && grid.opening[grid.index(empty[0], empty[1], empty[2])] >= 0)
              element = static_cast<std::uint32_t>(grid.opening[grid.index(empty[0], empty[1], empty[2])]);
            std::array<std::uint32_t, 4> q{};
            for (int corner = 0; corner < 4; ++corner) {
              std::array<long, 3> g{};
              g[static_cast<std::size_t>(a)] = l;
              g[static_cast<std::size_t>(b)] = jb + ((corner == 1 || corner == 2) ? 1 : 0);
              g[static_cast<std::size_t>(c)] = jc + (corner >= 2 ? 1 : 0);
              q[static_cast<std::size_t>(corner)] = vertex(g[0], g[1], g[2]);
            }
            if (sign < 0) std::swap(q[1], q[3]);
            mesh.triangles.push_back({q[0], q[1], q[2]});
            mesh.triangles.push_back({q[0], q[2], q[3]});
            out.model.triangle_element.insert(out.model.triangle_element.end(), 2, element);
            const double area = mesh.triangleArea(mesh.triangles.size() - 1) + mesh.triangleArea(mesh.triangles.size() - 2);
            const auto key = std::make_tuple(element, a, l, sign);
            auto it = plane_of.find(key);
            if (it == plane_of.end()) {
              TruthPlane p;
              p.normal = sign * L.planeNormal(a);
              p.offset = sign * L.planeScale(a) * grid.lines[static_cast<std::size_t>(a)][static_cast<std::size_t>(l)];
              p.element = element;
              p.element_type = out.model.elements[element].type;
              p.face = faceLabel(element, a, sign);
              it = plane_of.emplace(key, out.truth.planes.size()).first;
              out.truth.planes.push_back(p);
            }
            out.truth.planes[it->second].area += area;
          }
    }
    out.glass_triangles.assign(mesh.triangles.size(), false);
  }

  // A grid edge is sharp unless the 4 cells around it are all alike or form a flat boundary.
  void sharpEdges() {
    const auto n = grid.cells();
    for (int a = 0; a < 3; ++a) {
      const int b = (a + 1) % 3, c = (a + 2) % 3;
      for (long gc = 0; gc <= n[static_cast<std::size_t>(c)]; ++gc)
        for (long gb = 0; gb <= n[static_cast<std::size_t>(b)]; ++gb) {
          long run_start = -1;
          for (long l = 0; l <= n[static_cast<std::size_t>(a)]; ++l) {
            bool sharp = false;
            if (l < n[static_cast<std::size_t>(a)]) {
              bool s[2][2];
              for (int db = 0; db < 2; ++db)
                for (int dc = 0; dc < 2; ++dc) {
                  std::array<long, 3> g{};
                  g[static_cast<std::size_t>(a)] = l;
                  g[static_cast<std::size_t>(b)] = gb - 1 + db;
                  g[static_cast<std::size_t>(c)] = gc - 1 + dc;
                  s[db][dc] = grid.solid(g[0], g[1], g[2]);
                }
              const int count = s[0][0] + s[0][1] + s[1][0] + s[1][1];
              const bool flat = (s[0][0] == s[1][0] && s[0][1] == s[1][1] && s[0][0] != s[0][1]) ||
                                (s[0][0] == s[0][1] && s[1][0] == s[1][1] && s[0][0] != s[1][0]);
              sharp = count != 0 && count != 4 && !flat;
            }
            if (sharp && run_start < 0) run_start = l;
            if (!sharp && run_start >= 0) {
              std::array<long, 3> p0{}, p1{};
              p0[static_cast<std::size_t>(a)] = run_start;
              p1[static_cast<std::size_t>(a)] = l;
              p0[static_cast<std::size_t>(b)] = p1[static_cast<std::size_t>(b)] = gb;
              p0[static_cast<std::size_t>(c)] = p1[static_cast<std::size_t>(c)] = gc;
              Segment3D seg;
              seg.a = world(p0[0], p0[1], p0[2]);
              seg.b = world(p1[0], p1[1], p1[2]);
              out.truth.sharp_edges.push_back(seg);
              run_start = -1;
            }
          }
        }
    }
  }

  // Furniture: separate closed boxes standing on the floor (their bottom faces lie on the
  // floor, unseen). Their 12 edges are sharp; the floor under them stays one flat face.
  void addFurniture() {
    auto& mesh = out.model.mesh;
    for (std::size_t e = 0; e < kinds.size(); ++e) {
      if (kinds[e] != Kind::Furniture) continue;
      const Box& box = L.furniture[static_cast<std::size_t>(layout_index[e])].boxes[0];
      auto corner = [&](int bits) {
        return L.toWorld({(bits & 1) ? box.hi.x() : box.lo.x(), (bits & 2) ? box.hi.y() : box.lo.y(),
                          (bits & 4) ? box.hi.z() : box.lo.z()});
      };
      const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
      for (int bits = 0; bits < 8; ++bits) mesh.vertices.push_back(corner(bits));
      for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;
        for (int sign : {-1, +1}) {
          std::array<std::uint32_t, 4> q{};
          for (int k = 0; k < 4; ++k) {
            const int db = (k == 1 || k == 2) ? 1 : 0, dc = k >= 2 ? 1 : 0;
            q[static_cast<std::size_t>(k)] = first + static_cast<std::uint32_t>(((sign > 0) << a) | (db << b) | (dc << c));
          }
          if (sign < 0) std::swap(q[1], q[3]);
          mesh.triangles.push_back({q[0], q[1], q[2]});
          mesh.triangles.push_back({q[0], q[2], q[3]});
          out.model.triangle_element.insert(out.model.triangle_element.end(), 2, static_cast<std::uint32_t>(e));
          out.glass_triangles.insert(out.glass_triangles.end(), 2, false);
          TruthPlane p;
          p.normal = sign * L.planeNormal(a);
          p.offset = sign * L.planeScale(a) * (sign > 0 ? box.hi[a] : box.lo[a]);
          p.element = static_cast<std::uint32_t>(e);
          p.element_type = out.model.elements[e].type;
          p.face = "other";
          p.area = mesh.triangleArea(mesh.triangles.size() - 1) + mesh.triangleArea(mesh.triangles.size() - 2);
          out.truth.planes.push_back(p);
        }
      }
      for (int bits = 0; bits < 8; ++bits)
        for (int a = 0; a < 3; ++a)
          if (!(bits & (1 << a))) {
            Segment3D s;
            s.a = corner(bits);
            s.b = corner(bits | (1 << a));
            out.truth.sharp_edges.push_back(s);
          }
    }
  }

  void openingsTruthAndGlass() {
    auto& mesh = out.model.mesh;
    for (std::size_t e = 0; e < kinds.size(); ++e) {
      if (kinds[e] != Kind::Opening) continue;
      const auto& op = L.openings[static_cast<std::size_t>(layout_index[e])];
      const auto& w = L.walls[static_cast<std::size_t>(op.wall)];
      const int along = 1 - w.axis;
      auto cornerAt = [&](double across, bool hi_along, bool hi_z) {
        Eigen::Vector3d g;
        g[w.axis] = across;
        g[along] = hi_along ? op.box.hi[along] : op.box.lo[along];
        g.z() = hi_z ? op.box.hi.z() : op.box.lo.z();
        return L.toWorld(g);
      };
      for (int sign : {-1, +1}) {
        TruthOpening t;
        t.element = static_cast<std::uint32_t>(e);
        t.element_type = out.model.elements[e].type;
        t.wall = 0;
        for (std::size_t we = 0; we < kinds.size(); ++we)
          if (kinds[we] == Kind::Wall && layout_index[we] == op.wall) t.wall = static_cast<std::uint32_t>(we);
        t.face = w.outside_sign != 0 && sign == w.outside_sign ? "exterior" : "interior";
        t.face_normal = sign * L.planeNormal(w.axis);
        t.storey = op.storey;
        const double across = w.line + sign * w.half;
        const Eigen::Vector3d right = Eigen::Vector3d::UnitZ().cross(t.face_normal);
        const Eigen::Vector3d p0 = cornerAt(across, false, false), p1 = cornerAt(across, true, false);
        const bool flip = (p1 - p0).dot(right) < 0;
        t.corners = {flip ? p1 : p0, flip ? p0 : p1, cornerAt(across, !flip, true), cornerAt(across, flip, true)};
        out.truth.openings.push_back(t);
      }
      if (op.door || !spec.glass) continue;
      // Glass pane on the wall's centre line.
      const auto first = static_cast<std::uint32_t>(mesh.vertices.size());
      const std::array<Eigen::Vector3d, 4> pane{cornerAt(w.line, false, false), cornerAt(w.line, true, false),
                                                cornerAt(w.line, true, true), cornerAt(w.line, false, true)};
      for (const auto& p : pane) mesh.vertices.push_back(p);
      mesh.triangles.push_back({first, first + 1, first + 2});
      mesh.triangles.push_back({first, first + 2, first + 3});
      out.model.triangle_element.insert(out.model.triangle_element.end(), 2, static_cast<std::uint32_t>(e));
      out.glass_triangles.insert(out.glass_triangles.end(), 2, true);
      for (int k = 0; k < 4; ++k) {
        Segment3D s;
        s.a = pane[static_cast<std::size_t>(k)];
        s.b = pane[static_cast<std::size_t>((k + 1) % 4)];
        out.truth.glass_edges.push_back(s);
      }
    }
  }
};

}  // namespace

GeneratedBuilding generateBuilding(const BuildingSpec& spec) {
  spec.validate();
  Generator g(spec);
  g.out.spec = spec;
  g.out.model.format = "generated";
  g.out.model.source = spec.name;
  g.buildGrid();
  g.buildMesh();
  g.sharpEdges();
  g.addFurniture();
  g.openingsTruthAndGlass();
  auto& t = g.out.truth;
  t.exterior_wall_thickness = spec.exterior_wall_thickness;
  t.interior_wall_thickness = spec.interior_wall_thickness;
  t.axis_angle_deg = spec.axis_angle_deg;
  for (const auto& p : g.L.footprint_uv) t.footprint.push_back(g.L.toWorld({p.x(), p.y(), 0.0}));
  return std::move(g.out);
}

}  // namespace plumb
