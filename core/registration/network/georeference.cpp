// Georeferencing a network on control points (georeference.hpp).
#include "registration/network/georeference.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
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

/// The observed point's given coordinates in the ground frame.
Eigen::Vector3d groundOf(const ControlSurvey& survey, const Seen& s) {
  return survey.grid.toGround(survey.points[s.point].grid);
}

/// Rigid fit (Umeyama, no scale) of the control targets among `seen`, each observed at
/// `where(seen)`, onto the ground frame.
template <class Where>
RigidTransform fitControl(const ControlSurvey& survey, const std::vector<Seen>& seen, Where where) {
  std::vector<Eigen::Vector3d> from, to;
  for (const auto& s : seen)
    if (!survey.points[s.point].check) {
      from.push_back(where(s));
      to.push_back(groundOf(survey, s));
    }
  Eigen::Matrix3Xd src(3, from.size()), dst(3, to.size());
  for (std::size_t i = 0; i < from.size(); ++i) {
    src.col(long(i)) = from[i];
    dst.col(long(i)) = to[i];
  }
  const Eigen::Matrix4d m = Eigen::umeyama(src, dst, false);
  return RigidTransform(m.topLeftCorner<3, 3>(), m.topRightCorner<3, 1>());
}

/// A control observation this far from its point under the first fit is a gross error: the
/// links placed its station wrong (a half turn, an identical room), not a few centimetres of
/// drift, which the adjustment on the control absorbs. 10 times the drop translation.
double grossError(const PoseGraphParams& p) { return 10.0 * p.drop_translation; }

double misfit(const ControlSurvey& survey, const Seen& s, const RigidTransform& pose) {
  return (pose.apply(s.observed) - groundOf(survey, s)).norm();
}

/// The placed stations' control targets fitted onto the ground frame: the network's first move.
/// A station the links placed wrong must not tilt it, so the fit is the consensus of every triple
/// of control observations (most observations within the gross-error distance, then the
/// smallest squared misfit), refitted on the observations it agrees with.
RigidTransform firstFit(const ControlSurvey& survey, const std::vector<Seen>& seen, const NetworkAdjustment& a,
                        const PoseGraphParams& params) {
  std::vector<Seen> control;
  for (const auto& s : seen)
    if (!survey.points[s.point].check) control.push_back(s);
  const auto where = [&](const Seen& s) { return a.poses[s.station]->apply(s.observed); };
  const auto agreeing = [&](const RigidTransform& fit, double& cost) {
    std::vector<Seen> in;
    cost = 0.0;
    for (const auto& s : control) {
      const double d = misfit(survey, s, fit * *a.poses[s.station]);
      if (d <= grossError(params)) in.push_back(s), cost += d * d;
    }
    return in;
  };
  std::vector<Seen> best;
  double best_cost = 0.0;
  std::size_t tried = 0;
  for (std::size_t i = 0; i < control.size() && tried < 4000; ++i)
    for (std::size_t j = i + 1; j < control.size() && tried < 4000; ++j)
      for (std::size_t k = j + 1; k < control.size() && tried < 4000; ++k, ++tried) {
        const std::vector<Seen> triple{control[i], control[j], control[k]};
        if (!spanProblem(survey, triple).empty()) continue;
        double cost = 0.0;
        auto in = agreeing(fitControl(survey, triple, where), cost);
        if (in.size() > best.size() || (in.size() == best.size() && cost < best_cost))
          best = std::move(in), best_cost = cost;
      }
  return fitControl(survey, best.size() >= 3 ? best : control, where);
}

std::vector<Seen> seenBy(const std::vector<Seen>& seen, const std::vector<bool>& stations) {
  std::vector<Seen> out;
  for (const auto& s : seen)
    if (stations[s.station]) out.push_back(s);
  return out;
}

std::vector<Seen> seenByStation(const std::vector<Seen>& seen, std::size_t station) {
  std::vector<Seen> out;
  for (const auto& s : seen)
    if (s.station == station) out.push_back(s);
  return out;
}

/// The georeferenced solve's state: which stations it places, which links it keeps, the poses.
struct ControlSolve {
  std::vector<bool> placed;          ///< per station
  std::vector<bool> active;          ///< per link
  std::vector<RigidTransform> poses; ///< ground frame
};

