#include "unit/registration/synthetic_building.hpp"

#include <cmath>

namespace plumb::test {

PlanarPolygon makeRectPolygon(const Eigen::Vector3d& origin, const Eigen::Vector3d& u,
                              const Eigen::Vector3d& v, double w, double h,
                              const std::vector<Eigen::Vector4d>& holes, std::size_t inliers) {
  PlanarPolygon p;
  p.u_axis = u.normalized();
  p.v_axis = v.normalized();
  p.normal = p.u_axis.cross(p.v_axis);
  p.origin = origin;
  p.offset = p.normal.dot(origin);
  p.rings.push_back({{0, 0}, {w, 0}, {w, h}, {0, h}});
  double area = w * h;
  for (const auto& hl : holes) {
    p.rings.push_back({{hl[0], hl[1]}, {hl[0], hl[3]}, {hl[2], hl[3]}, {hl[2], hl[1]}});
    area -= (hl[2] - hl[0]) * (hl[3] - hl[1]);
  }
  p.area = area;
  p.centroid = p.to3d({w / 2, h / 2});
  p.inlier_count = inliers ? inliers : std::size_t(area * 400);
  return p;
}

namespace {
void addSegment(FeatureSet& f, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  Segment3D s;
  s.a = a;
  s.b = b;
  s.support = 100;
  f.segments.push_back(s);
}
}  // namespace

FeatureSet roomFeatures(const std::vector<Room>& rooms, bool windows) {
  FeatureSet f;
  const Eigen::Vector3d X = Eigen::Vector3d::UnitX(), Y = Eigen::Vector3d::UnitY(),
                        Z = Eigen::Vector3d::UnitZ();
  for (const auto& r : rooms) {
    const Eigen::Vector3d s = r.max - r.min;
    const Eigen::Vector3d& o = r.min;
    // Floor (normal +z seen from inside) and ceiling.
    f.planes.push_back(makeRectPolygon(o, X, Y, s.x(), s.y()));
    f.planes.push_back(makeRectPolygon(o + Eigen::Vector3d(0, 0, s.z()), Y, X, s.y(), s.x()));
    // Walls facing -y and +y (normals along y): no windows.
    f.planes.push_back(makeRectPolygon(o, Z, X, s.z(), s.x()));
    f.planes.push_back(makeRectPolygon(o + Eigen::Vector3d(0, s.y(), 0), X, Z, s.x(), s.z()));
    // Walls facing x with a window whose position depends on the room (asymmetry).
    std::vector<Eigen::Vector4d> holes;
    const double w0 = 0.3 * s.y(), w1 = w0 + std::min(1.2, 0.3 * s.y());
    if (windows) holes.push_back({w0, 0.9, w1, std::min(2.1, s.z() - 0.2)});
    f.planes.push_back(makeRectPolygon(o, Y, Z, s.y(), s.z(), holes));
    f.planes.push_back(makeRectPolygon(o + Eigen::Vector3d(s.x(), 0, 0), Z, Y, s.z(), s.y()));
    if (windows) {
      f.facades.push_back(int(f.planes.size()) - 2);
      Opening op;
      op.corners = {o + Eigen::Vector3d(0, w0, 0.9), o + Eigen::Vector3d(0, w1, 0.9),
                    o + Eigen::Vector3d(0, w1, std::min(2.1, s.z() - 0.2)),
                    o + Eigen::Vector3d(0, w0, std::min(2.1, s.z() - 0.2))};
      op.facade = int(f.planes.size()) - 2;
      op.evidence_count = 200;
      f.openings.push_back(op);
      for (const auto& e : op.edges()) f.segments.push_back(e);
    }
    // The 12 box edges.
    for (int a = 0; a < 8; ++a) {
      const Eigen::Vector3d pa(a & 1 ? r.max.x() : r.min.x(), a & 2 ? r.max.y() : r.min.y(),
                               a & 4 ? r.max.z() : r.min.z());
      for (int bit : {1, 2, 4}) {
        if (a & bit) continue;
        const int b = a | bit;
        const Eigen::Vector3d pb(b & 1 ? r.max.x() : r.min.x(), b & 2 ? r.max.y() : r.min.y(),
                                 b & 4 ? r.max.z() : r.min.z());
        addSegment(f, pa, pb);
      }
    }
  }
  return f;
}

std::vector<Room> asymmetricRooms() {
  return {
      {{0, 0, 0}, {6, 4, 2.8}},       {{6.2, 0, 0}, {9, 4, 2.8}},
      {{0, 4.2, 0}, {4, 9, 2.8}},     {{4.2, 4.2, 0}, {5.5, 6.5, 2.8}},
      {{0, 0, 3.0}, {9, 4, 5.6}},     {{0, 4.2, 3.0}, {3.1, 7.0, 5.6}},
  };
}

RigidTransform randomPose(std::mt19937_64& rng, double max_shift) {
  std::uniform_real_distribution<double> yaw(-M_PI, M_PI), u(-1, 1), zs(-2, 2);
  Eigen::Vector3d t(u(rng), u(rng), 0);
  if (t.norm() > 1) t.normalize();
  t *= max_shift * std::abs(u(rng));
  t.z() = zs(rng);
  return RigidTransform::fromYaw(yaw(rng), t);
}

FeatureSet perturb(const FeatureSet& in, const Perturbation& p, std::mt19937_64& rng) {
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> u(0, 1);
  FeatureSet out;
  const double ang = p.angle_noise_deg * M_PI / 180.0;
  std::vector<int> remap(in.planes.size(), -1);
  for (std::size_t i = 0; i < in.planes.size(); ++i) {
    if (u(rng) < p.drop_fraction) continue;
    PlanarPolygon pl = in.planes[i];
    const Eigen::Vector3d axis(n(rng), n(rng), n(rng));
    const RigidTransform tilt(
        Eigen::AngleAxisd(ang * n(rng), axis.normalized()).toRotationMatrix(), Eigen::Vector3d::Zero());
    const Eigen::Vector3d c = pl.centroid;
    // Small rotation about the centroid, then a shift along the normal.
    pl.transform(RigidTransform(Eigen::Matrix3d::Identity(), -c));
    pl.transform(tilt);
    pl.transform(RigidTransform(Eigen::Matrix3d::Identity(),
                                c + p.position_noise * n(rng) * pl.normal));
    remap[i] = int(out.planes.size());
    out.planes.push_back(pl);
  }
  for (int f : in.facades)
    if (remap[f] >= 0) out.facades.push_back(remap[f]);
  for (const auto& o : in.openings) {
    if (o.facade >= 0 && remap[o.facade] < 0) continue;
    Opening q = o;
    q.facade = o.facade >= 0 ? remap[o.facade] : -1;
    for (auto& c : q.corners) c += p.position_noise * Eigen::Vector3d(n(rng), 0, n(rng));
    out.openings.push_back(q);
  }
  for (const auto& s : in.segments) {
    if (u(rng) < p.drop_fraction) continue;
    Segment3D q = s;
    q.a += p.position_noise * Eigen::Vector3d(n(rng), n(rng), n(rng));
    q.b += p.position_noise * Eigen::Vector3d(n(rng), n(rng), n(rng));
    // Partial detections: shorten a little at random.
    const Eigen::Vector3d d = q.b - q.a;
    q.a += 0.1 * u(rng) * d;
    q.b -= 0.1 * u(rng) * d;
    out.segments.push_back(q);
  }
  Bounds b;
  for (const auto& s : in.segments) {
    b.extend(s.a);
    b.extend(s.b);
  }
  for (int k = 0; k < p.outliers; ++k) {
    const Eigen::Vector3d a = b.min + Eigen::Vector3d(u(rng), u(rng), u(rng)).cwiseProduct(b.size());
    const Eigen::Vector3d d = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    Segment3D s;
    s.a = a;
    s.b = a + (0.5 + 2 * u(rng)) * d;
    out.segments.push_back(s);
    const Eigen::Vector3d nv = Eigen::Vector3d(n(rng), n(rng), n(rng)).normalized();
    const Eigen::Vector3d uu = nv.unitOrthogonal();
    out.planes.push_back(makeRectPolygon(a, uu, nv.cross(uu), 0.5 + u(rng), 0.5 + u(rng)));
  }
  return out;
}

}  // namespace plumb::test
