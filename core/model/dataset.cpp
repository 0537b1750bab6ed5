#include "model/dataset.hpp"

namespace plumb {

std::size_t Dataset::pointCount() const {
  std::size_t n = 0;
  for (const auto& s : scans) n += s.cloud.size();
  return n;
}

PointCloud scanInDatasetFrame(const Scan& scan) {
  PointCloud c = scan.cloud;
  if (!scan.pose.isIdentity()) c.transform(scan.pose);
  return c;
}

Bounds Dataset::bounds() const {
  Bounds b;
  for (const auto& s : scans) {
    if (s.pose.isIdentity()) {
      b.extend(s.cloud.bounds());
    } else {
      for (std::size_t i = 0; i < s.cloud.size(); ++i)
        if (s.cloud.positions[i].allFinite()) b.extend(s.pose.apply(s.cloud.world(i)));
    }
  }
  return b;
}

PointCloud Dataset::merged(bool with_sensor_origins) const {
  PointCloud out;
  for (std::size_t k = 0; k < scans.size(); ++k) {
    PointCloud c = scanInDatasetFrame(scans[k]);
    if (with_sensor_origins && !c.hasSensorOrigins() && !c.empty()) {
      const Eigen::Vector3f o = (scans[k].pose.translation() - c.offset).cast<float>();
      c.sensor_origins.assign(c.size(), o);
    }
    if (scans.size() > 1) c.scan_id.assign(c.size(), static_cast<std::uint16_t>(k));
    if (k == 0) {
      out = std::move(c);
    } else {
      out.append(c);
    }
  }
  if (scans.size() == 1) {
    out.grid_rows = scans[0].cloud.grid_rows;
    out.grid_columns = scans[0].cloud.grid_columns;
  }
  return out;
}

void Dataset::transform(const RigidTransform& T) {
  for (auto& scan : scans) {
    scan.pose = T * scan.pose;
    scan.has_pose = true;
  }
}

Dataset Dataset::fromCloud(PointCloud cloud, std::string name) {
  Dataset d;
  Scan s;
  s.name = std::move(name);
  s.cloud = std::move(cloud);
  d.scans.push_back(std::move(s));
  return d;
}

}  // namespace plumb
