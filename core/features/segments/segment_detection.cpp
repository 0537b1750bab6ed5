// 3D line segments (Lu, Liu, Li 2019 steps 4-7): each planar patch is rasterised in its plane,
// its boundary pixels are grouped into straight line-support regions (greedy growth along
// 8-connected boundary pixels with a direction tolerance and a distance-to-line tolerance),
// each region gets a least-squares line whose offset is then moved to the outermost points of
// its pixels, and is lifted back to 3D. Segments on the junction of two patches are snapped
// onto the intersection line of the two planes; short ones are dropped, collinear ones merged.
#include "features/segments/segment_detection.hpp"

#include <tbb/parallel_for.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>

#include "common/error.hpp"
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
          .integer(&P::min_patch_points, "min-patch-points", "Minimum patch size", "points", 3, 1e7, "")
          .real(&P::pixel_size, "pixel-size", "Pixel size", "m", 0, 1,
                "raster pixel in the patch plane (0: from the point spacing)", true)
          .real(&P::split_tolerance_px, "split-tolerance", "Straightness", "px", 0.5, 20,
                "max deviation of contour pixels from a line", true)
          .real(&P::min_length, "min-length", "Minimum length", "m", 0, 100, "")
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

using segments_detail::Patch;

struct Line2 {
  Eigen::Vector2d a, b;
  double support = 0;
};

