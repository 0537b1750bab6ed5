// 3D line segments (Lu, Liu, Li 2019 steps 4-7): each planar patch is rasterised in its plane,
// its boundary pixels are grouped into straight line-support regions (greedy growth along
// 8-connected boundary pixels with a direction tolerance and a distance-to-line tolerance),
// each region gets a least-squares line whose offset is then moved to the outermost points of
// its pixels, and is lifted back to 3D. Segments on the junction of two patches are snapped
// onto the intersection line of the two planes; short ones are dropped, collinear ones merged.
#include "features/segments/segment_detection.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/QR>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "common/error.hpp"
#include "features/segments/patch_lines.hpp"
#include "features/segments/voxel_patches.hpp"

namespace plumb {

const ParamSchema<SegmentDetectionParams>& SegmentDetectionParams::schema() {
  using P = SegmentDetectionParams;
  static const auto s =
      ParamSchema<P>("segments")
          .real(&P::voxel_size, "voxel-size", "Voxel size", "m", 0.005, 5,
                "grid for normals and region growing")
          .real(&P::smoothness_deg, "smoothness", "Smoothness angle", "deg", 0.1, 45,
                "max normal angle between neighbouring voxels of a patch")
          .real(&P::plane_tolerance, "plane-tolerance", "Plane tolerance", "m", 0.001, 1,
                "max point-to-plane distance in a patch")
          .real(&P::merge_angle_deg, "merge-angle", "Merge angle", "deg", 0, 30,
                "patches and segments within this angle are merged", true)
          .integer(&P::min_patch_points, "min-patch-points", "Minimum patch size", "points", 3, 1e7,
                   "Smaller planar patches give no segments")
          .real(&P::pixel_size, "pixel-size", "Pixel size", "m", 0, 1,
                "raster pixel in the patch plane (0: from the point spacing)", true)
          .real(&P::split_tolerance_px, "split-tolerance", "Straightness", "px", 0.5, 20,
                "max deviation of contour pixels from a line", true)
          .real(&P::min_length, "min-length", "Minimum length", "m", 0, 100, "Shorter segments are dropped")
          .real(&P::merge_distance, "merge-distance", "Merge distance", "m", 0, 1,
                "collinear segments closer than this are merged", true)
          .real(&P::snap_distance, "snap-distance", "Snap distance", "m", 0, 0.5,
                "snap to plane intersections within this distance (0: off)", true)
          .boolean(&P::intersections_only, "intersections-only", "Edges only",
                   "keep only segments where two planar patches meet")
          .real(&P::line_angle_deg, "line-angle", "Line angle", "deg", 1, 60,
                "boundary pixels of one line differ in direction by less than this", true)
          .real(&P::min_linearity, "min-linearity", "Min linearity", "", 0, 1,
                "lines grow from boundary pixels at least this linear", true)
          .real(&P::snap_min_angle_deg, "snap-angle", "Snap angle", "deg", 1, 89,
                "snap only onto patches meeting at more than this angle", true)
          .real(&P::snap_near_distance, "snap-near", "Snap extent distance", "m", 0.001, 0.5,
                "points within max(this, 0.4 voxel) of a snapped line bound its extent", true);
  return s;
}

namespace {

using segments_detail::Line2;
using segments_detail::Patch;

/// Distance from p to the infinite line through s.
double lineDistance(const Segment3D& s, const Eigen::Vector3d& p) {
  const Eigen::Vector3d d = s.direction();
  const Eigen::Vector3d r = p - s.a;
  return (r - r.dot(d) * d).norm();
}

/// Extent [lo, hi] (along s, from s.a) over which `points` lie next to the line of s, walking
/// out from the segment's middle while consecutive points leave no gap wider than 3 typical
/// spacings. Returns false when no point is near the middle.
bool extentAlongPoints(const PointCloud& cloud, const std::vector<std::uint32_t>& points,
                       const Segment3D& s, double near, double& lo_t, double& hi_t) {
  const Eigen::Vector3d d = s.direction();
  const double len = s.length();
  std::vector<double> t;
  for (auto i : points) {
    const Eigen::Vector3d r = cloud.positions[i].cast<double>() - s.a;
    const double along = r.dot(d);
    if ((r - along * d).squaredNorm() < near * near) t.push_back(along);
  }
  if (t.size() < 10) return false;
  std::sort(t.begin(), t.end());
  const double gap = std::max(0.05, 3.0 * len / double(t.size()));
  auto mid = std::lower_bound(t.begin(), t.end(), 0.5 * len) - t.begin();
  if (mid >= static_cast<long>(t.size()) || std::abs(t[mid] - 0.5 * len) > gap) return false;
  std::size_t lo = mid, hi = mid;
  while (lo > 0 && t[lo] - t[lo - 1] < gap) --lo;
  while (hi + 1 < t.size() && t[hi + 1] - t[hi] < gap) ++hi;
  lo_t = t[lo];
  hi_t = t[hi];
  return true;
}

/// Extends a snapped segment along the intersection over the stretch where BOTH patches have
/// points next to the line (contour pieces stop short of corners, where pixel directions are
/// mixed; one patch alone would extend a reveal edge over a whole wall).
void extendAlongPoints(const PointCloud& cloud, const std::vector<std::uint32_t>& a,
                       const std::vector<std::uint32_t>& b, double near, Segment3D& s) {
  double a0, a1, b0, b1;
  if (!extentAlongPoints(cloud, a, s, near, a0, a1) || !extentAlongPoints(cloud, b, s, near, b0, b1)) return;
  const double len = s.length();
  const double lo = std::max(a0, b0), hi = std::min(a1, b1);
  if (hi - lo < 0.5 * len) return;  // the two stretches do not agree: keep the contour extent
  const Eigen::Vector3d d = s.direction(), o = s.a;
  s.a = o + lo * d;
  s.b = o + hi * d;
}

/// Patches with a valid plane and at least min_patch_points, with their plane frames (local
/// coordinates).
struct KeptPatches {
  std::vector<int> keep_id;  ///< per patch: its number among the kept, or -1
  std::vector<int> kept;     ///< patch of each kept one
  std::vector<PlanarPolygon> frames;
};

KeptPatches keepPatches(const std::vector<Patch>& patches, const SegmentDetectionParams& params) {
  KeptPatches k;
  k.keep_id.assign(patches.size(), -1);
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (!patches[p].fit.valid || patches[p].points.size() < std::size_t(params.min_patch_points)) continue;
    k.keep_id[p] = static_cast<int>(k.kept.size());
    k.kept.push_back(static_cast<int>(p));
    PlanarPolygon f;
    f.normal = patches[p].fit.normal;
    f.offset = patches[p].fit.offset;
    f.centroid = patches[p].fit.centroid;
    f.inlier_count = patches[p].points.size();
    setPlaneFrame(f);
    k.frames.push_back(f);
  }
  return k;
}

struct Cand {
  Segment3D s;
  bool snapped = false;
};

/// s projected on the intersection line of planes A and B.
Segment3D onIntersection(const PlanarPolygon& A, const PlanarPolygon& B, const Segment3D& s) {
  const Eigen::Vector3d dir = A.normal.cross(B.normal).normalized();
  Eigen::Matrix3d M;
  M.row(0) = A.normal.transpose();
  M.row(1) = B.normal.transpose();
  M.row(2) = dir.transpose();
  const Eigen::Vector3d p0 = M.colPivHouseholderQr().solve(Eigen::Vector3d(A.offset, B.offset, 0.0));
  Segment3D snapped = s;
  snapped.a = p0 + (s.a - p0).dot(dir) * dir;
  snapped.b = p0 + (s.b - p0).dot(dir) * dir;
  return snapped;
}

/// Line l of kept patch k lifted to 3D and, when a neighbouring kept patch meets it at more
/// than 20 degrees with both ends within snap_distance (the nearest such patch), snapped onto
/// their intersection and extended along the points of both.
Cand liftAndSnap(const PointCloud& cloud, const std::vector<Patch>& patches, const KeptPatches& kp, std::size_t k,
                 const Line2& l, const SegmentDetectionParams& params) {
  const double cos20 = std::cos(params.snap_min_angle_deg * M_PI / 180.0);
  // "Next to the line": 3 cm, or more on coarse voxel grids (sparse scans).
  const double near = std::max(params.snap_near_distance, 0.4 * params.voxel_size);
  const auto& A = kp.frames[k];
  Cand c;
  c.s.a = A.to3d(l.a);
  c.s.b = A.to3d(l.b);
  c.s.support = l.support;
  if (!(params.snap_distance > 0)) return c;
  int partner = -1;
  double best = params.snap_distance;
  for (int nbp : patches[kp.kept[k]].neighbours) {
    const int j = kp.keep_id[nbp];
    if (j < 0) continue;
    const auto& B = kp.frames[j];
    if (std::abs(A.normal.dot(B.normal)) > cos20) continue;
    const double da = std::abs(B.signedDistance(c.s.a)), db = std::abs(B.signedDistance(c.s.b));
    const double worst = std::max(da, db);
    if (worst >= best) continue;
    const Segment3D snapped = onIntersection(A, B, c.s);
    // B must really border the segment (points next to it), not just its infinite plane.
    double b0, b1;
    if (!extentAlongPoints(cloud, patches[nbp].points, snapped, near, b0, b1)) continue;
    best = worst;
    c.s.a = snapped.a;
    c.s.b = snapped.b;
    c.snapped = true;
    partner = nbp;
  }
  if (c.snapped) extendAlongPoints(cloud, patches[kp.kept[k]].points, patches[partner].points, near, c.s);
  return c;
}

/// Extends cands[i] by cands[j] when they are collinear and overlap; true when it did. d is
/// cands[i]'s direction at the start of the current merging pass.
bool absorb(std::vector<Cand>& cands, std::size_t i, std::size_t j, const Eigen::Vector3d& d, double cos_merge,
            double merge_distance) {
  auto& s = cands[i].s;
  const auto& t = cands[j].s;
  if (std::abs(t.direction().dot(d)) < cos_merge) return false;
  if (lineDistance(s, t.a) > merge_distance || lineDistance(s, t.b) > merge_distance) return false;
  double ta = (t.a - s.a).dot(d), tb = (t.b - s.a).dot(d);
  if (ta > tb) std::swap(ta, tb);
  const double L = s.length();
  if (tb < -merge_distance || ta > L + merge_distance) return false;  // no overlap
  // Prefer the snapped line's position; extend to the union.
  const Eigen::Vector3d o = s.a;
  const double lo = std::min(0.0, ta), hi = std::max(L, tb);
  if (!cands[i].snapped && cands[j].snapped) {
    const Eigen::Vector3d td = t.direction();
    const Eigen::Vector3d p = t.a;
    auto proj = [&](const Eigen::Vector3d& x) { return p + (x - p).dot(td) * td; };
    s.a = proj(o + lo * d);
    s.b = proj(o + hi * d);
    cands[i].snapped = true;
  } else {
    s.a = o + lo * d;
    s.b = o + hi * d;
  }
  s.support += t.support;
  return true;
}

/// Merges collinear overlapping candidates, longest first; returns which were absorbed.
std::vector<char> mergeCollinear(std::vector<Cand>& cands, const SegmentDetectionParams& params) {
  std::stable_sort(cands.begin(), cands.end(), [](const Cand& x, const Cand& y) { return x.s.length() > y.s.length(); });
  const double cos_merge = std::cos(std::max(params.merge_angle_deg, 0.5) * M_PI / 180.0);
  std::vector<char> gone(cands.size(), 0);
  for (std::size_t i = 0; i < cands.size(); ++i) {
    if (gone[i]) continue;
    bool grew = true;
    while (grew) {
      grew = false;
      const Eigen::Vector3d d = cands[i].s.direction();
      for (std::size_t j = i + 1; j < cands.size(); ++j) {
        if (gone[j] || !absorb(cands, i, j, d, cos_merge, params.merge_distance)) continue;
        gone[j] = 1;
        grew = true;
      }
    }
  }
  return gone;
}

/// The result: surviving segments long enough (and snapped, with intersections_only) in world
/// coordinates, longest first; patches in world coordinates and the patch of each point.
void fillResult(const PointCloud& cloud, const std::vector<Patch>& patches, const KeptPatches& kp,
                const std::vector<Cand>& cands, const std::vector<char>& gone, const SegmentDetectionParams& params,
                SegmentDetectionResult& result) {
  for (std::size_t i = 0; i < cands.size(); ++i) {
    if (gone[i] || cands[i].s.length() < params.min_length) continue;
    if (params.intersections_only && !cands[i].snapped) continue;
    Segment3D s = cands[i].s;
    s.a += cloud.offset;
    s.b += cloud.offset;
    result.segments.push_back(s);
  }
  std::stable_sort(result.segments.begin(), result.segments.end(),
                   [](const Segment3D& x, const Segment3D& y) { return x.length() > y.length(); });
  for (std::size_t k = 0; k < kp.kept.size(); ++k) {
    PlanarPolygon f = kp.frames[k];
    f.offset += f.normal.dot(cloud.offset);
    f.centroid += cloud.offset;
    f.origin += cloud.offset;
    result.patches.push_back(f);
    for (auto i : patches[kp.kept[k]].points) result.point_patch[i] = static_cast<int>(k);
  }
}

}  // namespace

