#include "registration/openings/opening_match.hpp"

#include <Eigen/Dense>

#include <cmath>
#include <tuple>

namespace plumb {

namespace {
std::vector<Segment3D> edgesOf(const std::vector<OrientedOpening>& v) {
  std::vector<Segment3D> out;
  for (const auto& o : v)
    for (const auto& e : o.edges) out.push_back(e);
  return out;
}

/// Normal equations of one least-squares step in x = (yaw about c, t), with the weighted
/// squared residuals of the point-to-line rows.
struct YawTranslationSystem {
  Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
  Eigen::Vector4d b = Eigen::Vector4d::Zero();
  double sq = 0.0, wsum = 0.0;
};

/// Mean midpoint of the matched edges (the centre of the yaw).
Eigen::Vector3d matchCentre(const std::vector<ThickEdgeMatch>& matches) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& m : matches) c += 0.5 * (m.a + m.b);
  c /= double(matches.size());
  return c;
}

/// Rows of both endpoints of every match: residual r = P (q - p) - P (z x (p - c)) yaw - P dt.
void addPointToLineRows(const std::vector<ThickEdgeMatch>& matches,
                        const std::vector<Segment3D>& target_edges, const Eigen::Vector3d& c,
                        YawTranslationSystem& sys) {
  for (const auto& m : matches) {
    const Segment3D& q = target_edges[m.target_edge];
    const Eigen::Vector3d dir = (q.b - q.a).normalized();
    // Point-to-line (2023 eq. 11, A = I - d d^T) without the façade-normal component.
    const Eigen::Matrix3d P = Eigen::Matrix3d::Identity() - dir * dir.transpose() -
                              m.facade_normal * m.facade_normal.transpose();
    for (const Eigen::Vector3d& p : {m.a, m.b}) {
      const Eigen::Vector3d r = P * (q.a - p);
      Eigen::Matrix<double, 3, 4> J;
      J.col(0) = P * Eigen::Vector3d::UnitZ().cross(p - c);
      J.rightCols<3>() = P;
      sys.A += m.similarity * J.transpose() * J;
      sys.b += m.similarity * J.transpose() * r;
      sys.sq += m.similarity * r.squaredNorm();
      sys.wsum += m.similarity;
    }
  }
}

/// Façade group of each match: normals within 30° and target edges within 2d of the plane
/// of the group's first edge. Returns the number of groups.
int facadeGroups(const std::vector<ThickEdgeMatch>& matches,
                 const std::vector<Segment3D>& target_edges, double d, std::vector<int>& group) {
  group.assign(matches.size(), -1);
  int groups = 0;
  for (std::size_t i = 0; i < matches.size(); ++i) {
    if (group[i] >= 0) continue;
    group[i] = groups;
    const auto& mi = matches[i];
    const Segment3D& qi = target_edges[mi.target_edge];
    for (std::size_t j = i + 1; j < matches.size(); ++j) {
      const auto& mj = matches[j];
      if (group[j] < 0 && mi.facade_normal.dot(mj.facade_normal) > std::cos(M_PI / 6) &&
          std::abs(mi.facade_normal.dot(target_edges[mj.target_edge].a - qi.a)) < 2 * d)
        group[j] = groups;
    }
    ++groups;
  }
  return groups;
}

