#include "registration/refine/icp_refinement.hpp"

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>
#include <pcl/registration/gicp.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <random>
#include <unordered_map>

#include "common/error.hpp"
#include "registration/refine/point_to_plane.hpp"

namespace plumb {

const ParamSchema<RefineParams>& RefineParams::schema() {
  using P = RefineParams;
  static const auto s =
      ParamSchema<P>("refine")
          .choice(&P::method, "refine-method", "Refinement", {"point-to-plane", "gicp"},
                  "Local refinement: trimmed point-to-plane ICP or PCL GICP")
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
                   "points constraining one direction are never trimmed away together", true);
  return s;
}

namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

/// World points relative to `origin` as float (keeps precision for georeferenced data).
Cloud::Ptr toPcl(const PointCloud& c, const RigidTransform& t, const Eigen::Vector3d& origin,
                 double voxel) {
  Cloud::Ptr out(new Cloud);
  out->reserve(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    if (!c.positions[i].allFinite()) continue;
    const Eigen::Vector3d p = t.apply(c.world(i)) - origin;
    out->push_back(pcl::PointXYZ(float(p.x()), float(p.y()), float(p.z())));
  }
  if (voxel > 0 && out->size() > 1000) {
    // Centroid per occupied voxel, in first-occurrence order (deterministic). A hash map rather
    // than pcl::VoxelGrid, which silently returns the cloud unthinned when the grid exceeds
    // 2^31 cells (any MMS street scene at 5 cm) and then makes the refinement 30x slower.
    std::unordered_map<std::uint64_t, std::uint32_t> slot;
    slot.reserve(out->size() / 4);
    std::vector<Eigen::Vector4d> acc;  // x, y, z, count
    const double inv = 1.0 / voxel;
    for (const auto& q : *out) {
      const auto k = [&](float v) {
        return std::uint64_t(std::int64_t(std::floor(double(v) * inv)) + (1 << 20)) & 0x1FFFFF;
      };
      const std::uint64_t key = (k(q.x) << 42) | (k(q.y) << 21) | k(q.z);
      const auto [it, fresh] = slot.try_emplace(key, std::uint32_t(acc.size()));
      if (fresh) acc.emplace_back(0, 0, 0, 0);
      acc[it->second] += Eigen::Vector4d(q.x, q.y, q.z, 1.0);
    }
    Cloud::Ptr thin(new Cloud);
    thin->reserve(acc.size());
    for (const auto& a : acc)
      thin->push_back(pcl::PointXYZ(float(a.x() / a.w()), float(a.y() / a.w()), float(a.z() / a.w())));
    return thin;
  }
  return out;
}

using refine_detail::PlaneCorrespondence;

/// What the ICP loop and the slide test read: the used source points, the target with its
/// kd-tree and normals (all in the refinement's local frame).
struct LocalClouds {
  const Cloud& src;
  const Cloud& tgt;
  const pcl::KdTreeFLANN<pcl::PointXYZ>& tree;
  const std::vector<Eigen::Vector3d>& normals;
};

/// Mean capped point-to-plane cost, min(r^2, d^2) / d^2, of every source point placed by
/// (R, t) and then moved by (dR, dt) about `centre`; a point without a neighbour within `gate`
/// costs 1.
double slideCost(const LocalClouds& s, const Eigen::Matrix3d& R, const Eigen::Vector3d& t,
                 const Eigen::Vector3d& centre, const Eigen::Matrix3d& dR, const Eigen::Vector3d& dt,
                 double d, double gate) {
  const double d2 = d * d;
  const float gate2 = float(gate * gate);
  // Deterministic reduce: the same chunks summed in the same order on every run, so the cost
  // (and the candidates compared on it) do not change with thread timing.
  return tbb::parallel_deterministic_reduce(
             tbb::blocked_range<std::size_t>(0, s.src.size(), 512), 0.0,
             [&](const auto& range, double sum) {
               std::vector<int> idx(1);
               std::vector<float> nd2(1);
               for (std::size_t i = range.begin(); i < range.end(); ++i) {
                 const Eigen::Vector3d x0 = R * s.src[i].getVector3fMap().cast<double>() + t;
                 const Eigen::Vector3d x = dR * (x0 - centre) + centre + dt;
                 const pcl::PointXYZ q(float(x.x()), float(x.y()), float(x.z()));
                 double r2 = d2;
                 if (s.tree.nearestKSearch(q, 1, idx, nd2) == 1 && nd2[0] <= gate2 &&
                     s.normals[idx[0]].allFinite()) {
                   const double r = s.normals[idx[0]].dot(x - s.tgt[idx[0]].getVector3fMap().cast<double>());
                   r2 = std::min(r * r, d2);
                 }
                 sum += r2 / d2;
               }
               return sum;
             },
             std::plus<double>()) /
         double(s.src.size());
}