/// Start: every placed station moved by `fit`, except a station that sees 3 control points
/// itself and whose own resection puts it elsewhere (beyond the drop thresholds): the control
/// says its links placed it wrong, so it starts where the control puts it. A station with fewer
/// whose control observations are gross errors at its start is unplaced (`g.unplaced`): its
/// links placed it wrong and its own targets cannot place it.
ControlSolve startControlSolve(const ControlSurvey& survey, const std::vector<Seen>& seen,
                               const std::vector<AdjustmentLink>& links, const PoseGraphParams& params,
                               const NetworkAdjustment& a, const RigidTransform& fit, Georeference& g) {
  ControlSolve c;
  for (std::size_t i = 0; i < a.poses.size(); ++i) {
    c.placed.push_back(a.poses[i].has_value());
    c.poses.push_back(a.poses[i] ? fit * *a.poses[i] : RigidTransform());
    if (!a.poses[i]) continue;
    std::vector<Seen> own;
    for (const auto& s : seenByStation(seen, i))
      if (!survey.points[s.point].check) own.push_back(s);
    if (spanProblem(survey, own).empty()) {
      const RigidTransform resection = fitControl(survey, own, [](const Seen& s) { return s.observed; });
      if (!samePlacement(resection, c.poses[i], params)) c.poses[i] = resection;
    } else if (std::any_of(own.begin(), own.end(),
                           [&](const Seen& s) { return misfit(survey, s, c.poses[i]) > grossError(params); })) {
      c.placed[i] = false;
      g.unplaced.push_back(i);
    }
  }
  for (std::size_t k = 0; k < links.size(); ++k)
    c.active.push_back(!a.links[k].dropped && c.placed[links[k].a] && c.placed[links[k].b]);
  return c;
}

/// The kept links from a station the control still holds to one unplaced for gross errors
/// (startControlSolve) placed it wrong: dropped.
void dropLinksToGrossErrors(const std::vector<AdjustmentLink>& links, ControlSolve& c, NetworkAdjustment& a,
                            Georeference& g) {
  const auto gross = [&](std::size_t i) { return std::find(g.unplaced.begin(), g.unplaced.end(), i) != g.unplaced.end(); };
  for (std::size_t k = 0; k < links.size(); ++k) {
    const auto& l = links[k];
    if (a.links[k].dropped || !((gross(l.a) && c.placed[l.b]) || (gross(l.b) && c.placed[l.a]))) continue;
    a.links[k].dropped = a.links[k].dropped_by_control = true;
    a.dropped_order.push_back(k);
    c.active[k] = false;
    ++g.links_dropped;
  }
}

/// Links touching a station no longer placed are no longer active.
void deactivateLinksOfUnplaced(const std::vector<AdjustmentLink>& links, ControlSolve& c) {
  for (std::size_t k = 0; k < links.size(); ++k) c.active[k] = c.active[k] && c.placed[links[k].a] && c.placed[links[k].b];
}

/// Groups of placed stations (joined by active links) that do not see 3 control points, not in
/// a line, are unplaced and their links deactivated. Returns the stations unplaced.
std::vector<std::size_t> unplaceUncontrolled(const ControlSurvey& survey, const std::vector<Seen>& seen,
                                             const std::vector<AdjustmentLink>& links, ControlSolve& c) {
  const std::size_t n = c.placed.size();
  deactivateLinksOfUnplaced(links, c);
  std::vector<GraphEdge> edges;
  for (std::size_t k = 0; k < links.size(); ++k)
    if (c.active[k]) edges.push_back({links[k].a, links[k].b, links[k].transform});
  const auto component = connectedComponents(n, edges);
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < n; ++i) {
    if (!c.placed[i]) continue;
    std::vector<bool> group(n, false);
    for (std::size_t j = 0; j < n; ++j) group[j] = c.placed[j] && component[j] == component[i];
    if (spanProblem(survey, seenBy(seen, group)).empty()) continue;
    for (std::size_t j = 0; j < n; ++j)
      if (group[j]) c.placed[j] = false, out.push_back(j);
  }
  deactivateLinksOfUnplaced(links, c);
  std::sort(out.begin(), out.end());
  return out;
}

/// The pose graph of the active links and the placed stations' control observations, no station
/// fixed; `edge_link[e]` is the link of edge e.
PoseGraphProblem controlProblem(const ControlSurvey& survey, const std::vector<Seen>& seen,
                                const std::vector<AdjustmentLink>& links, const PoseGraphParams& params,
                                const ControlSolve& c, std::vector<std::size_t>& edge_link) {
  PoseGraphProblem pg;
  pg.initial = c.poses;
  pg.fix_reference = false;
  pg.robust_scale = params.robust_scale;
  pg.max_iterations = params.max_iterations;
  edge_link.clear();
  for (std::size_t k = 0; k < links.size(); ++k)
    if (c.active[k]) {
      pg.edges.push_back(poseGraphEdge(links[k]));
      edge_link.push_back(k);
    }
  for (const auto& s : seen)
    if (!survey.points[s.point].check && c.placed[s.station])
      pg.points.push_back({s.station, s.observed, groundOf(survey, s), survey.sigma});
  return pg;
}

