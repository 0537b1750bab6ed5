#include "features/facades/opening_detection.hpp"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "common/error.hpp"
#include "features/planes/polygon_2d.hpp"

namespace plumb {

const ParamSchema<OpeningDetectionParams>& OpeningDetectionParams::schema() {
  using P = OpeningDetectionParams;
  static const auto s =
      ParamSchema<P>("openings")
          .choice(&P::source, "source", "Evidence", {"auto", "ray-tracing", "holes"},
                  "auto: ray tracing when sensor origins exist, plus holes of wall polygons")
          .real(&P::vertical_tolerance_deg, "vertical-tolerance", "Verticality", "deg", 0, 45,
                "façade normals within this angle of horizontal")
          .real(&P::min_facade_area, "min-facade-area", "Minimum façade area", "m2", 0, 1e6,
                "Smaller façades are not searched for openings")
          .real(&P::min_depth, "min-depth", "Minimum depth", "m", 0, 100,
                "A point must lie this far behind the façade to count as seen through an opening\n"
                "(d_min, 2021 §3.1, 2023 §III-A)")
          .real(&P::link_distance, "link-distance", "Evidence link", "m", 0.005, 5,
                "evidence points closer than this form one opening")
          .integer(&P::min_evidence, "min-evidence", "Minimum evidence", "points", 1, 1e7,
                   "Points seen through an opening needed to keep it")
          .real(&P::min_width, "min-width", "Minimum width", "m", 0, 100, "Narrower openings are dropped")
          .real(&P::min_height, "min-height", "Minimum height", "m", 0, 100, "Lower openings are dropped")
          .real(&P::max_width, "max-width", "Maximum width", "m", 0, 1000, "Wider openings are dropped (a missing wall is no window)")
          .real(&P::max_height, "max-height", "Maximum height", "m", 0, 1000, "Taller openings are dropped")
          .real(&P::snap_distance, "snap-distance", "Snap distance", "m", 0, 2,
                "sides move to the wall edge; closer than this: middle of evidence and wall; 0: off", true);
  return s;
}

std::vector<int> selectFacades(const std::vector<PlanarPolygon>& planes,
                               double vertical_tolerance_deg, double min_facade_area) {
  std::vector<int> out;
  for (std::size_t k = 0; k < planes.size(); ++k)
    if (planes[k].isVertical(vertical_tolerance_deg) && planes[k].area >= min_facade_area &&
        !planes[k].rings.empty())
      out.push_back(static_cast<int>(k));
  return out;
}

namespace {

struct Rect {
  double u0, v0, u1, v1;
  double area() const { return std::max(0.0, u1 - u0) * std::max(0.0, v1 - v0); }
};

double overlap(const Rect& a, const Rect& b) {
  const Rect i{std::max(a.u0, b.u0), std::max(a.v0, b.v0), std::min(a.u1, b.u1), std::min(a.v1, b.v1)};
  const double u = a.area() + b.area() - i.area();
  return u > 0 ? i.area() / u : 0.0;
}

/// Convex hull (Andrew's monotone chain), counter-clockwise. Doors reach the floor: they are
/// notches of the wall's outer ring, not holes, but lie inside its convex hull.
std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> p) {
  std::sort(p.begin(), p.end(), [](const auto& a, const auto& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  if (p.size() < 3) return p;
  std::vector<Eigen::Vector2d> h(2 * p.size());
  std::size_t k = 0;
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h[k++] = p[i - 1];
  }
  h.resize(k - 1);
  return h;
}

/// Rasterised outer ring for fast inside tests (cell 5 cm).
struct RingMask {
  double u0 = 0, v0 = 0, cell = 0.05;
  int nu = 0, nv = 0;
  std::vector<char> in;
  explicit RingMask(const std::vector<Eigen::Vector2d>& ring) {
    double u1 = -1e300, v1 = -1e300;
    u0 = v0 = 1e300;
    for (const auto& p : ring) {
      u0 = std::min(u0, p.x()); v0 = std::min(v0, p.y());
      u1 = std::max(u1, p.x()); v1 = std::max(v1, p.y());
    }
    nu = static_cast<int>(std::ceil((u1 - u0) / cell)) + 1;
    nv = static_cast<int>(std::ceil((v1 - v0) / cell)) + 1;
    in.assign(static_cast<std::size_t>(nu) * nv, 0);
    for (int j = 0; j < nv; ++j)
      for (int i = 0; i < nu; ++i)
        in[static_cast<std::size_t>(j) * nu + i] =
            ringContains(ring, {u0 + (i + 0.5) * cell, v0 + (j + 0.5) * cell});
  }
  bool contains(const Eigen::Vector2d& p) const {
    const int i = static_cast<int>(std::floor((p.x() - u0) / cell));
    const int j = static_cast<int>(std::floor((p.y() - v0) / cell));
    return i >= 0 && j >= 0 && i < nu && j < nv && in[static_cast<std::size_t>(j) * nu + i];
  }
};

/// Moves each side of r to the nearest façade inlier beyond it (the wall edge).
/// A side with no inlier within `snap` moves to the first inlier beyond it at any distance
/// (up to `max_w` / `max_h` for the whole opening): evidence stops short where rays through
/// the opening return nothing (an indoor scanner sees the sky through a door's upper part:
/// rays above the horizon give no point, so no evidence, and the top of the evidence sits at
/// about the scanner's height). The wall samples, not the rays, then give that edge: the band
/// between the evidence and the first wall sample holds no wall point across the opening's
/// middle span (a notch or hole of the wall polygon, the ray-confirmed opening itself).
Rect snapToWall(const Rect& r, const std::vector<Eigen::Vector2d>& wall, double snap,
                double max_w, double max_h) {
  if (snap <= 0 || wall.empty()) return r;
  Rect out = r;
  const double mu = 0.2 * (r.u1 - r.u0), mv = 0.2 * (r.v1 - r.v0);
  const double cu = 0.5 * (r.u0 + r.u1), cv = 0.5 * (r.v0 + r.v1);
  double left = -1e300, right = 1e300, bottom = -1e300, top = 1e300;
  for (const auto& p : wall) {
    if (p.y() > r.v0 + mv && p.y() < r.v1 - mv) {
      if (p.x() <= cu && p.x() >= r.u1 - max_w) left = std::max(left, p.x());
      if (p.x() >= cu && p.x() <= r.u0 + max_w) right = std::min(right, p.x());
    }
    if (p.x() > r.u0 + mu && p.x() < r.u1 - mu) {
      if (p.y() <= cv && p.y() >= r.v1 - max_h) bottom = std::max(bottom, p.y());
      if (p.y() >= cv && p.y() <= r.v0 + max_h) top = std::min(top, p.y());
    }
  }
  // Only move outwards (evidence lies inside the opening; wall points inside it are noise).
  // The edge lies between the last evidence and the first wall sample: take the middle when
  // they are close (within `snap` and one sampling step each side). When the evidence stops
  // short, the edge lies within one sampling step before the first wall sample (the sample
  // before it on the same scan line fell into the opening): take half a step before it, the
  // step measured on the wall rows (or columns) beyond it (MMS rows are ~6 cm apart; the wall
  // sample alone put a door top 2.8 cm high).
  auto step = [&](bool vertical, double edge, double dir) {
    std::vector<double> d;
    for (const auto& p : wall) {
      const bool in_band = vertical ? (p.x() > r.u0 + mu && p.x() < r.u1 - mu)
                                    : (p.y() > r.v0 + mv && p.y() < r.v1 - mv);
      const double x = dir * ((vertical ? p.y() : p.x()) - edge);
      if (in_band && x >= 0 && x < 0.3) d.push_back(x);
    }
    std::sort(d.begin(), d.end());
    std::vector<double> rows, gaps;  // row starts, then the gaps between them
    for (double x : d)
      if (rows.empty() || x - rows.back() > 0.015) rows.push_back(x);
    for (std::size_t q = 1; q < rows.size(); ++q) gaps.push_back(rows[q] - rows[q - 1]);
    if (gaps.size() < 2) return 0.0;
    std::nth_element(gaps.begin(), gaps.begin() + gaps.size() / 2, gaps.end());
    const double g = gaps[gaps.size() / 2];
    return g < 0.15 ? g : 0.0;
  };
  auto side = [&](double evidence, double wall_edge, bool vertical, double dir) {
    const double gap = std::abs(wall_edge - evidence);
    if (gap < std::min(0.15, snap)) return 0.5 * (evidence + wall_edge);
    const double e = wall_edge - dir * 0.5 * step(vertical, wall_edge, dir);
    return dir > 0 ? std::max(evidence, e) : std::min(evidence, e);
  };
  if (bottom == -1e300) {
    // No wall below the opening: a door. It reaches down to where the wall beside it ends
    // (rays through a door's lower part hit the floor closer than d_min and give no evidence).
    double vmin = 1e300;
    for (const auto& p : wall)
      if ((p.x() < r.u0 && p.x() > r.u0 - 0.3) || (p.x() > r.u1 && p.x() < r.u1 + 0.3)) vmin = std::min(vmin, p.y());
    if (vmin < r.v0 - 0.05) out.v0 = vmin;
  }
  if (left > -1e300 && left < r.u0) out.u0 = side(r.u0, left, false, -1);
  if (right < 1e300 && right > r.u1) out.u1 = side(r.u1, right, false, +1);
  if (bottom > -1e300 && bottom < r.v0) out.v0 = side(r.v0, bottom, true, -1);
  if (top < 1e300 && top > r.v1) out.v1 = side(r.v1, top, true, +1);
  return out;
}

/// Points just behind a façade (depth in (3 cm, 60 cm) on the far side from the viewer):
/// the reveals (jambs, sill, lintel) of its openings. (u, v) in the façade frame.
/// A reveal is seen through its opening, from the viewer's side: with sensor origins, points
/// measured from the far side are left out. They are the wall's other face (at depth = the
/// wall thickness, often < 60 cm), e.g. an exterior wall's inner face seen by an MMS through
/// the windows of the opposite façade, or an interior wall's face seen from the next room;
/// taken as reveals, they moved a door's top onto the inner face's visible band (+4.5 cm).
std::vector<Eigen::Vector2d> revealPoints(const PointCloud& cloud, const PlanarPolygon& f,
                                          const Eigen::Vector3d& view) {
  const double sign = view.dot(f.normal) > 0 ? -1.0 : 1.0;  // depth measured away from viewer
  const bool origins = cloud.hasSensorOrigins();
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!cloud.positions[i].allFinite()) continue;
    const Eigen::Vector3d p = cloud.world(i);
    const double depth = sign * f.signedDistance(p);
    if (depth <= 0.03 || depth >= 0.6) continue;
    if (origins && sign * f.signedDistance(cloud.offset + cloud.sensor_origins[i].cast<double>()) >= 0) continue;
    out.push_back(f.to2d(p));
  }
  return out;
}

