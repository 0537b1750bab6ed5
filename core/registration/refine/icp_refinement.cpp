#include "registration/refine/icp_refinement.hpp"

#include <pcl/registration/gicp.h>

#include <algorithm>
#include <random>

#include "common/error.hpp"
#include "registration/refine/icp_loop.hpp"
#include "registration/refine/point_target.hpp"
#include "registration/refine/point_to_plane.hpp"
#include "registration/refine/triangle_target.hpp"

namespace plumb {

const ParamSchema<RefineParams>& RefineParams::schema() {
  using P = RefineParams;
  static const auto s =
      ParamSchema<P>("refine")
          .choice(&P::method, "refine-method", "Refinement", {"point-to-plane", "gicp"},
                  "Local refinement: trimmed point-to-plane ICP or PCL GICP")
          .choice(&P::model_surface, "model-surface", "Model surface", {"triangles", "samples"},
                  "A model target: the triangles the scan's stations see (closest point, "
                  "triangle normal) or points sampled on the model")
          .real(&P::voxel_size, "voxel", "Voxel size", "m", 0.0, 1.0,
                "Voxel grid thinning before refinement")
          .integer(&P::max_source_points, "max-points", "Max source points", "", 100, 1e7,
                   "Source points used by the refinement", true)
          .real(&P::start_distance, "start-distance", "Start distance", "m", 0.01, 10.0,
                "First-stage max correspondence distance")
          .real(&P::final_distance, "final-distance", "Final distance", "m", 0.005, 1.0,
                "Last-stage max correspondence distance (inlier distance)")
          .integer(&P::stages, "stages", "Stages", "", 1, 10, "Coarse-to-fine stages", true)
          .integer(&P::iterations, "icp-iterations", "Iterations per stage", "", 1, 200,
                   "Max iterations per stage", true)
          .real(&P::trim_fraction, "trim", "Trim fraction", "", 0.05, 1.0,
                "Fraction of correspondences kept (trimmed ICP)", true)
          .boolean(&P::trim_per_direction, "trim-per-direction", "Trim per direction",
                   "Keep the trim fraction within each wall / floor direction, so that the "
                   "points constraining one direction are never trimmed away together", true)
          .boolean(&P::both_stations, "both-stations", "Seen from both stations",
                   "Scan to scan: match only surfaces whose front faces both the target's and "
                   "the source's station (never a wall's other face)", true)
          .real(&P::huber, "huber", "Huber threshold", "m", 0.0, 1.0,
                "Residuals beyond this get a Huber weight (0: trimming only)", true);
  return s;
}

namespace {

using refine_detail::Cloud;
using refine_detail::LocalPose;
using refine_detail::LoopOutcome;

/// PCL GICP over the same coarse-to-fine distances.
LoopOutcome runGicp(const Cloud::Ptr& src, const Cloud::Ptr& tgt, const RefineParams& p, Progress* progress) {
  const int stages = std::max(1, p.stages);
  pcl::GeneralizedIterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ> gicp;
  gicp.setInputSource(src);
  gicp.setInputTarget(tgt);
  gicp.setMaximumIterations(p.iterations);
  gicp.setTransformationEpsilon(1e-8);
  Eigen::Matrix4f guess = Eigen::Matrix4f::Identity();
  Cloud aligned;
  LoopOutcome out;
  for (int st = 0; st < stages; ++st) {
    checkCanceled(progress);
    gicp.setMaxCorrespondenceDistance(refine_detail::stageDistance(p.start_distance, p.final_distance, stages, st));
    gicp.align(aligned, guess);
    guess = gicp.getFinalTransformation();
    out.iterations += p.iterations;
  }
  out.pose.R = guess.topLeftCorner<3, 3>().cast<double>();
  out.pose.t = guess.topRightCorner<3, 1>().cast<double>();
  out.converged = gicp.hasConverged();
  return out;
}

}  // namespace

struct RefineTarget::Data {
  Eigen::Vector3d origin;  ///< world position of the local frame's origin (target centre)
  double voxel_size = 0.0;
  Cloud::Ptr cloud;        ///< thinned target, local frame (a point target)
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  std::vector<Eigen::Vector3d> normals;
  std::unique_ptr<refine_detail::PointSurface> points;
  std::unique_ptr<refine_detail::TriangleTarget> triangles;  ///< a model target
};

namespace {

/// The station that saw each thinned target point (local frame): the sensor origin of the first
/// point of its voxel, or the single viewpoint; empty when neither is known.
std::vector<Eigen::Vector3f> targetStations(const PointCloud& target, const std::vector<std::uint32_t>& first,
                                            const std::optional<Eigen::Vector3d>& viewpoint,
                                            const Eigen::Vector3d& origin) {
  std::vector<Eigen::Vector3f> out;
  if (target.hasSensorOrigins()) {
    out.reserve(first.size());
    for (const std::uint32_t i : first)
      out.push_back((target.offset + target.sensor_origins[i].cast<double>() - origin).cast<float>());
  } else if (viewpoint) {
    out.assign(first.size(), (*viewpoint - origin).cast<float>());
  }
  return out;
}

}  // namespace

RefineTarget::RefineTarget(const PointCloud& target, const RefineParams& p,
                           const std::optional<Eigen::Vector3d>& viewpoint)
    : d_(std::make_unique<Data>()) {
  if (target.empty()) throw InputError("refinement needs two non-empty clouds");
  d_->origin = target.bounds().center();
  d_->voxel_size = p.voxel_size;
  // Work in a frame centred on the target: x_local = x_world - origin.
  std::vector<std::uint32_t> first;
  const bool stations_known = target.hasSensorOrigins() || viewpoint.has_value();
  d_->cloud = refine_detail::toPcl(target, RigidTransform(), d_->origin, p.voxel_size,
                                   stations_known ? &first : nullptr);
  d_->tree.setInputCloud(d_->cloud);
  d_->normals = refine_detail::targetNormals(*d_->cloud, d_->tree, p.voxel_size);
  if (stations_known)
    refine_detail::orientTowards(*d_->cloud, targetStations(target, first, viewpoint, d_->origin), d_->normals);
  d_->points = std::make_unique<refine_detail::PointSurface>(*d_->cloud, d_->tree, d_->normals, stations_known);
}

RefineTarget::RefineTarget(const TriangleMesh& mesh, const RefineParams& p) : d_(std::make_unique<Data>()) {
  if (mesh.triangles.empty()) throw InputError("refinement: the model has no triangles");
  d_->origin = mesh.bounds().center();
  d_->voxel_size = p.voxel_size;
  d_->triangles = std::make_unique<refine_detail::TriangleTarget>(mesh, d_->origin);
}

RefineTarget::~RefineTarget() = default;

RefineResult refineRegistration(const PointCloud& source, const PointCloud& target,
                                const RigidTransform& initial, const RefineParams& p,
                                Progress* progress) {
  if (source.empty() || target.empty()) throw InputError("refinement needs two non-empty clouds");
  const RefineTarget prepared(target, p);
  return refineRegistration(source, prepared, initial, p, progress);
}

namespace {

/// The source points the refinement uses (local frame): voxel-thinned, then every k-th so that
/// at most max_source_points remain; with the sensor origin of each (that of the first point
/// of its voxel) when the source has them and `rays` is given.
Cloud::Ptr usedSourcePoints(const PointCloud& source, const RigidTransform& initial,
                            const Eigen::Vector3d& origin, const RefineParams& p,
                            refine_detail::SourceRays* rays = nullptr,
                            const std::optional<Eigen::Vector3d>& viewpoint = std::nullopt) {
  std::vector<std::uint32_t> first;
  const bool with_origins = rays && source.hasSensorOrigins();
  const bool with_viewpoint = rays && !with_origins && viewpoint;
  Cloud::Ptr src_all = refine_detail::toPcl(source, initial, origin, p.voxel_size, with_origins ? &first : nullptr);
  Cloud::Ptr src(new Cloud);
  const std::size_t stride =
      std::max<std::size_t>(1, (src_all->size() + p.max_source_points - 1) / p.max_source_points);
  for (std::size_t i = 0; i < src_all->size(); i += stride) {
    src->push_back((*src_all)[i]);
    if (with_viewpoint) {
      rays->points.push_back((*src_all)[i].getVector3fMap().cast<double>());
      rays->origins.push_back(initial.apply(*viewpoint) - origin);
    }
    if (!with_origins) continue;
    rays->points.push_back((*src_all)[i].getVector3fMap().cast<double>());
    const Eigen::Vector3d o = source.offset + source.sensor_origins[first[i]].cast<double>();
    rays->origins.push_back(initial.apply(o) - origin);
  }
  return src;
}

/// The surface a model target offers for a pose: every triangle at the first call (the
/// coarsest stage, whose start may be too far off for its visibility to hold), then the
/// triangles visible from the source's stations under that pose (found again at each call, or
/// once with visibility_per_stage off); without sensor origins, the front-facing triangles.
class ModelSurfaceAt {
 public:
  ModelSurfaceAt(const refine_detail::TriangleTarget& target, const refine_detail::SourceRays& rays,
                 bool per_stage, int stages)
      : target_(target), rays_(rays), per_stage_(per_stage), stages_(stages) {
    if (rays_.origins.empty()) current_ = target_.frontFacingSurface();
  }
  const refine_detail::TargetSurface& operator()(const LocalPose& pose) {
    if (rays_.origins.empty() || (visible_.rays > 0 && !per_stage_)) return *current_;
    if (calls_++ == 0 && stages_ > 1) {  // the coarsest stage: every triangle
      current_ = target_.everySurface();
      return *current_;
    }
    visible_ = refine_detail::visibleTriangles(target_.caster(), rays_, pose.R, pose.t);
    current_ = target_.visibleSurface(visible_);
    seconds_ += visible_.seconds;
    return *current_;
  }
  double seconds() const { return seconds_; }
  std::size_t triangles() const {
    return rays_.origins.empty() ? target_.triangleCount() : visible_.triangles.size();
  }
  std::string name() const { return rays_.origins.empty() ? "front-facing triangles" : "visible triangles"; }

