// Rasterised patches and their boundary pixels (patch_raster.hpp).
#include "features/segments/patch_raster.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace plumb::segments_detail {
namespace {

/// Boundary pixels of the mask, in row order.
void findBoundary(const PatchRaster& r, BoundaryPixels& b) {
  const int W = r.W, H = r.H;
  b.index.assign(std::size_t(W) * H, -1);
  for (int j = 1; j + 1 < H; ++j)
    for (int i = 1; i + 1 < W; ++i) {
      const std::size_t k = r.at(i, j);
      if (!r.mask[k]) continue;
      if (!r.mask[k - 1] || !r.mask[k + 1] || !r.mask[k - W] || !r.mask[k + W]) {
        b.index[k] = static_cast<int>(b.pixels.size());
        b.pixels.emplace_back(i, j);
      }
    }
}

/// Direction and linearity of boundary pixel `n` from the boundary pixels of its 7x7 window.
void windowDirection(const PatchRaster& r, BoundaryPixels& b, std::size_t n) {
  Eigen::Vector2d s = Eigen::Vector2d::Zero();
  Eigen::Matrix2d o = Eigen::Matrix2d::Zero();
  int c = 0;
  for (int dj = -3; dj <= 3; ++dj)
    for (int di = -3; di <= 3; ++di) {
      const int i = b.pixels[n].x() + di, j = b.pixels[n].y() + dj;
      if (i < 0 || j < 0 || i >= r.W || j >= r.H || b.index[r.at(i, j)] < 0) continue;
      const Eigen::Vector2d q(di, dj);
      s += q;
      o += q * q.transpose();
      ++c;
    }
  if (c < 3) return;
  const Eigen::Vector2d m = s / c;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(o / c - m * m.transpose());
  b.dir[n] = eig.eigenvectors().col(1);
  b.linearity[n] = eig.eigenvalues()(1) > 0 ? 1.0 - eig.eigenvalues()(0) / eig.eigenvalues()(1) : 0.0;
}

}  // namespace

double patchPixelSize(const std::vector<Eigen::Vector2d>& uv, const Eigen::Vector2d& lo,
                      const Eigen::Vector2d& hi, double requested) {
  if (!(requested <= 0)) return requested;
  // Spacing from the area covered at 10 cm: 1.5 x sqrt(area / n).
  const double c = 0.1;
  const int cu = int((hi.x() - lo.x()) / c) + 1, cv = int((hi.y() - lo.y()) / c) + 1;
  std::vector<char> occ(std::size_t(cu) * cv, 0);
  for (const auto& p : uv) occ[std::size_t(int((p.y() - lo.y()) / c)) * cu + int((p.x() - lo.x()) / c)] = 1;
  const double area = std::count(occ.begin(), occ.end(), 1) * c * c;
  return std::clamp(1.5 * std::sqrt(area / double(uv.size())), 0.005, 0.2);
}

bool rasterisePatch(const PointCloud& cloud, const Patch& patch, const PlanarPolygon& frame,
                    double pixel_size, PatchRaster& r) {
  const std::size_t n = patch.points.size();
  r.uv.resize(n);
  Eigen::Vector2d lo(1e300, 1e300), hi(-1e300, -1e300);
  for (std::size_t k = 0; k < n; ++k) {
    r.uv[k] = frame.to2d(cloud.positions[patch.points[k]].cast<double>());
    lo = lo.cwiseMin(r.uv[k]);
    hi = hi.cwiseMax(r.uv[k]);
  }
  r.lo = lo;
  r.px = patchPixelSize(r.uv, lo, hi, pixel_size);
  r.W = int((hi.x() - lo.x()) / r.px) + 3;
  r.H = int((hi.y() - lo.y()) / r.px) + 3;
  if (double(r.W) * r.H > 6e7) return false;
  r.occupied.assign(std::size_t(r.W) * r.H, 0);
  for (const auto& p : r.uv) {
    auto [i, j] = r.pixel(p);
    r.occupied[r.at(i, j)] = 1;
  }
  r.mask = closeMask(r.occupied, r.W, r.H);
  return true;
}

std::vector<char> closeMask(const std::vector<char>& occ, int W, int H) {
  std::vector<char> dil(std::size_t(W) * H, 0), mask(std::size_t(W) * H, 0);
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
  return mask;
}

BoundaryPixels boundaryPixels(const PatchRaster& r) {
  BoundaryPixels b;
  findBoundary(r, b);
  b.dir.assign(b.pixels.size(), Eigen::Vector2d::Zero());
  b.linearity.assign(b.pixels.size(), 0.0);
  for (std::size_t n = 0; n < b.pixels.size(); ++n) windowDirection(r, b, n);
  return b;
}

}  // namespace plumb::segments_detail