/// Openings on one façade lie in one plane whatever the wall thickness: the spread of their
/// normal offsets about the façade's mean offset observes the yaw (the zero-thickness
/// placement of the paper, with the common thickness eliminated per façade).
void addCoplanarityRows(const std::vector<ThickEdgeMatch>& matches,
                        const std::vector<Segment3D>& target_edges, const Eigen::Vector3d& c,
                        double d, YawTranslationSystem& sys) {
  std::vector<int> group;
  const int groups = facadeGroups(matches, target_edges, d, group);
  for (int g = 0; g < groups; ++g) {
    double mr = 0.0, mj = 0.0, w = 0.0;
    std::vector<std::tuple<double, double, double>> rows;  // residual, d/dyaw, weight
    for (std::size_t i = 0; i < matches.size(); ++i) {
      if (group[i] != g) continue;
      const auto& m = matches[i];
      const Segment3D& q = target_edges[m.target_edge];
      for (const Eigen::Vector3d& p : {m.a, m.b}) {
        // Before the per-opening move onto the façade face (the move would hide the yaw).
        const double r = m.facade_normal.dot(q.a - p) + m.thickness;
        const double jy = m.facade_normal.dot(Eigen::Vector3d::UnitZ().cross(p - c));
        rows.emplace_back(r, jy, m.similarity);
        mr += m.similarity * r;
        mj += m.similarity * jy;
        w += m.similarity;
      }
    }
    if (rows.size() < 4 || w <= 0) continue;
    mr /= w;
    mj /= w;
    for (const auto& [r, jy, wt] : rows) {
      sys.A(0, 0) += wt * (jy - mj) * (jy - mj);
      sys.b(0) += wt * (jy - mj) * (r - mr);
    }
  }
}

/// Whether the matches lie on non-parallel façades (normals more than 30° apart).
bool twoFacadeDirections(const std::vector<ThickEdgeMatch>& matches) {
  bool two_directions = false;
  for (const auto& m : matches)
    if (std::abs(m.facade_normal.dot(matches.front().facade_normal)) < std::cos(M_PI / 6))
      two_directions = true;
  return two_directions;
}

/// The step x = (yaw, t). The yaw is only observable with openings on non-parallel façades
/// (on one façade it moves the edges along the façade normal, which is free). Without it,
/// the translation alone, minimum-norm: no motion along an unconstrained direction. False
/// when the system is not determined.
bool solveYawTranslation(const YawTranslationSystem& sys, bool two_directions,
                         Eigen::Vector4d& x) {
  const Eigen::Matrix4d& A = sys.A;
  const Eigen::Vector4d& b = sys.b;
  x = Eigen::Vector4d::Zero();
  if (two_directions) {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> es(A);
    if (es.eigenvalues()(0) < 1e-6 * es.eigenvalues()(3)) return false;
    x = A.ldlt().solve(b);
  } else if (A(0, 0) > 0.0) {
    // One façade: yaw from the coplanarity rows, then the in-plane translation (min-norm).
    x(0) = b(0) / A(0, 0);
    const Eigen::Matrix3d At = A.bottomRightCorner<3, 3>();
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(At, Eigen::ComputeFullU | Eigen::ComputeFullV);
    svd.setThreshold(1e-3);
    x.tail<3>() = svd.solve(b.tail<3>() - A.block<3, 1>(1, 0) * x(0));
  } else {
    const Eigen::Matrix3d At = A.bottomRightCorner<3, 3>();
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(At, Eigen::ComputeFullU | Eigen::ComputeFullV);
    svd.setThreshold(1e-3);
    x.tail<3>() = svd.solve(b.tail<3>());
  }
  return true;
}

}  // namespace

std::vector<OrientedOpening> orientedOpenings(const FeatureSet& f, double vertical_tolerance_deg) {
  std::vector<OrientedOpening> out;
  const double sin_tol = std::sin(vertical_tolerance_deg * M_PI / 180.0);
  for (std::size_t i = 0; i < f.openings.size(); ++i) {
    const Opening& o = f.openings[i];
    // Counter-clockwise seen from the scanner side: (c1 - c0) x (c3 - c0) points to it.
    const Eigen::Vector3d n = (o.corners[1] - o.corners[0]).cross(o.corners[3] - o.corners[0]);
    if (n.norm() < 1e-6) continue;
    OrientedOpening k;
    k.index = int(i);
    k.normal = n.normalized();
    // The wall plane's normal is far more precise than the corners' (fitted on every inlier);
    // the corners only give its sign.
    if (o.facade >= 0 && o.facade < int(f.planes.size())) {
      const Eigen::Vector3d w = f.planes[o.facade].normal;
      if (w.allFinite() && std::abs(w.dot(k.normal)) > std::cos(M_PI / 12))
        k.normal = w.dot(k.normal) >= 0 ? Eigen::Vector3d(w) : Eigen::Vector3d(-w);
    }
    if (std::abs(k.normal.z()) > sin_tol) continue;  // not in a vertical wall
    k.centre = 0.25 * (o.corners[0] + o.corners[1] + o.corners[2] + o.corners[3]);
    k.width = o.width();
    k.height = o.height();
    k.edges = o.edges();
    out.push_back(k);
  }
  return out;
}

