// Distances of a whole dataset, scan by scan (the desktop's distance colouring and plumb-cli
// register --distances), and the "distance" scalar field the writers export.
#include <string>

#include "common/error.hpp"
#include "quality/cloud_distance.hpp"

namespace plumb {

DatasetDistances datasetDistances(const Dataset& source, const RigidTransform& source_to_world,
                                  const DistanceTarget& target, const DistanceParams& params,
                                  Progress* progress) {
  if (!target.cloud && !target.mesh) throw InputError("distance: no target cloud or model");
  DatasetDistances out;
  out.signed_values = params.signed_distances;
  const std::size_t n = source.scans.size();
  for (std::size_t i = 0; i < n; ++i) {
    Progress p = progress ? progress->sub(double(i) / double(n), double(i + 1) / double(n)) : Progress();
    const Scan& scan = source.scans[i];
    const RigidTransform scan_to_world = source_to_world * scan.pose;
    DistanceResult r = target.cloud
                           ? cloudToCloudDistances(scan.cloud, scan_to_world, *target.cloud, {}, params, &p)
                           : cloudToMeshDistances(scan.cloud, scan_to_world, *target.mesh, {}, params, &p);
    out.all.distances.insert(out.all.distances.end(), r.distances.begin(), r.distances.end());
    out.per_scan.push_back(std::move(r.distances));
  }
  summarizeDistances(out.all);
  return out;
}

void attachDistanceField(Dataset& dataset, const std::vector<std::vector<float>>& per_scan) {
  if (per_scan.size() != dataset.scans.size())
    throw InputError("distance field: " + std::to_string(per_scan.size()) + " scans of distances for " +
                     std::to_string(dataset.scans.size()) + " scans");
  for (std::size_t i = 0; i < per_scan.size(); ++i) {
    PointCloud& cloud = dataset.scans[i].cloud;
    if (per_scan[i].size() != cloud.size())
      throw InputError("distance field: scan " + std::to_string(i + 1) + " has " + std::to_string(cloud.size()) +
                       " points but " + std::to_string(per_scan[i].size()) + " distances");
    ScalarField* field = cloud.findScalarField(kDistanceField);
    if (!field) field = &cloud.scalar_fields.emplace_back(ScalarField{kDistanceField, {}});
    field->values.assign(per_scan[i].begin(), per_scan[i].end());
  }
}

}  // namespace plumb
