// Georeferencing a network on control points (georeference.hpp).
#include "registration/network/georeference.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "common/error.hpp"

namespace plumb {
namespace {

struct Seen {
  std::size_t station, point;  // indices into the station names and survey.points
  Eigen::Vector3d observed;
};

std::vector<Seen> observationsOfPlacedStations(const ControlSurvey& survey, const std::vector<std::string>& names,
                                               const NetworkAdjustment& a) {
  std::map<std::string, std::size_t> station, point;
  for (std::size_t i = 0; i < names.size(); ++i) station[names[i]] = i;
  for (std::size_t i = 0; i < survey.points.size(); ++i) point[survey.points[i].name] = i;
  std::vector<Seen> out;
  for (const auto& o : survey.observations) {
    const std::size_t s = station.at(o.station);
    if (a.poses[s]) out.push_back({s, point.at(o.point), o.position});
  }
  return out;
}

/// The control points among `seen` span a plane: at least 3, their spread's middle axis over
/// 5 cm (a line of targets leaves the rotation about it free).
std::string spanProblem(const ControlSurvey& survey, const std::vector<Seen>& seen) {
  std::set<std::size_t> used;
  for (const auto& s : seen)
    if (!survey.points[s.point].check) used.insert(s.point);
  if (used.size() < 3)
    return std::to_string(used.size()) + " control point(s) seen by placed stations; 3 are needed";
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (std::size_t p : used) mean += survey.points[p].grid;
  mean /= double(used.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (std::size_t p : used) cov += (survey.points[p].grid - mean) * (survey.points[p].grid - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov / double(used.size()));
  if (std::sqrt(std::max(0.0, es.eigenvalues()(1))) < 0.05) return "the control points seen lie in a line";
  return {};
}

/// Rigid fit (Umeyama, no scale) of the placed stations' control targets onto the ground frame.
RigidTransform firstFit(const ControlSurvey& survey, const std::vector<Seen>& seen, const NetworkAdjustment& a) {
  std::vector<Eigen::Vector3d> from, to;
  for (const auto& s : seen)
    if (!survey.points[s.point].check) {
      from.push_back(a.poses[s.station]->apply(s.observed));
      to.push_back(survey.grid.toGround(survey.points[s.point].grid));
    }
  Eigen::Matrix3Xd src(3, from.size()), dst(3, to.size());
  for (std::size_t i = 0; i < from.size(); ++i) {
    src.col(long(i)) = from[i];
    dst.col(long(i)) = to[i];
  }
  const Eigen::Matrix4d m = Eigen::umeyama(src, dst, false);
  return RigidTransform(m.topLeftCorner<3, 3>(), m.topRightCorner<3, 1>());
}

PoseGraphProblem controlProblem(const ControlSurvey& survey, const std::vector<Seen>& seen,
                                const std::vector<AdjustmentLink>& links, const PoseGraphParams& params,
                                const NetworkAdjustment& a, const RigidTransform& fit) {
  PoseGraphProblem pg;
  for (const auto& p : a.poses) pg.initial.push_back(p ? fit * *p : RigidTransform());
  pg.fix_reference = false;
  pg.robust_scale = params.robust_scale;
  pg.max_iterations = params.max_iterations;
  for (std::size_t k = 0; k < links.size(); ++k) {
    const auto& l = links[k];
    if (!a.links[k].dropped && a.poses[l.a] && a.poses[l.b])
      pg.edges.push_back(poseGraphEdge(l));
  }
  for (const auto& s : seen)
    if (!survey.points[s.point].check)
      pg.points.push_back({s.station, s.observed, survey.grid.toGround(survey.points[s.point].grid), survey.sigma});
  return pg;
}

std::vector<PointResidual> pointResiduals(const ControlSurvey& survey, const std::vector<Seen>& seen,
                                          const std::vector<RigidTransform>& ground_poses) {
  std::vector<PointResidual> out;
  for (const auto& p : survey.points) out.push_back({p.name, p.check});
  for (const auto& s : seen) {
    auto& r = out[s.point];
    r.ground += ground_poses[s.station].apply(s.observed) - survey.grid.toGround(survey.points[s.point].grid);
    ++r.observations;
  }
  const double k = survey.grid.scale_factor;
  for (auto& r : out) {
    if (r.observations > 0) r.ground /= double(r.observations);
    r.grid = Eigen::Vector3d(r.ground.x() * k, r.ground.y() * k, r.ground.z());
  }
  return out;
}

/// The solution written back: poses at the grid origin, sigmas, chain poses, link residuals.
void writeBack(const PoseGraphSolution& s, const RigidTransform& fit, const GridFrame& grid,
               const std::vector<AdjustmentLink>& links, const PoseGraphParams& params, NetworkAdjustment& a) {
  const RigidTransform to_grid_origin(Eigen::Matrix3d::Identity(), grid.origin);
  for (std::size_t i = 0; i < a.poses.size(); ++i) {
    if (!a.poses[i]) continue;
    a.poses[i] = to_grid_origin * s.poses[i];
    a.sigma_position[i] = s.sigma_position[i];
    a.sigma_rotation_deg[i] = s.sigma_rotation_deg[i];
    if (i < a.chain_poses.size() && a.chain_poses[i]) a.chain_poses[i] = to_grid_origin * fit * *a.chain_poses[i];
  }
  for (std::size_t k = 0; k < links.size(); ++k) {
    const auto& l = links[k];
    LinkOutcome& o = a.links[k];
    if (o.dropped || !a.poses[l.a] || !a.poses[l.b]) continue;
    o.residual = edgeResidual(poseGraphEdge(l), s.poses[l.a], s.poses[l.b]);
    o.flagged = beyondFlag(o.residual, params);
  }
  a.covariance_ok = s.covariance_ok;
  a.converged = s.converged;
  a.message = s.message;
  ++a.solves;
}

void summarise(Georeference& g) {
  double sum2 = 0.0;
  for (const auto& r : g.points) {
    if (r.observations == 0) continue;
    if (r.check) {
      g.check_max = std::max(g.check_max, r.ground.norm());
    } else {
      sum2 += r.ground.squaredNorm();
      ++g.control_used;
    }
  }
  g.control_rms = g.control_used ? std::sqrt(sum2 / double(g.control_used)) : 0.0;
}

}  // namespace

void checkObservations(const ControlSurvey& survey, const std::vector<std::string>& names) {
  const std::set<std::string> stations(names.begin(), names.end());
  std::set<std::string> points;
  for (const auto& p : survey.points) points.insert(p.name);
  for (const auto& o : survey.observations) {
    if (!stations.count(o.station)) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      throw FileError(survey.targets_file, "no station is named '" + o.station + "' (the stations: " + list + ")",
                      atLine(o.line));
    }
    if (!points.count(o.point))
      throw FileError(survey.targets_file, "point '" + o.point + "' is not in the control points file",
                      atLine(o.line));
  }
}

Georeference georeferenceNetwork(const ControlSurvey& survey, const std::vector<std::string>& names,
                                 const std::vector<AdjustmentLink>& links, const PoseGraphParams& params,
                                 NetworkAdjustment& adjustment) {
  checkObservations(survey, names);
  Georeference g;
  g.grid = survey.grid;
  const std::vector<Seen> seen = observationsOfPlacedStations(survey, names, adjustment);
  if (const std::string why = spanProblem(survey, seen); !why.empty()) {
    g.message = "not georeferenced: " + why;
    for (const auto& p : survey.points) g.points.push_back({p.name, p.check});
    return g;
  }
  const RigidTransform fit = firstFit(survey, seen, adjustment);
  const PoseGraphSolution s = solvePoseGraph(controlProblem(survey, seen, links, params, adjustment, fit));
  writeBack(s, fit, survey.grid, links, params, adjustment);
  g.points = pointResiduals(survey, seen, s.poses);
  g.done = true;
  summarise(g);
  g.message = "georeferenced on " + std::to_string(g.control_used) + " control point(s)";
  return g;
}

}  // namespace plumb