/// Moves each side of r onto the reveal surface next to it when enough reveal points line up
/// there (median within 2 cm): reveals are exactly at the opening's edges.
Rect snapToReveals(const Rect& r, const std::vector<Eigen::Vector2d>& reveal, double snap) {
  Rect out = r;
  const double mu = 0.2 * (r.u1 - r.u0), mv = 0.2 * (r.v1 - r.v0);
  std::vector<double> l, rt, b, t;
  for (const auto& p : reveal) {
    if (p.y() > r.v0 + mv && p.y() < r.v1 - mv) {
      if (std::abs(p.x() - r.u0) < snap && p.x() < r.u0 + mu) l.push_back(p.x());
      if (std::abs(p.x() - r.u1) < snap && p.x() > r.u1 - mu) rt.push_back(p.x());
    }
    if (p.x() > r.u0 + mu && p.x() < r.u1 - mu) {
      if (std::abs(p.y() - r.v0) < snap && p.y() < r.v0 + mv) b.push_back(p.y());
      if (std::abs(p.y() - r.v1) < snap && p.y() > r.v1 - mv) t.push_back(p.y());
    }
  }
  auto median = [](std::vector<double>& v, double& m) {
    if (v.size() < 8) return false;
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    m = v[v.size() / 2];
    std::size_t close = 0;
    for (double x : v) close += std::abs(x - m) < 0.02;
    return close * 2 >= v.size();
  };
  double m;
  if (median(l, m)) out.u0 = m;
  if (median(rt, m)) out.u1 = m;
  if (median(b, m)) out.v0 = m;
  if (median(t, m)) out.v1 = m;
  return out;
}

