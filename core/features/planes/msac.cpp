// MSAC plane extraction (2021 §2.2): cost sum_i min(e_i^2, t^2) (eq. 2), best plane refitted
// by least squares on its inliers, inliers removed, repeated until the best plane is smaller
// than min_inliers. For speed, hypotheses are scored on a random subset of the remaining
// points; half of the hypotheses draw their 2nd and 3rd points near the first (a coarse voxel
// of the subset), which finds small planes that global triples almost never hit.
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <unordered_map>

#include "common/error.hpp"
#include "features/planes/detected_plane.hpp"

namespace plumb::planes_detail {
namespace {

struct Hypothesis {
  Eigen::Vector3f n;
  float d = 0;
  bool valid = false;
};

Hypothesis planeThrough(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                        const Eigen::Vector3f& c) {
  Hypothesis h;
  Eigen::Vector3f n = (b - a).cross(c - a);
  const float len = n.norm();
  if (!(len > 1e-9f)) return h;
  h.n = n / len;
  h.d = h.n.dot(a);
  h.valid = true;
  return h;
}

std::uint64_t voxelKey(const Eigen::Vector3f& p, float cell) {
  auto q = [cell](float v) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / cell)) + (1 << 20)) & 0x1FFFFF; };
  return (q(p.x()) << 42) | (q(p.y()) << 21) | q(p.z());
}

/// Inliers of the plane among `active`, in order.
std::vector<std::uint32_t> inliersOf(const PointCloud& cloud,
                                     const std::vector<std::uint32_t>& active,
                                     const Eigen::Vector3d& n, double d, double t) {
  const std::size_t n_blocks = std::max<std::size_t>(1, active.size() / 65536);
  std::vector<std::vector<std::uint32_t>> parts(n_blocks);
  const Eigen::Vector3f nf = n.cast<float>();
  tbb::parallel_for(std::size_t(0), n_blocks, [&](std::size_t b) {
    const std::size_t begin = active.size() * b / n_blocks;
    const std::size_t end = active.size() * (b + 1) / n_blocks;
    auto& out = parts[b];
    for (std::size_t k = begin; k < end; ++k) {
      const auto i = active[k];
      if (std::abs(double(nf.dot(cloud.positions[i])) - d) < t) out.push_back(i);
    }
  });
  std::vector<std::uint32_t> all;
  for (auto& p : parts) all.insert(all.end(), p.begin(), p.end());
  return all;
}

/// Score subset (deterministic for the seed): every active point when there are at most
/// `size`, else `size` drawn with replacement.
std::vector<Eigen::Vector3f> drawSample(const PointCloud& cloud,
                                        const std::vector<std::uint32_t>& active, int size,
                                        std::mt19937_64& rng) {
  std::vector<Eigen::Vector3f> sample;
  const std::size_t s = std::min<std::size_t>(active.size(), size);
  sample.reserve(s);
  if (s == active.size()) {
    for (auto i : active) sample.push_back(cloud.positions[i]);
  } else {
    std::uniform_int_distribution<std::size_t> pick(0, active.size() - 1);
    for (std::size_t k = 0; k < s; ++k) sample.push_back(cloud.positions[active[pick(rng)]]);
  }
  return sample;
}

/// The sample's points grouped by coarse voxel (for local draws).
struct SampleCells {
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells;
  std::vector<std::uint64_t> cell_of;  ///< per sample point

  SampleCells(const std::vector<Eigen::Vector3f>& sample, float cell) : cell_of(sample.size()) {
    for (std::size_t k = 0; k < sample.size(); ++k) {
      cell_of[k] = voxelKey(sample[k], cell);
      cells[cell_of[k]].push_back(static_cast<std::uint32_t>(k));
    }
  }
};

/// `iterations` plane hypotheses through three sample points (up to 10 draws each): even ones
/// draw the 2nd and 3rd point in the first one's voxel, odd ones anywhere in the sample.
std::vector<Hypothesis> drawHypotheses(const std::vector<Eigen::Vector3f>& sample,
                                       SampleCells& local, int iterations, std::mt19937_64& rng) {
  std::vector<Hypothesis> hyps(iterations);
  std::uniform_int_distribution<std::size_t> pick_s(0, sample.size() - 1);
  for (int h = 0; h < iterations; ++h) {
    for (int attempt = 0; attempt < 10 && !hyps[h].valid; ++attempt) {
      const std::size_t a = pick_s(rng);
      std::size_t b, c;
      if (h % 2 == 0) {
        const auto& cell = local.cells[local.cell_of[a]];
        if (cell.size() < 3) continue;
        std::uniform_int_distribution<std::size_t> pc(0, cell.size() - 1);
        b = cell[pc(rng)];
        c = cell[pc(rng)];
      } else {
        b = pick_s(rng);
        c = pick_s(rng);
      }
      if (a == b || b == c || a == c) continue;
      hyps[h] = planeThrough(sample[a], sample[b], sample[c]);
    }
  }
  return hyps;
}

