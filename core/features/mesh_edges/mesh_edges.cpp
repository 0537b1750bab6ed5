#include "features/mesh_edges/mesh_edges.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>

#include "common/error.hpp"

namespace plumb {

const ParamSchema<MeshEdgeParams>& MeshEdgeParams::schema() {
  using P = MeshEdgeParams;
  static const auto s =
      ParamSchema<P>("mesh-edges")
          .real(&P::angle_threshold_deg, "angle-threshold", "Sharp angle", "deg", 0.1, 180,
                "an edge is sharp when its two faces turn by more than this")
          .real(&P::weld_tolerance, "weld-tolerance", "Weld tolerance", "m", 0, 1,
                "vertices closer than this are merged", true)
          .boolean(&P::include_boundary, "include-boundary", "Boundary edges",
                   "edges with a single triangle are sharp")
          .real(&P::collinear_tolerance_deg, "collinear-tolerance", "Collinear tolerance", "deg",
                0, 10, "pieces chained into one segment turn by less than this", true)
          .real(&P::min_length, "min-length", "Minimum length", "m", 0, 1000,
                "Shorter model edges are not used as segments");
  return s;
}

namespace {

struct UnionFind {
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

/// Welds vertices on a grid of the tolerance (rounded coordinates as the key).
std::vector<std::uint32_t> weld(const TriangleMesh& mesh, double tol,
                                std::vector<Eigen::Vector3d>& welded) {
  std::vector<std::uint32_t> map(mesh.vertices.size());
  if (tol <= 0) {
    welded = mesh.vertices;
    std::iota(map.begin(), map.end(), 0u);
    return map;
  }
  std::map<std::array<std::int64_t, 3>, std::uint32_t> index;
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const auto& v = mesh.vertices[i];
    const std::array<std::int64_t, 3> k{std::llround(v.x() / tol), std::llround(v.y() / tol),
                                        std::llround(v.z() / tol)};
    auto [it, inserted] = index.emplace(k, static_cast<std::uint32_t>(welded.size()));
    if (inserted) welded.push_back(v);
    map[i] = it->second;
  }
  return map;
}

using EdgeMap = std::unordered_map<std::uint64_t, std::vector<std::uint32_t>>;
std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t(std::min(a, b)) << 32) | std::max(a, b);
}

/// T-junctions (common in exported BIM meshes): an edge with a single triangle may be split on
/// the other side by vertices lying on it. Such edges are split at those vertices, so both
/// sides share sub-edges and the dihedral test sees the real neighbours.
void splitTJunctions(const std::vector<Eigen::Vector3d>& verts, EdgeMap& edge_tris, double tol) {
  if (verts.empty()) return;
  Bounds b;
  for (const auto& v : verts) b.extend(v);
  const double cell = std::max(b.diagonal() / 256.0, 1e-3);
  auto cellOf = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector3d q = (p - b.min) / cell;
    return std::array<std::int64_t, 3>{std::int64_t(q.x()), std::int64_t(q.y()), std::int64_t(q.z())};
  };
  auto hash = [](const std::array<std::int64_t, 3>& c) {
    return (std::uint64_t(c[0] & 0x1FFFFF) << 42) | (std::uint64_t(c[1] & 0x1FFFFF) << 21) | std::uint64_t(c[2] & 0x1FFFFF);
  };
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> grid;
  for (std::size_t i = 0; i < verts.size(); ++i) grid[hash(cellOf(verts[i]))].push_back(static_cast<std::uint32_t>(i));
  std::vector<std::uint64_t> boundary;
  for (const auto& [key, tris] : edge_tris)
    if (tris.size() == 1) boundary.push_back(key);
  std::sort(boundary.begin(), boundary.end());
  for (auto key : boundary) {
    const auto a = static_cast<std::uint32_t>(key >> 32), c = static_cast<std::uint32_t>(key & 0xffffffffu);
    const Eigen::Vector3d pa = verts[a], d = verts[c] - verts[a];
    const double len = d.norm();
    if (!(len > 0)) continue;
    std::vector<std::pair<double, std::uint32_t>> on;
    std::vector<std::uint64_t> seen;
    const int steps = static_cast<int>(len / (0.5 * cell)) + 1;
    for (int k = 0; k <= steps; ++k) {
      const auto c0 = cellOf(pa + d * (double(k) / steps));
      for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
          for (int dz = -1; dz <= 1; ++dz) {
            const auto h = hash({c0[0] + dx, c0[1] + dy, c0[2] + dz});
            if (std::find(seen.begin(), seen.end(), h) != seen.end()) continue;
            seen.push_back(h);
            auto it = grid.find(h);
            if (it == grid.end()) continue;
            for (auto v : it->second) {
              if (v == a || v == c) continue;
              const double t = (verts[v] - pa).dot(d) / (len * len);
              if (t <= 1e-9 || t >= 1 - 1e-9) continue;
              if ((pa + t * d - verts[v]).norm() <= tol) on.emplace_back(t, v);
            }
          }
    }
    if (on.empty()) continue;
    std::sort(on.begin(), on.end());
    const std::uint32_t tri = edge_tris[key].front();
    edge_tris.erase(key);
    std::uint32_t prev = a;
    for (const auto& [t, v] : on) {
      edge_tris[edgeKey(prev, v)].push_back(tri);
      prev = v;
    }
    edge_tris[edgeKey(prev, c)].push_back(tri);
  }
}

