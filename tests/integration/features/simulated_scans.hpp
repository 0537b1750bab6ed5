#pragma once
// Simulated scans of the building presets, and truth matching, for the feature tests and the
// benchmark.
#include <string>
#include <vector>

#include "model/point_cloud.hpp"
#include "simulation/building_generator.hpp"

namespace plumb::test {

/// Indoor TLS: one station per room of storey 0 (room centres, 1.5 m), merged in the model
/// frame with per-point sensor origins. step_deg: azimuth and elevation step.
PointCloud indoorTls(const GeneratedBuilding& b, double step_deg, double noise_mm = 2.0,
                     int max_stations = 100);
/// Outdoor MMS loop around the footprint (model frame, sensor origins, line/pulse grid).
PointCloud outdoorMms(const GeneratedBuilding& b, double noise_mm = 10.0);
/// The model's mesh without glass panes (what the sharp-edge truth describes).
TriangleMesh meshWithoutGlass(const GeneratedBuilding& b);

double pointSegmentDistance(const Eigen::Vector3d& p, const Segment3D& s);

}  // namespace plumb::test