/// Index of the hypothesis of least eq. (2) cost over the sample (scored in parallel), or -1
/// when none is valid.
std::ptrdiff_t cheapestHypothesis(const std::vector<Hypothesis>& hyps,
                                  const std::vector<Eigen::Vector3f>& sample, float t2) {
  std::vector<double> cost(hyps.size(), std::numeric_limits<double>::infinity());
  tbb::parallel_for(std::size_t(0), hyps.size(), [&](std::size_t h) {
    if (!hyps[h].valid) return;
    const auto& hy = hyps[h];
    double c = 0;
    for (const auto& p : sample) {
      const float e = hy.n.dot(p) - hy.d;
      c += std::min(e * e, t2);
    }
    cost[h] = c;
  });
  const auto best = std::min_element(cost.begin(), cost.end()) - cost.begin();
  return std::isfinite(cost[best]) ? best : -1;
}

/// Inliers of the hypothesis among all remaining points, refitted by least squares; the refit
/// is kept only while it gains inliers (a hypothesis across a corner must not drift away).
DetectedPlane refitOnInliers(const PointCloud& cloud, const std::vector<std::uint32_t>& active,
                             const Hypothesis& hyp, double threshold) {
  DetectedPlane plane;
  Eigen::Vector3d n = hyp.n.cast<double>();
  double d = hyp.d;
  plane.inliers = inliersOf(cloud, active, n, d, threshold);
  plane.fit.normal = n;
  plane.fit.offset = d;
  for (int round = 0; round < 3 && plane.inliers.size() >= 3; ++round) {
    const PlaneFit fit = fitPlaneLocal(cloud, plane.inliers);
    if (!fit.valid) break;
    auto refit = inliersOf(cloud, active, fit.normal, fit.offset, threshold);
    if (refit.size() < plane.inliers.size()) break;
    const bool same = refit.size() == plane.inliers.size();
    plane.inliers.swap(refit);
    plane.fit = fit;
    if (same) break;
  }
  return plane;
}

/// `active` without `removed` (both sorted by index).
void removeInliers(std::vector<std::uint32_t>& active, const std::vector<std::uint32_t>& removed) {
  std::vector<std::uint32_t> rest;
  rest.reserve(active.size() - removed.size());
  std::set_difference(active.begin(), active.end(), removed.begin(), removed.end(),
                      std::back_inserter(rest));
  active.swap(rest);
}

}  // namespace

std::vector<std::uint32_t> finiteIndices(const PointCloud& cloud) {
  std::vector<std::uint32_t> idx;
  idx.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i)
    if (cloud.positions[i].allFinite()) idx.push_back(static_cast<std::uint32_t>(i));
  return idx;
}

std::vector<DetectedPlane> detectMsac(const PointCloud& cloud, std::vector<std::uint32_t> active,
                                      double threshold, const PlaneExtractionParams& params,
                                      std::uint64_t seed, Progress* progress) {
  std::vector<DetectedPlane> planes;
  std::mt19937_64 rng(seed);
  const float t2 = static_cast<float>(threshold * threshold);
  const std::size_t initial = std::max<std::size_t>(1, active.size());
  const float local_cell = static_cast<float>(params.msac_local_cell);  // metres
  int failures = 0;
  while (static_cast<int>(planes.size()) < params.max_planes &&
         active.size() >= static_cast<std::size_t>(params.min_inliers)) {
    checkCanceled(progress);
    const std::vector<Eigen::Vector3f> sample = drawSample(cloud, active, params.score_sample, rng);
    SampleCells local(sample, local_cell);
    const std::vector<Hypothesis> hyps = drawHypotheses(sample, local, params.iterations, rng);
    // Score: eq. (2) over the subset, in parallel over hypotheses.
    const std::ptrdiff_t best = cheapestHypothesis(hyps, sample, t2);
    if (best < 0) break;
    // Refit by least squares on the inliers of all remaining points.
    DetectedPlane plane = refitOnInliers(cloud, active, hyps[best], threshold);
    if (plane.inliers.size() < static_cast<std::size_t>(params.min_inliers) || plane.inliers.size() < 3) {
      if (++failures >= 3) break;  // three bad draws in a row: nothing large is left
      continue;
    }
    failures = 0;
    plane.fit = fitPlaneLocal(cloud, plane.inliers);
    removeInliers(active, plane.inliers);
    planes.push_back(std::move(plane));
    reportProgress(progress, 1.0 - double(active.size()) / double(initial), "MSAC planes");
  }
  return planes;
}

double logNfa(double n_points, double min_size, double detected, double sigma, double diag,
              double volume, double iterations) {
  // Eqs. (3)-(6): R = N/min_size, K = R - F, P = 2 sigma diag^2 / V,
  // NFA = N_iter * sum_{j=F..K} C(K,j) P^j (1-P)^(K-j), summed in log space.
  const double R = std::floor(n_points / std::max(1.0, min_size));
  const double F = detected;
  const double K = R - F;
  double P = 2.0 * sigma * diag * diag / std::max(volume, 1e-12);
  P = std::clamp(P, 1e-300, 1.0 - 1e-12);
  if (F > K) return -std::numeric_limits<double>::infinity();  // empty tail
  const double lp = std::log(P), lq = std::log1p(-P);
  double max_term = -std::numeric_limits<double>::infinity();
  std::vector<double> terms;
  for (double j = F; j <= K; j += 1.0) {
    const double t = std::lgamma(K + 1) - std::lgamma(j + 1) - std::lgamma(K - j + 1) + j * lp +
                     (K - j) * lq;
    terms.push_back(t);
    max_term = std::max(max_term, t);
  }
  double s = 0;
  for (double t : terms) s += std::exp(t - max_term);
  return (std::log(iterations) + max_term + std::log(s)) / std::log(10.0);
}

}  // namespace plumb::planes_detail