SegmentDetectionResult detectSegments(const PointCloud& cloud, const SegmentDetectionParams& params,
                                      Progress* progress) {
  const auto start = std::chrono::steady_clock::now();
  validateParams(SegmentDetectionParams::schema(), params);
  SegmentDetectionResult result;
  result.point_patch.assign(cloud.size(), -1);
  Progress sub = progress ? progress->sub(0.0, 0.6) : Progress();
  const auto patches = segments_detail::growPatches(cloud, params, progress ? &sub : nullptr);
  checkCanceled(progress);
  const KeptPatches kp = keepPatches(patches, params);
  // Lines per patch (parallel, results kept in patch order).
  std::vector<std::vector<Line2>> lines(kp.kept.size());
  tbb::parallel_for(std::size_t(0), kp.kept.size(), [&](std::size_t k) {
    lines[k] = segments_detail::patchLines(cloud, patches[kp.kept[k]], kp.frames[k], params);
  });
  reportProgress(progress, 0.85, "segments");
  checkCanceled(progress);
  // Lift to 3D (local), snap to intersections with adjacent patches.
  std::vector<Cand> cands;
  for (std::size_t k = 0; k < kp.kept.size(); ++k)
    for (const auto& l : lines[k]) {
      Cand c = liftAndSnap(cloud, patches, kp, k, l, params);
      if (c.s.length() > 0) cands.push_back(c);
    }
  const std::vector<char> gone = mergeCollinear(cands, params);
  fillResult(cloud, patches, kp, cands, gone, params, result);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  reportProgress(progress, 1.0, "segments");
  return result;
}

}  // namespace plumb