Opening makeOpening(const PlanarPolygon& f, const Rect& r, const Eigen::Vector3d& view_normal,
                    int facade, std::size_t evidence) {
  std::array<Eigen::Vector3d, 4> c = {f.to3d({r.u0, r.v0}), f.to3d({r.u1, r.v0}),
                                      f.to3d({r.u1, r.v1}), f.to3d({r.u0, r.v1})};
  // Order: bottom-left, bottom-right, top-right, top-left seen from view_normal's side.
  const Eigen::Vector3d right = Eigen::Vector3d::UnitZ().cross(view_normal);
  std::sort(c.begin(), c.end(), [](const auto& a, const auto& b) { return a.z() < b.z(); });
  Opening o;
  const bool bottom_swap = c[0].dot(right) > c[1].dot(right);
  o.corners[0] = bottom_swap ? c[1] : c[0];
  o.corners[1] = bottom_swap ? c[0] : c[1];
  const bool top_swap = c[2].dot(right) < c[3].dot(right);
  o.corners[2] = top_swap ? c[3] : c[2];
  o.corners[3] = top_swap ? c[2] : c[3];
  o.facade = facade;
  o.evidence_count = evidence;
  return o;
}

/// Mean point and mean sensor origin over a subsample of the cloud (about 20000 points).
struct CloudMeans {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

CloudMeans cloudMeans(const PointCloud& cloud, bool has_origins) {
  CloudMeans m;
  const std::size_t step = std::max<std::size_t>(1, cloud.size() / 20000);
  std::size_t n = 0;
  for (std::size_t i = 0; i < cloud.size(); i += step) {
    if (!cloud.positions[i].allFinite()) continue;
    m.point += cloud.world(i);
    if (has_origins) m.origin += cloud.offset + cloud.sensor_origins[i].cast<double>();
    ++n;
  }
  if (n) { m.point /= double(n); m.origin /= double(n); }
  return m;
}

/// Which side façade `f` was seen from: its normal or the opposite one, towards the mean
/// sensor origin of its own points (without origins: towards the cloud's mean point).
Eigen::Vector3d viewNormal(const PointCloud& cloud, const PlanarPolygon& f, const CloudMeans& means,
                           bool has_origins) {
  Eigen::Vector3d ref = means.point;
  if (has_origins && !f.inliers.empty()) {
    ref.setZero();
    std::size_t n = 0;
    const std::size_t step = std::max<std::size_t>(1, f.inliers.size() / 2000);
    for (std::size_t j = 0; j < f.inliers.size(); j += step)
      if (f.inliers[j] < cloud.size()) {
        ref += cloud.offset + cloud.sensor_origins[f.inliers[j]].cast<double>();
        ++n;
      }
    ref = n ? Eigen::Vector3d(ref / double(n)) : means.origin;
  } else if (has_origins) {
    ref = means.origin;
  }
  return f.signedDistance(ref) >= 0 ? f.normal : Eigen::Vector3d(-f.normal);
}

/// The façades of a detection with what each step needs of them.
struct Facades {
  const std::vector<PlanarPolygon>& planes;
  const std::vector<int>& index;  ///< into planes
  const PlanarPolygon& operator[](std::size_t k) const { return planes[index[k]]; }
  std::size_t size() const { return index.size(); }
};

/// Nearest façade crossed by the ray O->P with |P - hit| > d_min and the hit inside the
/// façade's outer ring (its mask); -1 when none. `uv` receives the hit in the façade frame.
int nearestCrossing(const Eigen::Vector3d& O, const Eigen::Vector3d& P, const Facades& facades,
                    const std::vector<RingMask>& masks, double min_depth, Eigen::Vector2d& uv) {
  int hit_facade = -1;
  double best_t = 2.0;
  for (std::size_t k = 0; k < facades.size(); ++k) {
    const auto& f = facades[k];
    const double so = f.signedDistance(O), sp = f.signedDistance(P);
    if (so * sp >= 0) continue;
    const double t = so / (so - sp);
    const Eigen::Vector3d hit = O + t * (P - O);
    if ((P - hit).norm() <= min_depth || t >= best_t) continue;
    const Eigen::Vector2d hit_uv = f.to2d(hit);
    if (!masks[k].contains(hit_uv)) continue;
    best_t = t;
    hit_facade = static_cast<int>(k);
    uv = hit_uv;
  }
  return hit_facade;
}

/// Ray evidence: the hits (u, v) on each façade and the interior points, in cloud order.
struct RayEvidence {
  std::vector<std::vector<Eigen::Vector2d>> per_facade;
  std::vector<std::uint32_t> interior_points;
};

RayEvidence traceRays(const PointCloud& cloud, const Facades& facades, double min_depth) {
  std::vector<RingMask> masks;
  for (auto fi : facades.index) masks.emplace_back(convexHull(facades.planes[fi].rings[0]));
  // Per point: nearest façade crossed by O->P with |P - hit| > d_min inside the outer ring.
  std::vector<int> hit_facade(cloud.size(), -1);
  std::vector<Eigen::Vector2d> hit_uv(cloud.size());
  const std::size_t blocks = std::max<std::size_t>(1, cloud.size() / 32768);
  tbb::parallel_for(std::size_t(0), blocks, [&](std::size_t b) {
    const std::size_t begin = cloud.size() * b / blocks, end = cloud.size() * (b + 1) / blocks;
    for (std::size_t i = begin; i < end; ++i) {
      if (!cloud.positions[i].allFinite()) continue;
      const Eigen::Vector3d P = cloud.world(i);
      const Eigen::Vector3d O = cloud.offset + cloud.sensor_origins[i].cast<double>();
      hit_facade[i] = nearestCrossing(O, P, facades, masks, min_depth, hit_uv[i]);
    }
  });
  RayEvidence out;
  out.per_facade.resize(facades.size());
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (hit_facade[i] >= 0) {
      out.per_facade[hit_facade[i]].push_back(hit_uv[i]);
      out.interior_points.push_back(static_cast<std::uint32_t>(i));
    }
  return out;
}

bool sizeOk(const Rect& r, const OpeningDetectionParams& params) {
  const double w = r.u1 - r.u0, h = r.v1 - r.v0;
  return w >= params.min_width && h >= params.min_height && w <= params.max_width &&
         h <= params.max_height;
}

constexpr Rect kEmptyRect{1e300, 1e300, -1e300, -1e300};

void extend(Rect& r, const Eigen::Vector2d& p) {
  r.u0 = std::min(r.u0, p.x()); r.v0 = std::min(r.v0, p.y());
  r.u1 = std::max(r.u1, p.x()); r.v1 = std::max(r.v1, p.y());
}

/// One façade's openings as they are found: rectangles (u, v) and the openings made of them,
/// in step (openings[first + q] is made of rects[q]).
struct FacadeOpenings {
  const PlanarPolygon& f;
  int facade;              ///< index into the input planes
  Eigen::Vector3d view;    ///< the side the façade was seen from
  std::vector<Rect> rects;
  std::vector<Opening>& openings;
  std::size_t first;

