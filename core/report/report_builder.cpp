#include "report/report_builder.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <numeric>

#include "common/error.hpp"
#include "quality/cloud_distance.hpp"
#include "registration/refine/icp_refinement.hpp"

#ifndef PLUMB_VERSION_STRING
#define PLUMB_VERSION_STRING "dev"
#endif

namespace plumb::report {

std::string nowUtc() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

namespace {

/// Indices 0, k, 2k... of n points, k chosen so that at most `max` are kept.
std::vector<std::size_t> strideIndices(std::size_t n, std::size_t max) {
  const std::size_t step = std::max<std::size_t>(1, (n + max - 1) / std::max<std::size_t>(1, max));
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < n; i += step) idx.push_back(i);
  return idx;
}

std::vector<Eigen::Vector3d> worldPoints(const PointCloud& c, const RigidTransform& t, std::size_t max) {
  std::vector<Eigen::Vector3d> out;
  for (const auto i : strideIndices(c.size(), max)) {
    const Eigen::Vector3d w = t.apply(c.world(i));
    if (w.allFinite()) out.push_back(w);
  }
  return out;
}

/// The target in world coordinates: its points, or its model's surface sampled at about
/// 50,000 points (the cloud itself is not copied).
std::vector<Eigen::Vector3d> targetWorldPoints(const ReportInputs& in, std::size_t max) {
  if (in.target_cloud) return worldPoints(*in.target_cloud, RigidTransform(), max);
  const TriangleMesh& mesh = in.target_model->mesh;
  double area = 0.0;
  for (const auto& t : mesh.triangles)
    area += 0.5 * (mesh.vertices[t[1]] - mesh.vertices[t[0]]).cross(mesh.vertices[t[2]] - mesh.vertices[t[0]]).norm();
  return worldPoints(sampleMeshSurface(mesh, std::max(0.02, std::sqrt(area / 50000.0)), in.seed), RigidTransform(), max);
}

DistanceResult measure(const ReportInputs& in, const PointCloud& sample, const RigidTransform& t,
                       const ReportParams& p, Progress* progress) {
  DistanceParams dp;
  dp.max_distance = p.max_distance;
  dp.signed_distances = false;  // the report's histogram is of distances over [0, max]
  return in.target_model ? cloudToMeshDistances(sample, t, in.target_model->mesh, RigidTransform(), dp, progress)
                         : cloudToCloudDistances(sample, t, *in.target_cloud, RigidTransform(), dp, progress);
}

DistanceSummary summarize(const DistanceResult& r, std::size_t sampled, const ReportParams& p) {
  DistanceSummary d;
  d.sampled = sampled;
  d.matched = r.matched;
  d.max_distance = p.max_distance;
  d.mean = r.mean, d.rms = r.rms, d.median = r.median, d.p95 = r.p95;
  d.histogram = distanceHistogram(r.distances, 0.0, p.max_distance, p.histogram_bins).counts;
  return d;
}

/// Median of the registered source points that matched the target (the centre of the
/// overlap); of all of them when none matched.
Eigen::Vector3d overlapCentre(const PointCloud& sample, const RigidTransform& t, const DistanceResult& r) {
  std::vector<Eigen::Vector3d> matched;
  for (std::size_t i = 0; i < sample.size(); ++i)
    if (std::isfinite(r.distances[i])) matched.push_back(t.apply(sample.world(i)));
  if (matched.empty()) matched = worldPoints(sample, t, sample.size());
  if (matched.empty()) return Eigen::Vector3d::Zero();
  Eigen::Vector3d c;
  for (int a = 0; a < 3; ++a) {
    std::vector<double> v;
    for (const auto& q : matched) v.push_back(q[a]);
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    c[a] = v[v.size() / 2];
  }
  return c;
}

ReportSide side(const std::string& role, const std::string& file, const PointCloud* cloud, const BimModel* model) {
  ReportSide s{role, file, model != nullptr};
  if (cloud) s.points = cloud->size();
  if (model) s.triangles = model->mesh.triangles.size();
  return s;
}

}  // namespace

RegistrationReport buildRegistrationReport(const ReportInputs& in, const PipelineResult& result,
                                           const ReportParams& p, Progress* progress) {
  if (!in.source) throw InputError("report: the source point cloud is missing");
  if (!in.target_cloud == !in.target_model) throw InputError("report: give the target as a cloud or a model");
  RegistrationReport r;
  r.source = side("source", in.source_file, in.source, nullptr);
  r.target = side("target", in.target_file, in.target_cloud, in.target_model);
  r.quality = result.report;
  r.created_utc = nowUtc();
  r.seed = in.seed;
  r.plumb_version = PLUMB_VERSION_STRING;
  if (result.report.level == VerdictLevel::Failed) return r;  // no transform to show or measure
  const RigidTransform& t = result.report.transform;
  r.residuals = featureResiduals(result.source_features, result.target_features, t);
  const PointCloud sample = in.source->subset(strideIndices(in.source->size(), p.max_distance_samples));
  const DistanceResult distances = measure(in, sample, t, p, progress);
  r.distances = summarize(distances, sample.size(), p);
  const auto src = worldPoints(*in.source, t, 2'000'000), tgt = targetWorldPoints(in, 2'000'000);
  r.pictures.push_back(planPicture(src, tgt, p.pictures));
  r.pictures.push_back(sectionPicture(src, tgt, overlapCentre(sample, t, distances), p.pictures));
  r.pictures.push_back(histogramPicture(r.distances));
  r.pictures.push_back(residualPicture(r.residuals));
  return r;
}

}  // namespace plumb::report
