#pragma once
// Internal to the planes module: what each detector returns before polygons are made.
#include <cstdint>
#include <random>
#include <vector>

#include "features/planes/plane_extraction.hpp"
#include "features/planes/plane_fit.hpp"

namespace plumb::planes_detail {

struct DetectedPlane {
  PlaneFit fit;                        ///< local coordinates of the cloud
  std::vector<std::uint32_t> inliers;  ///< cloud indices
};

/// Indices of points with finite positions.
std::vector<std::uint32_t> finiteIndices(const PointCloud& cloud);

/// MSAC (2021 §2.2, eq. 2) on the points `active`.
std::vector<DetectedPlane> detectMsac(const PointCloud& cloud, std::vector<std::uint32_t> active,
                                      double threshold, const PlaneExtractionParams& params,
                                      std::uint64_t seed, Progress* progress);
/// RANSAC on the sensor topology (2021 §2.1). Needs cloud.hasGrid().
std::vector<DetectedPlane> detectSensorTopology(const PointCloud& cloud, double threshold,
                                                const PlaneExtractionParams& params,
                                                std::uint64_t seed, Progress* progress);
/// PCL region growing + least-squares plane per region.
std::vector<DetectedPlane> detectRegionGrowing(const PointCloud& cloud, double threshold,
                                               const PlaneExtractionParams& params,
                                               Progress* progress);

/// log10 NFA of eq. (4)-(6) for F detected planes among N points.
double logNfa(double n_points, double min_size, double detected, double sigma, double diag,
              double volume, double iterations);

/// Splits inliers into connected parts and outlines each with an alpha shape.
std::vector<PlanarPolygon> makePolygons(const PointCloud& cloud, const DetectedPlane& plane,
                                        const PlaneExtractionParams& params);

}  // namespace plumb::planes_detail
