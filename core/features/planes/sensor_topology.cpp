// RANSAC on the sensor topology (2021 §2.1, after Guinard et al. 2020): the first sample is
// drawn among free points, the 2nd and 3rd in its grid window (rows/columns of an organized
// scan); a hypothesis is scored by growing a region from the first sample over 4-connected
// grid neighbours within the distance threshold, instead of scoring the whole cloud. The
// largest region is refitted by least squares, regrown, kept, and its points removed.
#include <algorithm>
#include <random>

#include "common/error.hpp"
#include "features/planes/detected_plane.hpp"

namespace plumb::planes_detail {
namespace {

/// Grid of every scan (merged clouds keep each scan's rows/columns, told apart by scan_id).
struct Grid {
  int rows = 0, cols = 0;
  std::vector<std::int64_t> cell;  // point index or -1
  std::int64_t at(std::size_t scan, int r, int c) const {
    if (r < 0 || c < 0 || r >= rows || c >= cols) return -1;
    return cell[(scan * rows + static_cast<std::size_t>(r)) * cols + c];
  }
};

std::vector<std::uint32_t> grow(const PointCloud& cloud, const Grid& g,
                                const std::vector<char>& used, std::uint32_t seed,
                                const Eigen::Vector3d& n, double d, double t,
                                std::vector<int>& stamp, int stamp_id) {
  std::vector<std::uint32_t> region{seed};
  stamp[seed] = stamp_id;
  const Eigen::Vector3f nf = n.cast<float>();
  for (std::size_t k = 0; k < region.size(); ++k) {
    const auto i = region[k];
    const int r = cloud.row[i], c = cloud.column[i];
    const std::size_t scan = cloud.hasScanId() ? cloud.scan_id[i] : 0;
    const int dr[4] = {1, -1, 0, 0}, dc[4] = {0, 0, 1, -1};
    for (int e = 0; e < 4; ++e) {
      const auto j = g.at(scan, r + dr[e], c + dc[e]);
      if (j < 0 || used[j] || stamp[j] == stamp_id) continue;
      if (std::abs(double(nf.dot(cloud.positions[j])) - d) >= t) continue;
      stamp[j] = stamp_id;
      region.push_back(static_cast<std::uint32_t>(j));
    }
  }
  return region;
}

/// The grid of every scan of the cloud, and its free (finite, gridded) points in index order.
Grid buildGrid(const PointCloud& cloud, std::vector<std::uint32_t>& free_points) {
  Grid g;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    g.rows = std::max(g.rows, cloud.row[i] + 1);
    g.cols = std::max(g.cols, cloud.column[i] + 1);
  }
  std::size_t scans = 1;
  if (cloud.hasScanId())
    for (auto id : cloud.scan_id) scans = std::max<std::size_t>(scans, id + 1u);
  g.cell.assign(scans * g.rows * g.cols, -1);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (!cloud.positions[i].allFinite() || cloud.row[i] < 0 || cloud.column[i] < 0) continue;
    const std::size_t scan = cloud.hasScanId() ? cloud.scan_id[i] : 0;
    auto& cell = g.cell[(scan * g.rows + cloud.row[i]) * g.cols + cloud.column[i]];
    if (cell >= 0)
      throw InputError("sensor-topology RANSAC: two points share row " + std::to_string(cloud.row[i]) +
                       ", column " + std::to_string(cloud.column[i]) + " of one scan (not a scan grid)");
    cell = static_cast<std::int64_t>(i);
    free_points.push_back(static_cast<std::uint32_t>(i));
  }
  return g;
}

/// What the detection has used so far: points taken by planes (or small regions), the free
/// list (compacted now and then) and the stamps of region growing.
struct TopologyState {
  std::vector<char> used;
  std::vector<std::uint32_t> free_points;
  std::size_t free_count = 0;
  std::vector<int> stamp;
  int stamp_id = 0;

  void take(const std::vector<std::uint32_t>& points) {
    for (auto i : points) used[i] = 1;
    free_count -= points.size();
  }
  /// Compact the free list now and then.
  void compact() {
    if (free_points.size() <= 2 * free_count) return;
    std::vector<std::uint32_t> f;
    for (auto i : free_points)
      if (!used[i]) f.push_back(i);
    free_points.swap(f);
  }
};

