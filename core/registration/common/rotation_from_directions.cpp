#include "registration/common/rotation_from_directions.hpp"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <cmath>
#include <sstream>

namespace plumb {

const ParamSchema<RotationEnumerationParams>& RotationEnumerationParams::schema() {
  using P = RotationEnumerationParams;
  static const auto s =
      ParamSchema<P>("rotations")
          .boolean(&P::up_axis_known, "up-axis-known", "Z is up in both",
                   "Both datasets are Z-up (levelled scanners, BIM): keep Z up, within max-tilt")
          .boolean(&P::allow_up_down_flip, "allow-up-down-flip", "Try upside down",
                   "Also try rotations turning Z down (up axis sign unknown)", true)
          .real(&P::max_tilt_deg, "max-tilt", "Max tilt", "deg", 0.0, 90.0,
                "With Z up in both: max angle between the rotated and the original Z", true)
          .real(&P::min_frame_angle_deg, "min-frame-angle", "Min frame angle", "deg", 5.0, 90.0,
                "The two directions defining a rotation frame are at least this far apart", true);
  return s;
}

std::optional<Eigen::Matrix3d> frameFromDirections(const Eigen::Vector3d& u,
                                                   const Eigen::Vector3d& v) {
  const Eigen::Vector3d x = u.normalized();
  const Eigen::Vector3d q = v - v.dot(x) * x;  // eq. 12-13 with unit u
  if (q.norm() < 1e-3 * v.norm()) return std::nullopt;
  const Eigen::Vector3d y = q.normalized();
  Eigen::Matrix3d m;
  m.col(0) = x;
  m.col(1) = y;
  m.col(2) = x.cross(y);  // eq. 14-15
  return m;
}

std::optional<Eigen::Matrix3d> rotationFromDirectionPairs(const Eigen::Vector3d& u_s,
                                                          const Eigen::Vector3d& v_s,
                                                          const Eigen::Vector3d& u_t,
                                                          const Eigen::Vector3d& v_t) {
  const auto ms = frameFromDirections(u_s, v_s);
  const auto mt = frameFromDirections(u_t, v_t);
  if (!ms || !mt) return std::nullopt;
  return Eigen::Matrix3d(*mt * ms->transpose());  // eq. 18-19: M_t = R M_s, M_s^-1 = M_s^T
}

std::vector<RotationCandidate> enumerateRotations(const std::vector<Eigen::Vector3d>& source,
                                                  const std::vector<Eigen::Vector3d>& target,
                                                  const RotationEnumerationParams& p) {
  std::vector<RotationCandidate> out;
  if (source.size() < 2 || target.size() < 2) return out;
  const double cos_tol = std::cos(p.angle_tolerance_deg * M_PI / 180.0);
  // The two heaviest mutually non-parallel source directions.
  const int a = 0;
  int b = -1;
  const double cos_frame = std::cos(p.min_frame_angle_deg * M_PI / 180.0);
  for (std::size_t i = 1; i < source.size() && b < 0; ++i)
    if (std::abs(source[0].normalized().dot(source[i].normalized())) < cos_frame) b = int(i);
  if (b < 0) return out;
  const double angle_s = source[a].normalized().dot(source[b].normalized());
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const double cos_tilt = std::cos(p.max_tilt_deg * M_PI / 180.0);
  for (std::size_t ta = 0; ta < target.size(); ++ta) {
    for (std::size_t tb = 0; tb < target.size(); ++tb) {
      if (ta == tb) continue;
      for (int sa : {1, -1}) {
        for (int sb : {1, -1}) {
          const Eigen::Vector3d ut = sa * target[ta].normalized();
          const Eigen::Vector3d vt = sb * target[tb].normalized();
          // The angle between the two directions must be preserved.
          if (std::abs(std::acos(std::clamp(ut.dot(vt), -1.0, 1.0)) -
                       std::acos(std::clamp(angle_s, -1.0, 1.0))) >
              p.angle_tolerance_deg * M_PI / 180.0)
            continue;
          const auto r = rotationFromDirectionPairs(source[a], source[b], ut, vt);
          if (!r) continue;
          if (p.up_axis_known) {
            const double up = ((*r) * z).dot(z);
            const bool upright = up >= cos_tilt;
            const bool flipped = p.allow_up_down_flip && up <= -cos_tilt;
            if (!upright && !flipped) continue;
          }
          RotationCandidate c;
          c.rotation = *r;
          c.target_of_source.assign(source.size(), -1);
          c.sign_of_source.assign(source.size(), 0);
          std::size_t matched = 0;
          for (std::size_t s = 0; s < source.size(); ++s) {
            const Eigen::Vector3d m = (*r) * source[s].normalized();
            int best = -1;
            double best_dot = cos_tol;
            for (std::size_t t = 0; t < target.size(); ++t) {
              const double d = std::abs(m.dot(target[t].normalized()));
              if (d >= best_dot) {
                best_dot = d;
                best = int(t);
              }
            }
            c.target_of_source[s] = best;
            if (best >= 0) {
              c.sign_of_source[s] = m.dot(target[best]) >= 0 ? 1 : -1;
              ++matched;
            }
          }
          // Directions a and b define R; a third one must also be matched when both sides
          // have three.
          if (matched < std::min<std::size_t>({3, source.size(), target.size()})) continue;
          bool duplicate = false;
          for (const auto& o : out) {
            const Eigen::AngleAxisd d(o.rotation.transpose() * c.rotation);
            if (std::abs(d.angle()) < p.angle_tolerance_deg * M_PI / 180.0 / 4) duplicate = true;
          }
          if (duplicate) continue;
          std::ostringstream label;
          label << "dir" << a << "->" << (sa > 0 ? "+" : "-") << ta << ", dir" << b << "->"
                << (sb > 0 ? "+" : "-") << tb;
          c.label = label.str();
          out.push_back(std::move(c));
        }
      }
    }
  }
  return out;
}

Eigen::Matrix3d fitRotation(const std::vector<Eigen::Vector3d>& source,
                            const std::vector<Eigen::Vector3d>& target,
                            const std::vector<double>& weights) {
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < source.size(); ++i)
    h += weights[i] * target[i] * source[i].transpose();
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d d = Eigen::Matrix3d::Identity();
  d(2, 2) = (svd.matrixU() * svd.matrixV().transpose()).determinant() < 0 ? -1 : 1;
  return svd.matrixU() * d * svd.matrixV().transpose();
}

}  // namespace plumb