/// Gate of the slide test's neighbour search, m.
double slideGate(double final_distance) {
  return std::max(final_distance, 0.15) + RefineResult::kSlideDistance;
}

/// RefineResult::direction_resistance: each eigen-direction of res.normal_matrix slid both ways
/// by kSlideDistance (rotations scaled by res.length_scale); the smaller rise of slideCost over
/// res.fit_cost (the cost unmoved), over the overlap ratio.
std::array<double, 6> slideResistance(const LocalClouds& s, const Eigen::Matrix3d& R,
                                      const Eigen::Vector3d& t, const Eigen::Vector3d& centre,
                                      const RefineResult& res, double final_distance) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(res.normal_matrix);
  auto cost = [&](const Eigen::Matrix3d& dR, const Eigen::Vector3d& dt) {
    return slideCost(s, R, t, centre, dR, dt, final_distance, slideGate(final_distance));
  };
  const double base = res.fit_cost;
  std::array<double, 6> out{};
  for (int k = 0; k < 6; ++k) {
    double least = std::numeric_limits<double>::infinity();
    for (double sign : {-1.0, 1.0}) {
      const Eigen::Matrix<double, 6, 1> xi = sign * RefineResult::kSlideDistance * es.eigenvectors().col(k);
      const Eigen::Vector3d w = xi.head<3>() / res.length_scale;
      const Eigen::Matrix3d dR = w.norm() > 0 ? Eigen::AngleAxisd(w.norm(), w.normalized()).toRotationMatrix()
                                             : Eigen::Matrix3d::Identity();
      least = std::min(least, cost(dR, xi.tail<3>()) - base);
    }
    out[k] = res.overlap > 0 ? least / res.overlap : 0.0;
  }
  return out;
}

std::vector<Eigen::Vector3d> gridNormals(const Cloud& c, double cell) {
  struct Acc {
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    Eigen::Matrix3d ss = Eigen::Matrix3d::Zero();
    int n = 0;
    Eigen::Vector3d normal = Eigen::Vector3d::Constant(std::nan(""));
  };
  std::unordered_map<std::uint64_t, Acc> cells;
  std::vector<std::uint64_t> keys(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Eigen::Vector3d p = c[i].getVector3fMap().cast<double>();
    const auto k = [&](double v) { return std::uint64_t(std::int64_t(std::floor(v / cell)) + (1 << 20)); };
    keys[i] = (k(p.x()) << 42) | (k(p.y()) << 21) | k(p.z());
    auto& a = cells[keys[i]];
    a.s += p;
    a.ss += p * p.transpose();
    ++a.n;
  }
  for (auto& [key, a] : cells) {
    if (a.n < 5) continue;
    const Eigen::Vector3d m = a.s / a.n;
    const Eigen::Matrix3d cov = a.ss / a.n - m * m.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
    // Planar enough: smallest eigenvalue well below the middle one.
    if (es.eigenvalues()(0) < 0.1 * es.eigenvalues()(1)) a.normal = es.eigenvectors().col(0);
  }
  std::vector<Eigen::Vector3d> out(c.size());
  for (std::size_t i = 0; i < c.size(); ++i) out[i] = cells[keys[i]].normal;
  return out;
}

/// Points of non-planar cells (edges, corners) get the PCA normal of their 10 nearest
/// neighbours.
void fillEdgeNormals(const Cloud& tgt, const pcl::KdTreeFLANN<pcl::PointXYZ>& tree,
                     std::vector<Eigen::Vector3d>& normals) {
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tgt.size(), 1024), [&](const auto& range) {
    std::vector<int> idx;
    std::vector<float> d2;
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      if (normals[i].allFinite()) continue;
      if (tree.nearestKSearch(tgt[i], 10, idx, d2) < 5) continue;
      Eigen::Vector3d m = Eigen::Vector3d::Zero();
      for (int j : idx) m += tgt[j].getVector3fMap().cast<double>();
      m /= double(idx.size());
      Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
      for (int j : idx) {
        const Eigen::Vector3d q = tgt[j].getVector3fMap().cast<double>() - m;
        cov += q * q.transpose();
      }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov);
      normals[i] = es.eigenvectors().col(0);
    }
  });
}

}  // namespace