/// Largest region grown from `hypotheses` planes, each through a free point and two free
/// points of its grid window (within `w` rows and columns).
std::vector<std::uint32_t> largestRegion(const PointCloud& cloud, const Grid& g,
                                         TopologyState& st, int hypotheses, int w,
                                         double threshold, std::mt19937_64& rng) {
  std::uniform_int_distribution<std::size_t> pick(0, st.free_points.size() - 1);
  std::uniform_int_distribution<int> off(-w, w);
  std::vector<std::uint32_t> best;
  for (int h = 0; h < hypotheses; ++h) {
    std::uint32_t a = st.free_points[pick(rng)];
    if (st.used[a]) continue;
    std::int64_t b = -1, c = -1;
    for (int attempt = 0; attempt < 20 && (b < 0 || c < 0 || b == c); ++attempt) {
      const std::size_t scan = cloud.hasScanId() ? cloud.scan_id[a] : 0;
      const auto j = g.at(scan, cloud.row[a] + off(rng), cloud.column[a] + off(rng));
      if (j < 0 || st.used[j] || j == a) continue;
      if (b < 0) b = j; else c = j;
    }
    if (b < 0 || c < 0 || b == c) continue;
    const Eigen::Vector3d pa = cloud.positions[a].cast<double>();
    Eigen::Vector3d n = (cloud.positions[b].cast<double>() - pa).cross(cloud.positions[c].cast<double>() - pa);
    if (n.norm() < 1e-12) continue;
    n.normalize();
    auto region = grow(cloud, g, st.used, a, n, n.dot(pa), threshold, st.stamp, st.stamp_id++);
    if (region.size() > best.size()) best.swap(region);
  }
  return best;
}

/// The region refitted by least squares, regrown from its first point, refitted again.
DetectedPlane refitRegion(const PointCloud& cloud, const Grid& g, TopologyState& st,
                          const std::vector<std::uint32_t>& region, double threshold) {
  DetectedPlane plane;
  plane.fit = fitPlaneLocal(cloud, region);
  if (plane.fit.valid) {
    plane.inliers = grow(cloud, g, st.used, region[0], plane.fit.normal, plane.fit.offset, threshold,
                         st.stamp, st.stamp_id++);
    if (plane.inliers.size() >= 3) plane.fit = fitPlaneLocal(cloud, plane.inliers);
  }
  return plane;
}

}  // namespace

std::vector<DetectedPlane> detectSensorTopology(const PointCloud& cloud, double threshold,
                                                const PlaneExtractionParams& params,
                                                std::uint64_t seed, Progress* progress) {
  if (!cloud.hasGrid())
    throw InputError("sensor-topology RANSAC needs an organized scan (row/column per point)");
  TopologyState st;
  const Grid g = buildGrid(cloud, st.free_points);
  st.used.assign(cloud.size(), 1);
  for (auto i : st.free_points) st.used[i] = 0;
  st.free_count = st.free_points.size();
  const std::size_t initial = std::max<std::size_t>(1, st.free_count);
  st.stamp.assign(cloud.size(), -1);
  std::mt19937_64 rng(seed);
  const int hypotheses = std::max(20, params.iterations / 8);
  std::vector<DetectedPlane> planes;
  int failures = 0;
  while (static_cast<int>(planes.size()) < params.max_planes &&
         st.free_count >= static_cast<std::size_t>(params.min_inliers) && failures < 5) {
    checkCanceled(progress);
    st.compact();
    const auto best = largestRegion(cloud, g, st, hypotheses, params.grid_window, threshold, rng);
    if (best.size() < 3) {
      ++failures;
      continue;
    }
    DetectedPlane plane = refitRegion(cloud, g, st, best, threshold);
    if (!plane.fit.valid || plane.inliers.size() < static_cast<std::size_t>(params.min_inliers)) {
      // Mark the small region used so it is not drawn again, count a failure.
      st.take(best);
      ++failures;
      continue;
    }
    failures = 0;
    st.take(plane.inliers);
    std::sort(plane.inliers.begin(), plane.inliers.end());
    planes.push_back(std::move(plane));
    reportProgress(progress, 1.0 - double(st.free_count) / double(initial), "topology planes");
  }
  return planes;
}

}  // namespace plumb::planes_detail