ThickOpeningMatcher::ThickOpeningMatcher(std::vector<OrientedOpening> target,
                                         const SegmentDistanceParams& distance,
                                         double max_thickness, double angle_tolerance_deg)
    : target_(std::move(target)),
      index_(edgesOf(target_), distance),
      max_thickness_(max_thickness),
      cos_tol_(std::cos(angle_tolerance_deg * M_PI / 180.0)),
      d_(distance.robust_distance) {}

ThickScore ThickOpeningMatcher::score(const std::vector<OrientedOpening>& source,
                                      const RigidTransform& t, bool keep) const {
  ThickScore out;
  const double d2 = d_ * d_;
  for (const auto& s : source) {
    const Eigen::Vector3d n = t.rotation() * s.normal;  // into the room
    const Eigen::Vector3d c = t.apply(s.centre);
    // The façade face this opening sits behind: a facing target opening (opposite normals)
    // whose plane lies in front of it by a plausible thickness; the nearest one defines it.
    int best = -1;
    double best_dist = 1e300, thick = 0.0;
    for (std::size_t j = 0; j < target_.size(); ++j) {
      const auto& o = target_[j];
      if (n.dot(o.normal) > -cos_tol_) continue;
      const double th = -o.normal.dot(c - o.centre);  // > 0: behind the façade face
      if (th < -d_ || th > max_thickness_) continue;
      const double dist = (c - o.centre).squaredNorm();
      if (dist < best_dist) {
        best_dist = dist;
        best = int(j);
        thick = th;
      }
    }
    if (best < 0) continue;
    const Eigen::Vector3d move = thick * target_[best].normal;  // onto the façade face
    int matched_edges = 0;
    for (const auto& e : s.edges) {
      const Eigen::Vector3d a = t.apply(e.a) + move, b = t.apply(e.b) + move;
      const SegmentMatch m = index_.match(a, b);
      const double sim = 1.0 - m.cost / d2;
      if (sim <= 0.0 || m.target < 0) continue;
      out.score += sim;
      if (sim > 0.5) ++matched_edges;
      if (keep) out.matches.push_back({a, b, m.target, target_[best].normal, sim, thick});
    }
    if (matched_edges >= 2) {
      ++out.matched_openings;
      out.thickness.push_back(thick);
    }
  }
  return out;
}

RigidTransform ThickOpeningMatcher::polish(const std::vector<OrientedOpening>& source,
                                           const RigidTransform& start, int iterations,
                                           double* rms) const {
  RigidTransform t = start;
  for (int it = 0; it < iterations; ++it) {
    const ThickScore s = score(source, t, true);
    if (s.matches.empty()) break;
    const Eigen::Vector3d c = matchCentre(s.matches);
    // Unknowns x = (yaw about c, t): residual r = P (q - p) - P (z x (p - c)) yaw - P dt.
    YawTranslationSystem sys;
    addPointToLineRows(s.matches, index_.segments(), c, sys);
    addCoplanarityRows(s.matches, index_.segments(), c, d_, sys);
    if (rms) *rms = sys.wsum > 0 ? std::sqrt(sys.sq / sys.wsum) : 0.0;
    if (sys.wsum <= 0) break;
    Eigen::Vector4d x;
    if (!solveYawTranslation(sys, twoFacadeDirections(s.matches), x)) break;
    const Eigen::Matrix3d dR = Eigen::AngleAxisd(x(0), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    t = RigidTransform(dR * t.rotation(), dR * (t.translation() - c) + c + x.tail<3>());
    if (std::abs(x(0)) < 1e-7 && x.tail<3>().norm() < 1e-5) break;
  }
  return t;
}

}  // namespace plumb
