#pragma once
// The report's pictures from world points: plan view and a vertical section through the
// overlap (registered source over the target), the distance histogram and the per-feature
// residual bars.
#include <Eigen/Core>

#include <vector>

#include "report/registration_report.hpp"

namespace plumb::report {

struct PictureParams {
  std::size_t max_points = 6000;   ///< per layer and picture
  double section_thickness = 0.1;  ///< m, the slab kept around the section plane
};

/// Registered source (orange) over the target (grey), seen from above; the extent is the
/// source's 2nd-98th percentile box grown by half its size plus 2 m.
Picture planPicture(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                    const PictureParams& params = {});

/// Vertical slab through `centre`, along the source's longer horizontal extent.
Picture sectionPicture(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                       const Eigen::Vector3d& centre, const PictureParams& params = {});

Picture histogramPicture(const DistanceSummary& distances);

Picture residualPicture(const std::vector<FeatureResidual>& residuals);

}  // namespace plumb::report
