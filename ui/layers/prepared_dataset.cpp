#include "ui/layers/prepared_dataset.hpp"

#include "model/robust_bounds.hpp"

#include <algorithm>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include "ui/layers/render_frame.hpp"
#include "ui/layers/scan_colors.hpp"

namespace plumb::ui {

namespace {

/// Bounds of the finite positions (min/max: the same for any split, so deterministic).
Bounds finiteBounds(const Column<Eigen::Vector3f>& positions) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, positions.size(), std::size_t{1} << 16), Bounds{},
      [&positions](const tbb::blocked_range<std::size_t>& r, Bounds b) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
          if (positions[i].allFinite()) b.extend(positions[i].cast<double>());
        return b;
      },
      [](Bounds a, const Bounds& b) {
        a.extend(b);
        return a;
      });
}

}  // namespace

bool anyScanHasColors(const Dataset& data) {
  return std::any_of(data.scans.begin(), data.scans.end(), [](const Scan& s) { return s.cloud.hasColors(); });
}

bool anyScanHasIntensity(const Dataset& data) {
  return std::any_of(data.scans.begin(), data.scans.end(), [](const Scan& s) { return s.cloud.hasIntensity(); });
}

PointStyle initialStyle(const Dataset& data) {
  PointStyle style;
  if (!anyScanHasColors(data)) style.mode = PointColorMode::Elevation;
  return style;
}

PreparedDataset prepareDataset(const std::shared_ptr<const Dataset>& data, Progress* progress) {
  PreparedDataset out;
  out.style = initialStyle(*data);
  const std::size_t total = std::max<std::size_t>(1, data->pointCount());
  std::size_t done = 0;
  // Points: half of the work; colours: the other half.
  auto fraction = [&](std::size_t points) {
    return 0.5 * static_cast<double>(points) / static_cast<double>(total);
  };
  Bounds shown;  // world bounds of the layer (identity dataset transform): the elevation range
  for (std::size_t i = 0; i < data->scans.size(); ++i) {
    checkCanceled(progress);
    const Scan& scan = data->scans[i];
    PreparedScan& prepared = out.scans.emplace_back();
    prepared.local_bounds = finiteBounds(scan.cloud.positions);
    prepared.points = PermutedPoints(scan.cloud, scanOrderSeed(i));
    Eigen::Matrix4d local_to_frame = scan.pose.matrix();
    local_to_frame.block<3, 1>(0, 3) += scan.pose.matrix().block<3, 3>(0, 0) * scan.cloud.offset;
    shown.extend(transformBounds(prepared.local_bounds, local_to_frame));
    done += scan.cloud.size();
    reportProgress(progress, fraction(done), "display points");
  }
  checkCanceled(progress);
  out.bounds = data->bounds();
  out.framing = robustBounds(datasetSamples(*data));
  done = 0;
  for (std::size_t i = 0; i < data->scans.size(); ++i) {
    const std::size_t n = data->scans[i].cloud.size();
    Progress sub = progress ? progress->sub(0.5 + fraction(done), 0.5 + fraction(done + n))
                            : Progress();
    const ScanColorJob job =
        makeScanColorJob(data, i, RigidTransform(), out.style, shown.min.z(), shown.max.z());
    out.scans[i].points.setColors(job.compute(progress ? &sub : nullptr));
    done += n;
  }
  return out;
}

}  // namespace plumb::ui