 private:
  const refine_detail::TriangleTarget& target_;
  const refine_detail::SourceRays& rays_;
  bool per_stage_;
  int stages_;
  int calls_ = 0;
  refine_detail::VisibleSet visible_;
  std::unique_ptr<refine_detail::TargetSurface> current_;
  double seconds_ = 0.0;
};

/// res.transform from the local pose: x -> origin + pose(initial(x) - origin); a refinement
/// left with fewer than 10 inliers did not converge.
void finish(RefineResult& res, const LocalPose& pose, const Eigen::Vector3d& origin,
            const RigidTransform& initial, const RefineParams& p) {
  const RigidTransform to_local(Eigen::Matrix3d::Identity(), -origin);
  const RigidTransform from_local(Eigen::Matrix3d::Identity(), origin);
  res.transform = from_local * RigidTransform(pose.R, pose.t) * to_local * initial;
  if (res.inliers < 10) {
    res.converged = false;
    res.message = "refinement lost its overlap: fewer than 10 correspondences within " +
                  std::to_string(p.final_distance) + " m";
  }
}

RefineResult refineOnTriangles(const PointCloud& source, const RefineTarget::Data& d,
                               const RigidTransform& initial, const RefineParams& p,
                               Progress* progress) {
  if (p.method == RefineParams::Method::Gicp)
    throw InputError("refinement: GICP needs points sampled on the model (model-surface = samples)");
  RefineResult res;
  refine_detail::SourceRays rays;
  const Cloud::Ptr src = usedSourcePoints(source, initial, d.origin, p, &rays);
  res.source_points = src->size();
  if (src->size() < 10) throw InputError("refinement: too few points");
  ModelSurfaceAt surface(*d.triangles, rays, p.visibility_per_stage, p.stages);
  const LoopOutcome loop = refine_detail::runPointToPlane(
      *src, [&surface](const LocalPose& pose) -> const refine_detail::TargetSurface& { return surface(pose); },
      p, progress);
  res.iterations = loop.iterations;
  res.converged = loop.converged;
  refine_detail::measureFit(*src, surface(loop.pose), loop.pose, d.origin, p, res);
  res.target_points = surface.triangles();
  res.surface = surface.name();
  res.visibility_seconds = surface.seconds();
  finish(res, loop.pose, d.origin, initial, p);
  return res;
}

}  // namespace

RefineResult refineRegistration(const PointCloud& source, const RefineTarget& prepared,
                                const RigidTransform& initial, const RefineParams& p,
                                Progress* progress, const std::optional<Eigen::Vector3d>& source_viewpoint) {
  if (source.empty()) throw InputError("refinement needs two non-empty clouds");
  const RefineTarget::Data& d = prepared.data();
  if (p.voxel_size != d.voxel_size)
    throw InputError("refinement: the target was prepared with another voxel size");
  reportProgress(progress, 0.1, "refine: normals");
  if (d.triangles) {
    RefineResult res = refineOnTriangles(source, d, initial, p, progress);
    reportProgress(progress, 1.0, "refine: done");
    return res;
  }
  RefineResult res;
  // Both sides' stations known: correspondences on surfaces both stations saw.
  refine_detail::SourceRays rays;
  const bool seen = d.points->oriented() && p.both_stations && p.method == RefineParams::Method::PointToPlane;
  const Cloud::Ptr src = usedSourcePoints(source, initial, d.origin, p, seen ? &rays : nullptr, source_viewpoint);
  const refine_detail::SourceViewers viewers = rays.origins.empty() ? nullptr : &rays.origins;
  res.source_points = src->size();
  res.target_points = d.cloud->size();
  if (src->size() < 10 || d.cloud->size() < 10) throw InputError("refinement: too few points");
  const refine_detail::TargetSurface& surface = *d.points;
  const LoopOutcome loop =
      p.method == RefineParams::Method::Gicp
          ? runGicp(src, d.cloud, p, progress)
          : refine_detail::runPointToPlane(
                *src, [&surface](const LocalPose&) -> const refine_detail::TargetSurface& { return surface; },
                p, progress, viewers);
  res.iterations = loop.iterations;
  res.converged = loop.converged;
  refine_detail::measureFit(*src, surface, loop.pose, d.origin, p, res, viewers);
  if (viewers) res.surface = "points both stations see";
  finish(res, loop.pose, d.origin, initial, p);
  reportProgress(progress, 1.0, "refine: done");
  return res;
}

PointCloud sampleMeshSurface(const TriangleMesh& mesh, double spacing, std::uint64_t seed) {
  PointCloud out;
  if (mesh.triangles.empty() || !(spacing > 0)) return out;
  const Bounds b = mesh.bounds();
  out.offset = b.center();
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double per_area = 1.0 / (spacing * spacing);
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const double area = mesh.triangleArea(i);
    if (!(area > 0)) continue;
    // Expected count area/spacing^2; the fractional part is drawn so small triangles count.
    const double expected = area * per_area;
    std::size_t n = std::size_t(expected);
    if (u(rng) < expected - double(n)) ++n;
    const auto& tri = mesh.triangles[i];
    const Eigen::Vector3d a = mesh.vertices[tri[0]], bb = mesh.vertices[tri[1]],
                          c = mesh.vertices[tri[2]];
    const Eigen::Vector3f nrm = mesh.triangleNormal(i).cast<float>();
    for (std::size_t k = 0; k < n; ++k) {
      double r1 = u(rng), r2 = u(rng);
      if (r1 + r2 > 1) {
        r1 = 1 - r1;
        r2 = 1 - r2;
      }
      const Eigen::Vector3d p = a + r1 * (bb - a) + r2 * (c - a);
      out.positions.push_back((p - out.offset).cast<float>());
      out.normals.push_back(nrm);
    }
  }
  return out;
}

}  // namespace plumb