/// Contour lines of one patch, in its (u,v) frame (local coordinates of the cloud).
std::vector<Line2> patchLines(const PointCloud& cloud, const Patch& patch, const PlanarPolygon& frame,
                              const SegmentDetectionParams& params) {
  const std::size_t n = patch.points.size();
  std::vector<Eigen::Vector2d> uv(n);
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (std::size_t k = 0; k < n; ++k) {
    uv[k] = frame.to2d(cloud.positions[patch.points[k]].cast<double>());
    lo = lo.cwiseMin(uv[k]);
    hi = hi.cwiseMax(uv[k]);
  }
  double px = params.pixel_size;
  if (px <= 0) {
    // Spacing from the area covered at 10 cm: 1.5 x sqrt(area / n).
    const double c = 0.1;
    const int cu = int((hi.x() - lo.x()) / c) + 1, cv = int((hi.y() - lo.y()) / c) + 1;
    std::vector<char> occ(std::size_t(cu) * cv, 0);
    for (const auto& p : uv) occ[std::size_t(int((p.y() - lo.y()) / c)) * cu + int((p.x() - lo.x()) / c)] = 1;
    const double area = std::count(occ.begin(), occ.end(), 1) * c * c;
    px = std::clamp(1.5 * std::sqrt(area / double(n)), 0.005, 0.2);
  }
  const int W = int((hi.x() - lo.x()) / px) + 3, H = int((hi.y() - lo.y()) / px) + 3;
  if (double(W) * H > 6e7) return {};
  auto pix = [&](const Eigen::Vector2d& p) {
    return std::pair<int, int>(int((p.x() - lo.x()) / px) + 1, int((p.y() - lo.y()) / px) + 1);
  };
  std::vector<int> count(std::size_t(W) * H, 0);
  for (const auto& p : uv) {
    auto [i, j] = pix(p);
    ++count[std::size_t(j) * W + i];
  }
  // Closing (3x3 dilate then erode) fills pixel-size gaps of the sampling.
  std::vector<char> occ(std::size_t(W) * H, 0), dil(std::size_t(W) * H, 0), mask(std::size_t(W) * H, 0);
  for (std::size_t k = 0; k < occ.size(); ++k) occ[k] = count[k] > 0;
  for (int j = 1; j + 1 < H; ++j)
    for (int i = 1; i + 1 < W; ++i) {
      bool any = false;
      for (int dj = -1; dj <= 1 && !any; ++dj)
        for (int di = -1; di <= 1 && !any; ++di) any = occ[std::size_t(j + dj) * W + i + di];
      dil[std::size_t(j) * W + i] = any;
    }
  for (int j = 1; j + 1 < H; ++j)
    for (int i = 1; i + 1 < W; ++i) {
      bool all = true;
      for (int dj = -1; dj <= 1 && all; ++dj)
        for (int di = -1; di <= 1 && all; ++di) all = dil[std::size_t(j + dj) * W + i + di];
      mask[std::size_t(j) * W + i] = all || occ[std::size_t(j) * W + i];
    }
  // Boundary pixels: occupied with an empty 4-neighbour.
  std::vector<int> bidx(std::size_t(W) * H, -1);
  std::vector<Eigen::Vector2i> bpix;
  for (int j = 1; j + 1 < H; ++j)
    for (int i = 1; i + 1 < W; ++i) {
      const std::size_t k = std::size_t(j) * W + i;
      if (!mask[k]) continue;
      if (!mask[k - 1] || !mask[k + 1] || !mask[k - W] || !mask[k + W]) {
        bidx[k] = static_cast<int>(bpix.size());
        bpix.emplace_back(i, j);
      }
    }
  // Local direction of each boundary pixel (PCA of boundary pixels in a 7x7 window).
  const std::size_t nb = bpix.size();
  std::vector<Eigen::Vector2d> dir(nb, Eigen::Vector2d::Zero());
  std::vector<double> lin(nb, 0.0);
  for (std::size_t b = 0; b < nb; ++b) {
    Eigen::Vector2d s = Eigen::Vector2d::Zero();
    Eigen::Matrix2d o = Eigen::Matrix2d::Zero();
    int c = 0;
    for (int dj = -3; dj <= 3; ++dj)
      for (int di = -3; di <= 3; ++di) {
        const int i = bpix[b].x() + di, j = bpix[b].y() + dj;
        if (i < 0 || j < 0 || i >= W || j >= H || bidx[std::size_t(j) * W + i] < 0) continue;
        const Eigen::Vector2d q(di, dj);
        s += q;
        o += q * q.transpose();
        ++c;
      }
    if (c < 3) continue;
    const Eigen::Vector2d m = s / c;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(o / c - m * m.transpose());
    dir[b] = eig.eigenvectors().col(1);
    lin[b] = eig.eigenvalues()(1) > 0 ? 1.0 - eig.eigenvalues()(0) / eig.eigenvalues()(1) : 0.0;
  }
  // Greedy line-support regions, most linear pixels first.
  std::vector<int> order(nb);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return lin[a] > lin[b]; });
  std::vector<char> used(nb, 0);
  const double cos_dir = std::cos(params.line_angle_deg * M_PI / 180.0);
  const double tol_px = params.split_tolerance_px;
  const int min_pixels = std::max(5, int(params.min_length / px * 0.5));
  std::vector<Line2> lines;
  for (int seed : order) {
    if (used[seed] || lin[seed] < params.min_linearity) continue;
    std::vector<int> region{seed};
    used[seed] = 1;
    Eigen::Vector2d p0 = bpix[seed].cast<double>(), d = dir[seed];
    Eigen::Vector2d s = p0;
    Eigen::Matrix2d o = p0 * p0.transpose();
    std::size_t refit = 4;
    for (std::size_t k = 0; k < region.size(); ++k) {
      const auto q = bpix[region[k]];
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int i = q.x() + di, j = q.y() + dj;
          if (i < 0 || j < 0 || i >= W || j >= H) continue;
          const int b = bidx[std::size_t(j) * W + i];
          if (b < 0 || used[b]) continue;
          if (std::abs(dir[b].dot(d)) < cos_dir) continue;
          const Eigen::Vector2d r = bpix[b].cast<double>() - p0;
          if (std::abs(r.x() * d.y() - r.y() * d.x()) > tol_px) continue;
          used[b] = 1;
          region.push_back(b);
          const Eigen::Vector2d pb = bpix[b].cast<double>();
          s += pb;
          o += pb * pb.transpose();
        }
      if (region.size() >= refit) {
        const Eigen::Vector2d m = s / double(region.size());
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(o / double(region.size()) - m * m.transpose());
        p0 = m;
        d = eig.eigenvectors().col(1);
        refit *= 2;
      }
    }
    if (static_cast<int>(region.size()) < min_pixels) continue;
    const Eigen::Vector2d m = s / double(region.size());
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(o / double(region.size()) - m * m.transpose());
    d = eig.eigenvectors().col(1);
    // Outward in-plane normal: towards the empty side.
    Eigen::Vector2d out(-d.y(), d.x());
    int votes = 0;
    for (int b : region) {
      const auto q = bpix[b];
      const int i = q.x() + int(std::lround(out.x())), j = q.y() + int(std::lround(out.y()));
      votes += mask[std::size_t(j) * W + i] ? -1 : 1;
    }
    if (votes < 0) out = -out;
    // Extent (pixel centres) and outermost point offset from the points in those pixels.
    double t0 = 1e300, t1 = -1e300;
    for (int b : region) {
      const double t = (bpix[b].cast<double>() - m).dot(d);
      t0 = std::min(t0, t);
      t1 = std::max(t1, t);
    }
    std::vector<char> in_region(std::size_t(W) * H, 0);
    for (int b : region) in_region[std::size_t(bpix[b].y()) * W + bpix[b].x()] = 1;
    const Eigen::Vector2d mm = lo + (m - Eigen::Vector2d(0.5, 0.5)) * px;  // metres
    std::vector<double> offs;
    for (const auto& p : uv) {
      auto [i, j] = pix(p);
      if (in_region[std::size_t(j) * W + i]) offs.push_back((p - mm).dot(out));
    }
    if (offs.size() < 3) continue;
    const std::size_t q = offs.size() * 9 / 10;
    std::nth_element(offs.begin(), offs.begin() + q, offs.end());
    const double off = offs[q];
    const Eigen::Vector2d base = mm + off * out;
    Line2 line;
    line.a = base + t0 * px * d;
    line.b = base + t1 * px * d;
    line.support = double(offs.size());
    lines.push_back(line);
  }
  return lines;
}

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

}  // namespace