  void add(const Rect& r, std::size_t evidence) {
    rects.push_back(r);
    openings.push_back(makeOpening(f, r, view, facade, evidence));
  }
  void replace(std::size_t q, const Rect& r) {
    rects[q] = r;
    openings[first + q] = makeOpening(f, r, view, facade, openings[first + q].evidence_count);
  }
};

/// Ray-traced openings: components -> vertical bounding rectangles -> snapped to the wall.
void addRayOpenings(FacadeOpenings& out, const PointCloud& cloud,
                    const std::vector<Eigen::Vector2d>& evidence,
                    const OpeningDetectionParams& params) {
  std::vector<Eigen::Vector2d> wall;
  for (auto i : out.f.inliers)
    if (i < cloud.size()) wall.push_back(out.f.to2d(cloud.world(i)));
  const auto reveal = evidence.empty() ? std::vector<Eigen::Vector2d>{} : revealPoints(cloud, out.f, out.view);
  for (const auto& comp : gridComponents(evidence, params.link_distance)) {
    if (comp.size() < static_cast<std::size_t>(params.min_evidence)) continue;
    Rect r = kEmptyRect;
    for (auto c : comp) extend(r, evidence[c]);
    r = snapToReveals(snapToWall(r, wall, params.snap_distance, params.max_width, params.max_height), reveal, 0.1);
    if (!sizeOk(r, params)) continue;
    out.add(r, comp.size());
  }
}

/// `x` with each side moved out to the hole's side where the hole reaches more than `gap`
/// beyond it.
Rect widenToHole(const Rect& x, const Rect& hole, double gap) {
  Rect merged = x;
  if (hole.u0 < x.u0 - gap) merged.u0 = hole.u0;
  if (hole.u1 > x.u1 + gap) merged.u1 = hole.u1;
  if (hole.v0 < x.v0 - gap) merged.v0 = hole.v0;
  if (hole.v1 > x.v1 + gap) merged.v1 = hole.v1;
  return merged;
}

/// Holes of the wall polygon (indoor side, or no sensor origins).
void addHoleOpenings(FacadeOpenings& out, const OpeningDetectionParams& params) {
  for (std::size_t h = 1; h < out.f.rings.size(); ++h) {
    Rect r = kEmptyRect;
    for (const auto& p : out.f.rings[h]) extend(r, p);
    if (!sizeOk(r, params)) continue;
    // A hole overlapping a ray-traced opening completes it where the evidence stops short
    // (indoor rays leaving upwards hit nothing): such sides move out to the hole's side.
    bool dup = false;
    for (std::size_t q = 0; q < out.rects.size(); ++q) {
      if (overlap(out.rects[q], r) <= 0.1) continue;
      dup = true;
      // Farther than the wall snap could reach.
      const Rect merged = widenToHole(out.rects[q], r, params.snap_distance);
      if (merged.area() > out.rects[q].area()) out.replace(q, merged);
    }
    if (dup) continue;
    out.add(r, out.f.rings[h].size());
  }
}

/// Explains when the cloud cannot be ray traced (an error when ray tracing was required).
void checkRaySource(bool has_origins, const OpeningDetectionParams& params,
                    OpeningDetectionResult& result) {
  const bool want_rays = params.source != OpeningSource::Holes;
  if (params.source == OpeningSource::RayTracing && !has_origins)
    throw InputError("ray tracing cannot run: the cloud has no sensor origins (per-point origins "
                     "or scan poses are needed to know where each ray came from)");
  if (want_rays && !has_origins)
    result.messages.push_back("ray tracing cannot run: the cloud has no sensor origins; "
                              "openings come from holes in wall polygons only");
}

}  // namespace