/// Edge -> incident triangles (after welding; degenerate triangles skipped), and the unit
/// normal of each triangle (zero for skipped ones).
EdgeMap edgeTriangles(const TriangleMesh& mesh, const std::vector<std::uint32_t>& vmap,
                      const std::vector<Eigen::Vector3d>& verts,
                      std::vector<Eigen::Vector3d>& normals) {
  EdgeMap edge_tris;
  normals.assign(mesh.triangles.size(), Eigen::Vector3d::Zero());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const std::uint32_t a = vmap[tri[0]], b = vmap[tri[1]], c = vmap[tri[2]];
    if (a == b || b == c || a == c) continue;
    const Eigen::Vector3d n = (verts[b] - verts[a]).cross(verts[c] - verts[a]);
    if (n.norm() <= 0) continue;
    normals[t] = n.normalized();
    const std::uint32_t e[3][2] = {{a, b}, {b, c}, {c, a}};
    for (auto& ed : e) {
      edge_tris[edgeKey(ed[0], ed[1])].push_back(static_cast<std::uint32_t>(t));
    }
  }
  return edge_tris;
}

using Edge = std::array<std::uint32_t, 2>;

/// Sharp edges: dihedral (turning) angle between face normals above the threshold. Edges
/// between coplanar triangles vanish, which merges coplanar triangles into facets.
std::vector<Edge> sharpEdges(const EdgeMap& edge_tris, const std::vector<Eigen::Vector3d>& normals,
                             double cos_thr, bool include_boundary) {
  std::vector<Edge> sharp;
  for (const auto& [key, tris] : edge_tris) {
    bool is_sharp = false;
    if (tris.size() == 1) {
      is_sharp = include_boundary;
    } else {
      for (std::size_t i = 0; i < tris.size() && !is_sharp; ++i)
        for (std::size_t j = i + 1; j < tris.size() && !is_sharp; ++j)
          if (normals[tris[i]].dot(normals[tris[j]]) < cos_thr) is_sharp = true;
    }
    if (is_sharp) sharp.push_back({static_cast<std::uint32_t>(key >> 32), static_cast<std::uint32_t>(key & 0xffffffffu)});
  }
  std::sort(sharp.begin(), sharp.end());  // deterministic order
  return sharp;
}

