// bench_features: plane extraction and 3D segment detection on a ~1 M point simulated indoor
// TLS scan (preset "house", 4 stations), on 2 threads, with PCL's SACSegmentation plane loop
// (segment, extract, remove, repeat) on the same cloud side by side.
// Usage: bench_features [step_deg=0.45] [threads=2]
#include <pcl/ModelCoefficients.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/method_types.h>
#include <pcl/sample_consensus/model_types.h>
#include <pcl/segmentation/sac_segmentation.h>
#include <tbb/global_control.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "features/planes/plane_extraction.hpp"
#include "features/segments/segment_detection.hpp"
#include "simulated_scans.hpp"
#include "simulation/presets.hpp"

using namespace plumb;

namespace {
double seconds(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

int main(int argc, char** argv) {
  const double step = argc > 1 ? std::atof(argv[1]) : 0.45;
  const int threads = argc > 2 ? std::atoi(argv[2]) : 2;
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
  const auto b = generateBuilding(buildingPreset("house"));
  const PointCloud cloud = test::indoorTls(b, step);
  const double n = double(cloud.size());
  std::printf("cloud: simulated indoor TLS, preset house, %zu points, %d threads\n", cloud.size(), threads);

  auto t0 = std::chrono::steady_clock::now();
  const auto planes = extractPlanes(cloud, {});
  const double tp = seconds(t0);
  std::printf("plumb planes (MSAC + alpha polygons): %zu planes, %zu polygons, %.3f s, %.2f M points/s\n",
              planes.planes_detected, planes.planes.size(), tp, n / tp / 1e6);

  // The other detectors on the same cloud (why Auto = MSAC): time and wall recall (truth
  // walls > 2 m2, normal within 1 deg and offset within 2 cm).
  auto recall = [&](const std::vector<PlanarPolygon>& ps) {
    std::size_t total = 0, found = 0;
    for (const auto& t : b.truth.planes) {
      if (t.element_type != "IfcWall" || t.area <= 2.0 || t.face != "interior") continue;
      std::size_t near = 0;
      for (std::size_t i = 0; i < cloud.size(); i += 8)
        near += std::abs(t.normal.dot(cloud.world(i)) - t.offset) < 0.01;
      if (near * 8 < 2000) continue;  // not observed by the indoor stations
      ++total;
      for (const auto& p : ps) {
        const double c = p.normal.dot(t.normal);
        if (std::abs(c) >= std::cos(M_PI / 180.0) && std::abs((c > 0 ? p.offset : -p.offset) - t.offset) <= 0.02) {
          ++found;
          break;
        }
      }
    }
    return std::pair<std::size_t, std::size_t>(found, total);
  };
  {
    const auto [f, t] = recall(planes.planes);
    std::printf("  msac wall recall %zu / %zu\n", f, t);
  }
  for (auto det : {PlaneDetector::SensorTopology, PlaneDetector::RegionGrowing}) {
    PlaneExtractionParams p;
    p.detector = det;
    t0 = std::chrono::steady_clock::now();
    const auto r = extractPlanes(cloud, p);
    const double t = seconds(t0);
    const auto [f, tot] = recall(r.planes);
    std::printf("plumb planes (%s): %zu planes, %zu polygons, %.3f s, wall recall %zu / %zu\n",
                detectorName(det).c_str(), r.planes_detected, r.planes.size(), t, f, tot);
  }

  t0 = std::chrono::steady_clock::now();
  const auto segs = detectSegments(cloud, {});
  const double ts = seconds(t0);
  std::printf("plumb 3D segments: %zu segments from %zu patches, %.3f s, %.2f M points/s\n", segs.segments.size(),
              segs.patches.size(), ts, n / ts / 1e6);

  // PCL: SACSegmentation (RANSAC plane, same 2 cm threshold), extract + remove, repeat until it
  // found as many planes as plumb did or the best plane is below plumb's min_inliers.
  pcl::PointCloud<pcl::PointXYZ>::Ptr rest(new pcl::PointCloud<pcl::PointXYZ>);
  rest->reserve(cloud.size());
  for (const auto& p : cloud.positions) rest->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  t0 = std::chrono::steady_clock::now();
  pcl::SACSegmentation<pcl::PointXYZ> seg;
  seg.setOptimizeCoefficients(true);
  seg.setModelType(pcl::SACMODEL_PLANE);
  seg.setMethodType(pcl::SAC_RANSAC);
  seg.setDistanceThreshold(0.02);
  seg.setMaxIterations(400);
  std::size_t pcl_planes = 0;
  const PlaneExtractionParams defaults;
  while (pcl_planes < planes.planes_detected && rest->size() >= std::size_t(defaults.min_inliers)) {
    pcl::PointIndices::Ptr inliers(new pcl::PointIndices);
    pcl::ModelCoefficients coeffs;
    seg.setInputCloud(rest);
    seg.segment(*inliers, coeffs);
    if (inliers->indices.size() < std::size_t(defaults.min_inliers)) break;
    pcl::ExtractIndices<pcl::PointXYZ> extract;
    extract.setInputCloud(rest);
    extract.setIndices(inliers);
    extract.setNegative(true);
    pcl::PointCloud<pcl::PointXYZ>::Ptr next(new pcl::PointCloud<pcl::PointXYZ>);
    extract.filter(*next);
    rest = next;
    ++pcl_planes;
  }
  const double tpcl = seconds(t0);
  std::printf("PCL SACSegmentation loop (RANSAC, 400 it, no polygons): %zu planes, %.3f s, %.2f M points/s\n",
              pcl_planes, tpcl, n / tpcl / 1e6);
  std::printf("targets: planes <= 2 s: %s, segments <= 2 s: %s (per 1 M points: %.2f s, %.2f s)\n",
              tp * 1e6 / n <= 2.0 ? "met" : "NOT met", ts * 1e6 / n <= 2.0 ? "met" : "NOT met", tp * 1e6 / n,
              ts * 1e6 / n);
  return 0;
}
