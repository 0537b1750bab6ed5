#include "ui/layers/scan_colors.hpp"

namespace plumb::ui {

std::vector<Rgba> ScanColorJob::compute(Progress* progress) const {
  const PointCloud& cloud = data->scans.at(scan_index).cloud;
  checkCanceled(progress);
  std::vector<Rgb> colors(cloud.size());  // cloud order (transient: 3 bytes per point)
  const bool by_distance = coloring.style.mode == PointColorMode::Distance && distances &&
                           distances->size() == cloud.size();
  if (by_distance) {
    fillDistanceColors(*distances, distance_scale, colors);
  } else {
    PointColoring c = coloring;
    if (c.style.mode == PointColorMode::Distance) c.style.mode = PointColorMode::Elevation;
    fillPointColors(cloud, c, colors);
  }
  reportProgress(progress, 0.5, "colours");
  checkCanceled(progress);
  auto permuted = permuteColors(colors, scanOrderSeed(scan_index));
  reportProgress(progress, 1.0, "colours");
  return permuted;
}

ScanColorJob makeScanColorJob(std::shared_ptr<const Dataset> data, std::size_t scan_index,
                              const RigidTransform& dataset_transform, const PointStyle& style,
                              double z_min, double z_max,
                              std::shared_ptr<const std::vector<float>> distances,
                              const DistanceScale& distance_scale) {
  ScanColorJob job;
  job.coloring.style = style;
  job.coloring.scan_index = scan_index;
  // Elevation row acts on (offset + local): world z of the scan-frame point.
  const Eigen::Matrix4d to_world =
      dataset_transform.matrix() * data->scans.at(scan_index).pose.matrix();
  job.coloring.elevation_row = to_world.row(2).transpose();
  job.coloring.z_min = z_min;
  job.coloring.z_max = z_max;
  job.data = std::move(data);
  job.scan_index = scan_index;
  job.distances = std::move(distances);
  job.distance_scale = distance_scale;
  if (!(job.distance_scale.max > 0)) job.distance_scale.max = 1.0;
  return job;
}

}  // namespace plumb::ui
