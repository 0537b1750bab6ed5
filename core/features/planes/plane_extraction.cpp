#include "features/planes/plane_extraction.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "common/error.hpp"
#include "features/planes/detected_plane.hpp"

namespace plumb {

const ParamSchema<PlaneExtractionParams>& PlaneExtractionParams::schema() {
  using P = PlaneExtractionParams;
  static const auto s =
      ParamSchema<P>("planes")
          .choice(&P::detector, "detector", "Detector", {"auto", "msac", "sensor-topology", "region-growing"},
                  "auto: MSAC (measured best on simulated TLS and MMS scans)")
          .real(&P::distance_threshold, "distance-threshold", "Distance threshold", "m", 0.001, 1.0,
                "Largest distance of a point from its plane for it to count as on the plane\n"
                "(MSAC inlier distance t, 2021 eq. 2)")
          .boolean(&P::auto_threshold, "auto-threshold", "A-contrario threshold",
                   "Choose the distance threshold from the data: the candidate whose planes are "
                   "least likely to be chance alignments\n(lowest a-contrario NFA, 2021 eqs. 3-6)")
          .integer(&P::threshold_candidates, "threshold-candidates", "Threshold candidates", "", 2, 20,
                   "thresholds tried by the a-contrario selection", true)
          .real(&P::threshold_range_min, "threshold-min", "Smallest threshold candidate", "m",
                0.001, 1.0, "lower end of the a-contrario candidates", true)
          .real(&P::threshold_range_max, "threshold-max", "Largest threshold candidate", "m",
                0.001, 1.0, "upper end of the a-contrario candidates", true)
          .integer(&P::min_inliers, "min-inliers", "Minimum plane size", "points", 3, 1e7,
                   "detection stops when the best plane has fewer inliers")
          .integer(&P::max_planes, "max-planes", "Maximum planes", "", 1, 10000,
                   "Planes detected at most, largest first")
          .integer(&P::iterations, "iterations", "Hypotheses per plane", "", 10, 100000,
                   "Random plane candidates tried for each plane found", true)
          .integer(&P::score_sample, "score-sample", "Scoring subset", "points", 1000, 1e8,
                   "hypotheses are scored on this many random points", true)
          .real(&P::component_distance, "component-distance", "Connection distance", "m", 0.005, 10,
                "inliers closer than this belong to the same polygon")
          .integer(&P::min_component_inliers, "min-component-inliers", "Minimum polygon size",
                   "points", 1, 1e7, "Smaller connected pieces of a plane are not kept as polygons")
          .real(&P::alpha_radius, "alpha-radius", "Alpha radius", "m", 0.01, 10,
                "alpha-shape radius of the polygon outlines")
          .real(&P::simplify_tolerance, "simplify-tolerance", "Outline simplification", "m", 0, 1,
                "Douglas-Peucker tolerance on the rings", true)
          .real(&P::smoothness_deg, "smoothness", "Smoothness angle", "deg", 0.1, 90,
                "region growing: max normal angle between neighbours", true)
          .integer(&P::normal_neighbours, "normal-neighbours", "Normal neighbours", "", 3, 100,
                   "Points used to estimate each point's normal", true)
          .integer(&P::grid_window, "grid-window", "Grid window", "cells", 1, 100,
                   "sensor topology: window of the 2nd and 3rd samples", true)
          .boolean(&P::keep_inlier_indices, "keep-inliers", "Keep inlier indices",
                   "Keep which points belong to each plane (more memory; for export and colouring)", true)
          .real(&P::msac_local_cell, "local-cell", "MSAC local cell", "m", 0.05, 10,
                "half the MSAC hypotheses draw their 2nd and 3rd points in the grid cell of "
                "this size holding the 1st", true);
  return s;
}

std::string detectorName(PlaneDetector d) {
  switch (d) {
    case PlaneDetector::Auto: return "auto";
    case PlaneDetector::Msac: return "msac";
    case PlaneDetector::SensorTopology: return "sensor-topology";
    case PlaneDetector::RegionGrowing: return "region-growing";
  }
  return "?";
}

namespace {

void validate(const PlaneExtractionParams& p) {
  validateParams(PlaneExtractionParams::schema(), p);
  if (!(p.threshold_range_min < p.threshold_range_max))
    throw InputError("planes: threshold-min (" + std::to_string(p.threshold_range_min) +
                     " m) must be below threshold-max (" + std::to_string(p.threshold_range_max) +
                     " m)");
}

std::vector<planes_detail::DetectedPlane> detect(const PointCloud& cloud, PlaneDetector d,
                                                 double t, const PlaneExtractionParams& p,
                                                 std::uint64_t seed, Progress* progress) {
  using namespace planes_detail;
  switch (d) {
    case PlaneDetector::SensorTopology: return detectSensorTopology(cloud, t, p, seed, progress);
    case PlaneDetector::RegionGrowing: return detectRegionGrowing(cloud, t, p, progress);
    default: return detectMsac(cloud, finiteIndices(cloud), t, p, seed, progress);
  }
}

}  // namespace

PlaneExtractionResult extractPlanes(const PointCloud& cloud, const PlaneExtractionParams& params,
                                    std::uint64_t seed, Progress* progress) {
  const auto start = std::chrono::steady_clock::now();
  validate(params);
  PlaneExtractionResult result;
  result.detector_used = params.detector;
  if (params.detector == PlaneDetector::Auto)
    result.detector_used = PlaneDetector::Msac;  // measured: see plane_extraction.hpp
  result.point_plane.assign(cloud.size(), -1);
  double t = params.distance_threshold;
  Progress detect_progress = progress ? progress->sub(0.0, 0.8) : Progress();
  Progress* dp = progress ? &detect_progress : nullptr;
  std::vector<planes_detail::DetectedPlane> planes;
  if (params.auto_threshold) {
    // A-contrario selection (2021 §3.1.1): run the detector for each candidate sigma and keep
    // the one with the lowest NFA (eq. 4).
    const Bounds b = cloud.bounds();
    const Eigen::Vector3d size = b.size().cwiseMax(1e-3);
    const double diag = size.norm();
    const double volume = size.prod();
    const int m = params.threshold_candidates;
    double best_nfa = std::numeric_limits<double>::infinity();
    for (int k = 0; k < m; ++k) {
      const double lo = params.threshold_range_min, hi = params.threshold_range_max;
      const double sigma = lo * std::pow(hi / lo, double(k) / (m - 1));
      Progress sub = progress ? progress->sub(0.8 * k / m, 0.8 * (k + 1) / m) : Progress();
      auto cand = detect(cloud, result.detector_used, sigma, params, seed, progress ? &sub : nullptr);
      const double nfa = planes_detail::logNfa(double(cloud.size()), params.min_inliers,
                                               double(cand.size()), sigma, diag, volume,
                                               params.iterations);
      if (nfa < best_nfa || planes.empty()) {
        best_nfa = nfa;
        t = sigma;
        planes = std::move(cand);
      }
    }
  } else {
    planes = detect(cloud, result.detector_used, t, params, seed, dp);
  }
  result.distance_threshold_used = t;
  result.planes_detected = planes.size();
  for (std::size_t k = 0; k < planes.size(); ++k) {
    checkCanceled(progress);
    auto polys = planes_detail::makePolygons(cloud, planes[k], params);
    for (auto& poly : polys) result.planes.push_back(std::move(poly));
    reportProgress(progress, 0.8 + 0.2 * double(k + 1) / double(planes.size()), "polygons");
  }
  std::stable_sort(result.planes.begin(), result.planes.end(),
                   [](const auto& a, const auto& b) { return a.inlier_count > b.inlier_count; });
  if (params.keep_inlier_indices)
    for (std::size_t k = 0; k < result.planes.size(); ++k)
      for (auto i : result.planes[k].inliers) result.point_plane[i] = static_cast<int>(k);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace plumb