OpeningDetectionResult detectOpenings(const PointCloud& cloud,
                                      const std::vector<PlanarPolygon>& planes,
                                      const OpeningDetectionParams& params, Progress* progress) {
  validateParams(OpeningDetectionParams::schema(), params);
  OpeningDetectionResult result;
  result.facades = selectFacades(planes, params.vertical_tolerance_deg, params.min_facade_area);
  const bool has_origins = cloud.hasSensorOrigins();
  checkRaySource(has_origins, params, result);
  const Facades facades{planes, result.facades};
  const std::size_t nf = facades.size();
  // Which side each façade was seen from.
  const CloudMeans means = cloudMeans(cloud, has_origins);
  std::vector<Eigen::Vector3d> view(nf);
  for (std::size_t k = 0; k < nf; ++k) view[k] = viewNormal(cloud, facades[k], means, has_origins);
  std::vector<std::vector<Eigen::Vector2d>> evidence(nf);
  if (params.source != OpeningSource::Holes && has_origins && nf > 0) {
    result.ray_tracing_ran = true;
    RayEvidence rays = traceRays(cloud, facades, params.min_depth);
    evidence = std::move(rays.per_facade);
    result.interior_points = std::move(rays.interior_points);
    result.evidence_count = result.interior_points.size();
    reportProgress(progress, 0.6, "ray tracing");
  }
  checkCanceled(progress);
  for (std::size_t k = 0; k < nf; ++k) {
    FacadeOpenings out{facades[k], result.facades[k], view[k], {}, result.openings,
                       result.openings.size()};
    addRayOpenings(out, cloud, evidence[k], params);
    if (params.source != OpeningSource::RayTracing) addHoleOpenings(out, params);
  }
  reportProgress(progress, 1.0, "openings");
  return result;
}

}  // namespace plumb