/// The link whose residual exceeds the drop thresholds by the largest factor; npos when none.
std::size_t worstLink(const PoseGraphSolution& s, const std::vector<std::size_t>& edge_link,
                      const PoseGraphParams& p) {
  std::size_t worst = std::string::npos;
  double factor = 1.0;
  for (std::size_t e = 0; e < edge_link.size(); ++e) {
    const double f = std::max(s.residuals[e].translation / p.drop_translation, s.residuals[e].rotation_deg / p.drop_rotation);
    if (f > factor) factor = f, worst = edge_link[e];
  }
  return worst;
}

/// Solves, dropping the link the control contradicts most and unplacing groups the control no
/// longer holds, until no link exceeds the drop thresholds (or auto-drop is off). Returns the
/// last solution, or nothing when no station is left placed.
std::optional<PoseGraphSolution> solveWithControl(const ControlSurvey& survey, const std::vector<Seen>& seen,
                                                  const std::vector<AdjustmentLink>& links,
                                                  const PoseGraphParams& params, ControlSolve& c,
                                                  NetworkAdjustment& a, Georeference& g) {
  for (;;) {
    const auto unplaced = unplaceUncontrolled(survey, seen, links, c);
    g.unplaced.insert(g.unplaced.end(), unplaced.begin(), unplaced.end());
    if (std::none_of(c.placed.begin(), c.placed.end(), [](bool b) { return b; })) return std::nullopt;
    std::vector<std::size_t> edge_link;
    PoseGraphSolution s = solvePoseGraph(controlProblem(survey, seen, links, params, c, edge_link));
    c.poses = s.poses;
    const std::size_t worst = params.auto_drop ? worstLink(s, edge_link, params) : std::string::npos;
    if (worst == std::string::npos) return s;
    c.active[worst] = false;
    a.links[worst].dropped = a.links[worst].dropped_by_control = true;
    a.dropped_order.push_back(worst);
    ++g.links_dropped;
  }
}

std::vector<PointResidual> pointResiduals(const ControlSurvey& survey, const std::vector<Seen>& seen,
                                          const std::vector<RigidTransform>& ground_poses) {
  std::vector<PointResidual> out;
  for (const auto& p : survey.points) out.push_back({p.name, p.check});
  for (const auto& s : seen) {
    auto& r = out[s.point];
    r.ground += ground_poses[s.station].apply(s.observed) - groundOf(survey, s);
    ++r.observations;
  }
  const double k = survey.grid.scale_factor;
  for (auto& r : out) {
    if (r.observations > 0) r.ground /= double(r.observations);
    r.grid = Eigen::Vector3d(r.ground.x() * k, r.ground.y() * k, r.ground.z());
  }
  return out;
}

/// Placed stations that see 3 control points (not in a line) themselves, each within the drop
/// translation at the station's pose.
std::vector<std::size_t> settledStations(const ControlSurvey& survey, const std::vector<Seen>& seen,
                                         const ControlSolve& c, const PoseGraphParams& params) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < c.placed.size(); ++i) {
    const auto own = seenByStation(seen, i);
    if (!c.placed[i] || !spanProblem(survey, own).empty()) continue;
    const bool agree = std::all_of(own.begin(), own.end(), [&](const Seen& s) {
      return survey.points[s.point].check || misfit(survey, s, c.poses[i]) <= params.drop_translation;
    });
    if (agree) out.push_back(i);
  }
  return out;
}

/// Placed stations seeing a check point beyond the drop translation at their pose; each is
/// unplaced, then the groups that no longer see 3 control points.
void unplaceCheckFailures(const ControlSurvey& survey, const std::vector<Seen>& seen,
                          const std::vector<AdjustmentLink>& links, const PoseGraphParams& params, ControlSolve& c,
                          Georeference& g) {
  for (const auto& s : seen) {
    if (!survey.points[s.point].check || !c.placed[s.station]) continue;
    const double d = misfit(survey, s, c.poses[s.station]);
    if (d > params.drop_translation) g.check_failures.push_back({s.station, survey.points[s.point].name, d});
  }
  for (const auto& f : g.check_failures)
    if (c.placed[f.station]) c.placed[f.station] = false, g.unplaced.push_back(f.station);
  const auto lost = unplaceUncontrolled(survey, seen, links, c);
  g.unplaced.insert(g.unplaced.end(), lost.begin(), lost.end());
}