struct RefineTarget::Data {
  Eigen::Vector3d origin;  ///< world position of the local frame's origin (target centre)
  double voxel_size = 0.0;
  Cloud::Ptr cloud;        ///< thinned target, local frame
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  std::vector<Eigen::Vector3d> normals;
};

RefineTarget::RefineTarget(const PointCloud& target, const RefineParams& p) : d_(std::make_unique<Data>()) {
  if (target.empty()) throw InputError("refinement needs two non-empty clouds");
  d_->origin = target.bounds().center();
  d_->voxel_size = p.voxel_size;
  // Work in a frame centred on the target: x_local = x_world - origin.
  d_->cloud = toPcl(target, RigidTransform(), d_->origin, p.voxel_size);
  const Cloud::Ptr& tgt = d_->cloud;
  pcl::KdTreeFLANN<pcl::PointXYZ>& tree = d_->tree;
  tree.setInputCloud(tgt);
  // Target normals: PCA of the points in a grid cell of a few voxels (O(n); building surfaces
  // are planar at that scale; mixed cells at edges are rare and trimmed away).
  std::vector<Eigen::Vector3d>& normals = d_->normals;
  normals = gridNormals(*tgt, std::max(0.15, 3 * p.voxel_size));
  fillEdgeNormals(*tgt, tree, normals);
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

/// The refinement's pose in the local frame, applied after the initial transform.
struct LocalPose {
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
};

/// The source points the refinement uses (local frame): voxel-thinned, then every k-th so that
/// at most max_source_points remain.
Cloud::Ptr usedSourcePoints(const PointCloud& source, const RigidTransform& initial,
                            const Eigen::Vector3d& origin, const RefineParams& p) {
  Cloud::Ptr src_all = toPcl(source, initial, origin, p.voxel_size);
  Cloud::Ptr src(new Cloud);
  const std::size_t stride =
      std::max<std::size_t>(1, (src_all->size() + p.max_source_points - 1) / p.max_source_points);
  for (std::size_t i = 0; i < src_all->size(); i += stride) src->push_back((*src_all)[i]);
  return src;
}

/// Correspondences of every `step`-th source point placed by `pose`: its nearest target point
/// within max_d, where the target has a normal; in source order.
std::vector<PlaneCorrespondence> findCorrespondences(const LocalClouds& s, const LocalPose& pose,
                                                     std::size_t step, double max_d) {
  const std::size_t n = (s.src.size() + step - 1) / step;
  std::vector<PlaneCorrespondence> c(n);
  std::vector<char> valid(n, 0);
  const float max_d2 = float(max_d * max_d);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, 512), [&](const auto& range) {
    std::vector<int> idx(1);
    std::vector<float> d2(1);
    for (std::size_t i = range.begin(); i < range.end(); ++i) {
      const Eigen::Vector3d x = pose.R * s.src[i * step].getVector3fMap().cast<double>() + pose.t;
      pcl::PointXYZ q(float(x.x()), float(x.y()), float(x.z()));
      if (s.tree.nearestKSearch(q, 1, idx, d2) < 1 || d2[0] > max_d2) continue;
      const Eigen::Vector3d& nn = s.normals[idx[0]];
      if (!nn.allFinite()) continue;
      const Eigen::Vector3d y = s.tgt[idx[0]].getVector3fMap().cast<double>();
      c[i] = {x, y, nn, nn.dot(x - y)};
      valid[i] = 1;
    }
  });
  std::vector<PlaneCorrespondence> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    if (valid[i]) out.push_back(c[i]);
  return out;
}

struct LoopOutcome {
  LocalPose pose;
  int iterations = 0;
  bool converged = false;
};

