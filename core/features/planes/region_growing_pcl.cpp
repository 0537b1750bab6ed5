// PCL region growing as an alternative plane detector: kNN normals (NormalEstimationOMP),
// pcl::RegionGrowing with a smoothness angle, then one least-squares plane per region whose
// inliers are the region's points within the distance threshold.
#include <pcl/features/normal_3d_omp.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/region_growing.h>

#include <algorithm>
#include <cmath>

#include "features/planes/detected_plane.hpp"

namespace plumb::planes_detail {

std::vector<DetectedPlane> detectRegionGrowing(const PointCloud& cloud, double threshold,
                                               const PlaneExtractionParams& params,
                                               Progress* progress) {
  const auto finite = finiteIndices(cloud);
  pcl::PointCloud<pcl::PointXYZ>::Ptr pc(new pcl::PointCloud<pcl::PointXYZ>);
  pc->reserve(finite.size());
  for (auto i : finite) {
    const auto& p = cloud.positions[i];
    pc->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  }
  reportProgress(progress, 0.05, "normals");
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  pcl::PointCloud<pcl::Normal>::Ptr normals(new pcl::PointCloud<pcl::Normal>);
  pcl::NormalEstimationOMP<pcl::PointXYZ, pcl::Normal> ne(2);
  ne.setInputCloud(pc);
  ne.setSearchMethod(tree);
  ne.setKSearch(params.normal_neighbours);
  ne.compute(*normals);
  checkCanceled(progress);
  reportProgress(progress, 0.4, "region growing");
  pcl::RegionGrowing<pcl::PointXYZ, pcl::Normal> rg;
  rg.setMinClusterSize(params.min_inliers);
  rg.setMaxClusterSize(static_cast<int>(std::min<std::size_t>(pc->size(), 2147483647u)));
  rg.setSearchMethod(tree);
  rg.setNumberOfNeighbours(params.normal_neighbours);
  rg.setInputCloud(pc);
  rg.setInputNormals(normals);
  rg.setSmoothnessThreshold(static_cast<float>(params.smoothness_deg * M_PI / 180.0));
  rg.setCurvatureThreshold(0.05f);
  std::vector<pcl::PointIndices> clusters;
  rg.extract(clusters);
  checkCanceled(progress);
  std::vector<DetectedPlane> planes;
  for (const auto& c : clusters) {
    std::vector<std::uint32_t> idx;
    idx.reserve(c.indices.size());
    for (int k : c.indices) idx.push_back(finite[k]);
    DetectedPlane plane;
    plane.fit = fitPlaneLocal(cloud, idx);
    if (!plane.fit.valid) continue;
    const Eigen::Vector3f nf = plane.fit.normal.cast<float>();
    for (auto i : idx)
      if (std::abs(double(nf.dot(cloud.positions[i])) - plane.fit.offset) < threshold)
        plane.inliers.push_back(i);
    if (plane.inliers.size() < static_cast<std::size_t>(params.min_inliers)) continue;
    std::sort(plane.inliers.begin(), plane.inliers.end());
    plane.fit = fitPlaneLocal(cloud, plane.inliers);
    planes.push_back(std::move(plane));
  }
  std::stable_sort(planes.begin(), planes.end(), [](const auto& a, const auto& b) {
    return a.inliers.size() > b.inliers.size();
  });
  if (static_cast<int>(planes.size()) > params.max_planes) planes.resize(params.max_planes);
  return planes;
}

}  // namespace plumb::planes_detail