SegmentDetectionResult detectSegments(const PointCloud& cloud, const SegmentDetectionParams& params,
                                      Progress* progress) {
  const auto start = std::chrono::steady_clock::now();
  validateParams(SegmentDetectionParams::schema(), params);
  SegmentDetectionResult result;
  result.point_patch.assign(cloud.size(), -1);
  Progress sub = progress ? progress->sub(0.0, 0.6) : Progress();
  auto patches = segments_detail::growPatches(cloud, params, progress ? &sub : nullptr);
  checkCanceled(progress);
  // Keep patches with enough points; frames in local coordinates.
  std::vector<int> keep_id(patches.size(), -1);
  std::vector<PlanarPolygon> frames;
  std::vector<int> kept;
  for (std::size_t p = 0; p < patches.size(); ++p) {
    if (!patches[p].fit.valid || patches[p].points.size() < std::size_t(params.min_patch_points)) continue;
    keep_id[p] = static_cast<int>(kept.size());
    kept.push_back(static_cast<int>(p));
    PlanarPolygon f;
    f.normal = patches[p].fit.normal;
    f.offset = patches[p].fit.offset;
    f.centroid = patches[p].fit.centroid;
    f.inlier_count = patches[p].points.size();
    setPlaneFrame(f);
    frames.push_back(f);
  }
  // Lines per patch (parallel, results kept in patch order).
  std::vector<std::vector<Line2>> lines(kept.size());
  tbb::parallel_for(std::size_t(0), kept.size(), [&](std::size_t k) {
    lines[k] = patchLines(cloud, patches[kept[k]], frames[k], params);
  });
  reportProgress(progress, 0.85, "segments");
  checkCanceled(progress);
  // Lift to 3D (local), snap to intersections with adjacent patches.
  struct Cand {
    Segment3D s;
    bool snapped = false;
  };
  std::vector<Cand> cands;
  const double cos20 = std::cos(params.snap_min_angle_deg * M_PI / 180.0);
  // "Next to the line": 3 cm, or more on coarse voxel grids (sparse scans).
  const double near = std::max(params.snap_near_distance, 0.4 * params.voxel_size);
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const auto& A = frames[k];
    for (const auto& l : lines[k]) {
      Cand c;
      c.s.a = A.to3d(l.a);
      c.s.b = A.to3d(l.b);
      c.s.support = l.support;
      int partner = -1;
      if (params.snap_distance > 0) {
        double best = params.snap_distance;
        for (int nbp : patches[kept[k]].neighbours) {
          const int j = keep_id[nbp];
          if (j < 0) continue;
          const auto& B = frames[j];
          if (std::abs(A.normal.dot(B.normal)) > cos20) continue;
          const double da = std::abs(B.signedDistance(c.s.a)), db = std::abs(B.signedDistance(c.s.b));
          const double worst = std::max(da, db);
          if (worst >= best) continue;
          // Intersection line of A and B.
          const Eigen::Vector3d dir = A.normal.cross(B.normal).normalized();
          Eigen::Matrix3d M;
          M.row(0) = A.normal.transpose();
          M.row(1) = B.normal.transpose();
          M.row(2) = dir.transpose();
          const Eigen::Vector3d p0 = M.colPivHouseholderQr().solve(Eigen::Vector3d(A.offset, B.offset, 0.0));
          Segment3D snapped = c.s;
          snapped.a = p0 + (c.s.a - p0).dot(dir) * dir;
          snapped.b = p0 + (c.s.b - p0).dot(dir) * dir;
          // B must really border the segment (points next to it), not just its infinite plane.
          double b0, b1;
          if (!extentAlongPoints(cloud, patches[nbp].points, snapped, near, b0, b1)) continue;
          best = worst;
          c.s.a = snapped.a;
          c.s.b = snapped.b;
          c.snapped = true;
          partner = nbp;
        }
      }
      if (c.snapped) extendAlongPoints(cloud, patches[kept[k]].points, patches[partner].points, near, c.s);
      if (c.s.length() > 0) cands.push_back(c);
    }
  }
  // Merge collinear overlapping segments (longest first).
  std::stable_sort(cands.begin(), cands.end(), [](const Cand& x, const Cand& y) { return x.s.length() > y.s.length(); });
  const double cos_merge = std::cos(std::max(params.merge_angle_deg, 0.5) * M_PI / 180.0);
  std::vector<char> gone(cands.size(), 0);
  for (std::size_t i = 0; i < cands.size(); ++i) {
    if (gone[i]) continue;
    auto& s = cands[i].s;
    bool grew = true;
    while (grew) {
      grew = false;
      const Eigen::Vector3d d = s.direction();
      for (std::size_t j = i + 1; j < cands.size(); ++j) {
        if (gone[j]) continue;
        const auto& t = cands[j].s;
        if (std::abs(t.direction().dot(d)) < cos_merge) continue;
        if (lineDistance(s, t.a) > params.merge_distance || lineDistance(s, t.b) > params.merge_distance) continue;
        double ta = (t.a - s.a).dot(d), tb = (t.b - s.a).dot(d);
        if (ta > tb) std::swap(ta, tb);
        const double L = s.length();
        if (tb < -params.merge_distance || ta > L + params.merge_distance) continue;  // no overlap
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
        gone[j] = 1;
        grew = true;
      }
    }
  }
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
  for (std::size_t k = 0; k < kept.size(); ++k) {
    PlanarPolygon f = frames[k];
    f.offset += f.normal.dot(cloud.offset);
    f.centroid += cloud.offset;
    f.origin += cloud.offset;
    result.patches.push_back(f);
    for (auto i : patches[kept[k]].points) result.point_patch[i] = static_cast<int>(k);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  reportProgress(progress, 1.0, "segments");
  return result;
}

}  // namespace plumb