/// One stage of trimmed point-to-plane ICP at correspondence distance max_d: up to
/// p.iterations steps (factor, reduction, optimizer: point_to_plane.hpp) until a step is small,
/// which sets out.converged (it stays set for the later stages).
void pointToPlaneStage(const LocalClouds& s, const RefineParams& p, double max_d, std::size_t step,
                       LoopOutcome& out, Progress* progress) {
  using namespace refine_detail;
  for (int it = 0; it < p.iterations; ++it) {
    checkCanceled(progress);
    auto c = findCorrespondences(s, out.pose, step, max_d);
    trimCorrespondences(c, p.trim_fraction, p.trim_per_direction);
    if (c.size() < 6) break;
    const IcpStep d = solveIcpStep(accumulateNormalEquations(c));
    if (!d.finite) break;
    out.pose.R = d.dR * out.pose.R;
    out.pose.t = d.dR * out.pose.t + d.dt;
    ++out.iterations;
    if (stepConverged(d)) {
      out.converged = true;
      break;
    }
  }
}

/// Coarse-to-fine point-to-plane ICP: early stages use a regular quarter of the source points,
/// the last stage all of them. Converged when a step of some stage was small.
LoopOutcome runPointToPlane(const LocalClouds& s, const RefineParams& p, Progress* progress) {
  const int stages = std::max(1, p.stages);
  LoopOutcome out;
  for (int st = 0; st < stages; ++st) {
    pointToPlaneStage(s, p, refine_detail::stageDistance(p.start_distance, p.final_distance, stages, st),
                      st + 1 < stages ? 4 : 1, out, progress);
    reportProgress(progress, 0.1 + 0.8 * (st + 1) / stages, "refine: ICP");
  }
  return out;
}

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

/// Final figures at the final distance (untrimmed: the overlap is what it is). Inliers: a
/// target point within max(final distance, 0.15 m) (sparse or thinned targets) and a
/// point-to-plane residual below the final distance. Then the fit cost and the slide test.
void measureFit(const LocalClouds& s, const LocalPose& pose, const Eigen::Vector3d& origin,
                const RefineParams& p, RefineResult& res) {
  auto c = findCorrespondences(s, pose, 1, std::max(p.final_distance, 0.15));
  const refine_detail::InlierFigures f = refine_detail::inlierFigures(c, p.final_distance);
  res.inliers = f.inliers;
  res.rms = f.rms;
  res.overlap = double(c.size()) / double(s.src.size());
  res.length_scale = f.length_scale;
  res.normal_matrix = f.normal_matrix;
  res.centre = f.centre + origin;
  res.fit_cost = slideCost(s, pose.R, pose.t, f.centre, Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero(),
                           p.final_distance, slideGate(p.final_distance));
  if (!c.empty() && p.slide_test)
    res.direction_resistance = slideResistance(s, pose.R, pose.t, f.centre, res, p.final_distance);
}

}  // namespace

RefineResult refineRegistration(const PointCloud& source, const RefineTarget& prepared,
                                const RigidTransform& initial, const RefineParams& p,
                                Progress* progress) {
  if (source.empty()) throw InputError("refinement needs two non-empty clouds");
  if (p.voxel_size != prepared.data().voxel_size)
    throw InputError("refinement: the target was prepared with another voxel size");
  RefineResult res;
  const Eigen::Vector3d& origin = prepared.data().origin;
  const Cloud::Ptr src = usedSourcePoints(source, initial, origin, p);
  const Cloud::Ptr& tgt = prepared.data().cloud;
  res.source_points = src->size();
  res.target_points = tgt->size();
  if (src->size() < 10 || tgt->size() < 10) throw InputError("refinement: too few points");
  reportProgress(progress, 0.1, "refine: normals");
  const LocalClouds local{*src, *tgt, prepared.data().tree, prepared.data().normals};
  const LoopOutcome loop = p.method == RefineParams::Method::Gicp ? runGicp(src, tgt, p, progress)
                                                                  : runPointToPlane(local, p, progress);
  res.iterations = loop.iterations;
  res.converged = loop.converged;
  measureFit(local, loop.pose, origin, p, res);
  // World transform: x -> origin + delta(initial(x) - origin).
  const RigidTransform to_local(Eigen::Matrix3d::Identity(), -origin);
  const RigidTransform from_local(Eigen::Matrix3d::Identity(), origin);
  res.transform = from_local * RigidTransform(loop.pose.R, loop.pose.t) * to_local * initial;
  if (res.inliers < 10) {
    res.converged = false;
    res.message = "refinement lost its overlap: fewer than 10 correspondences within " +
                  std::to_string(p.final_distance) + " m";
  }
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