/// The solution written back: poses at the grid origin (stations the control no longer holds
/// unplaced), sigmas, chain poses, link residuals.
void writeBack(const PoseGraphSolution& s, const ControlSolve& c, const RigidTransform& fit, const GridFrame& grid,
               const std::vector<AdjustmentLink>& links, const PoseGraphParams& params, NetworkAdjustment& a) {
  const RigidTransform to_grid_origin(Eigen::Matrix3d::Identity(), grid.origin);
  for (std::size_t k = 0; k < links.size(); ++k) {  // a station unplaced keeps its start pose in s: how far off it was
    const auto& l = links[k];
    LinkOutcome& o = a.links[k];
    if (!a.poses[l.a] || !a.poses[l.b]) continue;
    o.residual = edgeResidual(poseGraphEdge(l), s.poses[l.a], s.poses[l.b]);
    o.flagged = c.placed[l.a] && c.placed[l.b] && beyondFlag(o.residual, params);
  }
  for (std::size_t i = 0; i < a.poses.size(); ++i) {
    if (!a.poses[i]) continue;
    if (!c.placed[i]) {
      a.poses[i].reset();
      if (i < a.chain_poses.size()) a.chain_poses[i].reset();
      continue;
    }
    a.poses[i] = to_grid_origin * s.poses[i];
    a.sigma_position[i] = s.sigma_position[i];
    a.sigma_rotation_deg[i] = s.sigma_rotation_deg[i];
    if (i < a.chain_poses.size() && a.chain_poses[i]) a.chain_poses[i] = to_grid_origin * fit * *a.chain_poses[i];
  }
  a.covariance_ok = s.covariance_ok;
  a.converged = s.converged;
  a.message = s.message;
  ++a.solves;
}

void summarise(Georeference& g) {
  g.control_used = 0;
  g.check_max = 0.0;
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

void mergeGeoreference(Georeference& into, const Georeference& part) {
  const double k = into.grid.scale_factor;
  for (std::size_t i = 0; i < into.points.size() && i < part.points.size(); ++i) {
    PointResidual& r = into.points[i];
    const PointResidual& p = part.points[i];
    const std::size_t n = r.observations + p.observations;
    if (p.observations == 0) continue;
    r.ground = (r.ground * double(r.observations) + p.ground * double(p.observations)) / double(n);
    r.observations = n;
    r.grid = Eigen::Vector3d(r.ground.x() * k, r.ground.y() * k, r.ground.z());
  }
  sortedUnion(into.settled, part.settled);
  sortedUnion(into.unplaced, part.unplaced);
  into.links_dropped += part.links_dropped;
  into.check_failures.insert(into.check_failures.end(), part.check_failures.begin(), part.check_failures.end());
  summarise(into);
}

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
  const auto notDone = [&](const std::string& why) {
    g.message = "not georeferenced: " + why;
    for (const auto& p : survey.points) g.points.push_back({p.name, p.check});
    return g;
  };
  if (const std::string why = spanProblem(survey, seen); !why.empty()) return notDone(why);
  const RigidTransform fit = firstFit(survey, seen, adjustment, params);
  ControlSolve c = startControlSolve(survey, seen, links, params, adjustment, fit, g);
  NetworkAdjustment solved = adjustment;  // left as it was when the control holds nothing
  dropLinksToGrossErrors(links, c, solved, g);
  const auto s = solveWithControl(survey, seen, links, params, c, solved, g);
  if (!s) return notDone("the control points contradict the links of every group of stations that sees them");
  unplaceCheckFailures(survey, seen, links, params, c, g);
  std::sort(g.unplaced.begin(), g.unplaced.end());
  adjustment = std::move(solved);
  writeBack(*s, c, fit, survey.grid, links, params, adjustment);
  g.points = pointResiduals(survey, seenBy(seen, c.placed), s->poses);
  g.settled = settledStations(survey, seen, c, params);
  g.done = true;
  summarise(g);
  g.message = "georeferenced on " + std::to_string(g.control_used) + " control point(s)";
  if (g.links_dropped) g.message += "; " + std::to_string(g.links_dropped) + " link(s) the control points contradict dropped";
  if (!g.check_failures.empty())
    g.message += "; " + std::to_string(g.check_failures.size()) + " check point observation(s) contradict their station";
  return g;
}

}  // namespace plumb
