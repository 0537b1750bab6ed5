// Contour lines of a rasterised patch (patch_lines.hpp).
#include "features/segments/patch_lines.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace plumb::segments_detail {
namespace {

/// Mean and principal direction of a region's pixels.
void regionLine(const LineRegion& r, Eigen::Vector2d& mean, Eigen::Vector2d& dir) {
  mean = r.sum / double(r.pixels.size());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(r.outer / double(r.pixels.size()) - mean * mean.transpose());
  dir = eig.eigenvectors().col(1);
}

/// Adds to the region the 8-neighbours of pixel q that fit the line (p0, d).
void takeNeighbours(const PatchRaster& raster, const BoundaryPixels& bd, const Eigen::Vector2i& q,
                    const Eigen::Vector2d& p0, const Eigen::Vector2d& d, double cos_dir, double tol_px,
                    std::vector<char>& used, LineRegion& region) {
  for (int dj = -1; dj <= 1; ++dj)
    for (int di = -1; di <= 1; ++di) {
      const int i = q.x() + di, j = q.y() + dj;
      if (i < 0 || j < 0 || i >= raster.W || j >= raster.H) continue;
      const int b = bd.index[raster.at(i, j)];
      if (b < 0 || used[b]) continue;
      if (std::abs(bd.dir[b].dot(d)) < cos_dir) continue;
      const Eigen::Vector2d r = bd.pixels[b].cast<double>() - p0;
      if (std::abs(r.x() * d.y() - r.y() * d.x()) > tol_px) continue;
      used[b] = 1;
      region.pixels.push_back(b);
      const Eigen::Vector2d pb = bd.pixels[b].cast<double>();
      region.sum += pb;
      region.outer += pb * pb.transpose();
    }
}

/// Unit normal of the line direction d pointing to the empty side (majority of the region's
/// pixels, one step across).
Eigen::Vector2d outwardNormal(const PatchRaster& raster, const BoundaryPixels& bd, const LineRegion& region,
                              const Eigen::Vector2d& d) {
  Eigen::Vector2d out(-d.y(), d.x());
  int votes = 0;
  for (int b : region.pixels) {
    const auto q = bd.pixels[b];
    const int i = q.x() + int(std::lround(out.x())), j = q.y() + int(std::lround(out.y()));
    votes += raster.mask[raster.at(i, j)] ? -1 : 1;
  }
  return votes < 0 ? Eigen::Vector2d(-out) : out;
}

}  // namespace

LineRegion growLineRegion(const PatchRaster& raster, const BoundaryPixels& bd, int seed, double cos_dir,
                          double tol_px, std::vector<char>& used) {
  LineRegion region;
  region.pixels.push_back(seed);
  used[seed] = 1;
  Eigen::Vector2d p0 = bd.pixels[seed].cast<double>(), d = bd.dir[seed];
  region.sum = p0;
  region.outer = p0 * p0.transpose();
  std::size_t refit = 4;
  for (std::size_t k = 0; k < region.pixels.size(); ++k) {
    takeNeighbours(raster, bd, bd.pixels[region.pixels[k]], p0, d, cos_dir, tol_px, used, region);
    if (region.pixels.size() >= refit) {
      regionLine(region, p0, d);
      refit *= 2;
    }
  }
  return region;
}

std::optional<Line2> fitRegionLine(const PatchRaster& raster, const BoundaryPixels& bd, const LineRegion& region) {
  Eigen::Vector2d m, d;
  regionLine(region, m, d);
  const Eigen::Vector2d out = outwardNormal(raster, bd, region, d);
  // Extent (pixel centres) and outermost point offset from the points in those pixels.
  double t0 = 1e300, t1 = -1e300;
  for (int b : region.pixels) {
    const double t = (bd.pixels[b].cast<double>() - m).dot(d);
    t0 = std::min(t0, t);
    t1 = std::max(t1, t);
  }
  std::vector<char> in_region(std::size_t(raster.W) * raster.H, 0);
  for (int b : region.pixels) in_region[raster.at(bd.pixels[b].x(), bd.pixels[b].y())] = 1;
  const Eigen::Vector2d mm = raster.lo + (m - Eigen::Vector2d(0.5, 0.5)) * raster.px;  // metres
  std::vector<double> offs;
  for (const auto& p : raster.uv) {
    auto [i, j] = raster.pixel(p);
    if (in_region[raster.at(i, j)]) offs.push_back((p - mm).dot(out));
  }
  if (offs.size() < 3) return std::nullopt;
  const std::size_t q = offs.size() * 9 / 10;
  std::nth_element(offs.begin(), offs.begin() + q, offs.end());
  const double off = offs[q];
  const Eigen::Vector2d base = mm + off * out;
  Line2 line;
  line.a = base + t0 * raster.px * d;
  line.b = base + t1 * raster.px * d;
  line.support = double(offs.size());
  return line;
}

std::vector<Line2> patchLines(const PointCloud& cloud, const Patch& patch, const PlanarPolygon& frame,
                              const SegmentDetectionParams& params) {
  PatchRaster raster;
  if (!rasterisePatch(cloud, patch, frame, params.pixel_size, raster)) return {};
  const BoundaryPixels bd = boundaryPixels(raster);
  const auto& lin = bd.linearity;
  // Greedy line-support regions, most linear pixels first.
  std::vector<int> order(bd.pixels.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return lin[a] > lin[b]; });
  std::vector<char> used(bd.pixels.size(), 0);
  const double cos_dir = std::cos(params.line_angle_deg * M_PI / 180.0);
  const double tol_px = params.split_tolerance_px;
  const int min_pixels = std::max(5, int(params.min_length / raster.px * 0.5));
  std::vector<Line2> lines;
  for (int seed : order) {
    if (used[seed] || lin[seed] < params.min_linearity) continue;
    const LineRegion region = growLineRegion(raster, bd, seed, cos_dir, tol_px, used);
    if (static_cast<int>(region.pixels.size()) < min_pixels) continue;
    if (const auto line = fitRegionLine(raster, bd, region)) lines.push_back(*line);
  }
  return lines;
}

}  // namespace plumb::segments_detail