/// Chain: at each vertex, link pairs of incident sharp edges that continue each other
/// (turn by less than acos(cos_col)). Returns the chains as lists of edge indices.
std::map<std::size_t, std::vector<std::uint32_t>> chainEdges(const std::vector<Edge>& sharp,
                                                             const std::vector<Eigen::Vector3d>& verts,
                                                             double cos_col) {
  std::vector<std::vector<std::uint32_t>> incident(verts.size());
  for (std::size_t e = 0; e < sharp.size(); ++e) {
    incident[sharp[e][0]].push_back(static_cast<std::uint32_t>(e));
    incident[sharp[e][1]].push_back(static_cast<std::uint32_t>(e));
  }
  UnionFind uf(sharp.size());
  for (std::size_t v = 0; v < verts.size(); ++v) {
    const auto& inc = incident[v];
    for (std::size_t i = 0; i < inc.size(); ++i) {
      const auto& ei = sharp[inc[i]];
      const Eigen::Vector3d di = (verts[ei[0] == v ? ei[1] : ei[0]] - verts[v]).normalized();
      for (std::size_t j = i + 1; j < inc.size(); ++j) {
        const auto& ej = sharp[inc[j]];
        const Eigen::Vector3d dj = (verts[ej[0] == v ? ej[1] : ej[0]] - verts[v]).normalized();
        if (di.dot(dj) <= -cos_col) uf.unite(inc[i], inc[j]);
      }
    }
  }
  std::map<std::size_t, std::vector<std::uint32_t>> groups;
  for (std::size_t e = 0; e < sharp.size(); ++e) groups[uf.find(e)].push_back(static_cast<std::uint32_t>(e));
  return groups;
}

/// A chain as one segment: extreme vertices along the direction of its first edge.
Segment3D chainSegment(const std::vector<std::uint32_t>& members, const std::vector<Edge>& sharp,
                       const std::vector<Eigen::Vector3d>& verts) {
  const auto& e0 = sharp[members.front()];
  const Eigen::Vector3d d = (verts[e0[1]] - verts[e0[0]]).normalized();
  const Eigen::Vector3d o = verts[e0[0]];
  double lo = 0, hi = 0;
  Eigen::Vector3d a = o, b = o;
  for (auto m : members)
    for (auto vi : sharp[m]) {
      const double s = (verts[vi] - o).dot(d);
      if (s < lo) { lo = s; a = verts[vi]; }
      if (s > hi) { hi = s; b = verts[vi]; }
    }
  Segment3D seg;
  seg.a = a;
  seg.b = b;
  return seg;
}

}  // namespace

MeshEdgeResult extractSharpEdges(const TriangleMesh& mesh, const MeshEdgeParams& params,
                                 Progress* progress) {
  validateParams(MeshEdgeParams::schema(), params);
  MeshEdgeResult result;
  std::vector<Eigen::Vector3d> verts;
  const auto vmap = weld(mesh, params.weld_tolerance, verts);
  reportProgress(progress, 0.1, "edges");
  std::vector<Eigen::Vector3d> normals;
  EdgeMap edge_tris = edgeTriangles(mesh, vmap, verts, normals);
  checkCanceled(progress);
  splitTJunctions(verts, edge_tris, std::max(10.0 * params.weld_tolerance, 1e-6));
  checkCanceled(progress);
  const std::vector<Edge> sharp =
      sharpEdges(edge_tris, normals, std::cos(params.angle_threshold_deg * M_PI / 180.0),
                 params.include_boundary);
  result.sharp_edge_count = sharp.size();
  reportProgress(progress, 0.5, "chaining");
  const double cos_col = std::cos(params.collinear_tolerance_deg * M_PI / 180.0);
  for (const auto& [root, members] : chainEdges(sharp, verts, cos_col)) {
    const Segment3D seg = chainSegment(members, sharp, verts);
    if (seg.length() >= params.min_length && seg.length() > 0) result.segments.push_back(seg);
  }
  std::stable_sort(result.segments.begin(), result.segments.end(),
                   [](const Segment3D& x, const Segment3D& y) { return x.length() > y.length(); });
  reportProgress(progress, 1.0, "chaining");
  return result;
}

}  // namespace plumb
