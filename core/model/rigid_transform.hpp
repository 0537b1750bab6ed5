#pragma once
// A rigid transform x' = R x + t (docs/ALGORITHMS.md "Frames"): maps SOURCE coordinates to TARGET
// coordinates. Stored in double precision.
#include <Eigen/Geometry>

#include <filesystem>
#include <iosfwd>
#include <string>

namespace plumb {

class RigidTransform {
 public:
  RigidTransform() = default;  ///< identity
  RigidTransform(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation);
  /// From a 4x4 matrix; throws InputError if the upper-left 3x3 is not a rotation
  /// (orthonormal within `tolerance`, det +1) or the last row is not (0,0,0,1).
  static RigidTransform fromMatrix(const Eigen::Matrix4d& m, double tolerance = 1e-6);
  static RigidTransform fromQuaternion(const Eigen::Quaterniond& q, const Eigen::Vector3d& t);
  /// Rotation about +Z by yaw (radians), then translation.
  static RigidTransform fromYaw(double yaw, const Eigen::Vector3d& t);

  const Eigen::Matrix3d& rotation() const { return rotation_; }
  const Eigen::Vector3d& translation() const { return translation_; }
  Eigen::Matrix4d matrix() const;
  Eigen::Isometry3d isometry() const;
  Eigen::Quaterniond quaternion() const { return Eigen::Quaterniond(rotation_); }

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const { return rotation_ * p + translation_; }
  Eigen::Vector3d applyToDirection(const Eigen::Vector3d& d) const { return rotation_ * d; }
  /// (*this * other)(x) = this(other(x)).
  RigidTransform operator*(const RigidTransform& other) const;
  RigidTransform inverse() const;
  bool isIdentity(double tolerance = 1e-12) const;

  /// Rotation angle of R in degrees (geodesic distance to identity).
  double rotationAngleDeg() const;
  /// Differences used by accuracy tests: angle of (a^-1 b) in degrees, |t_a - t_b| in metres.
  static double rotationErrorDeg(const RigidTransform& a, const RigidTransform& b);
  static double translationError(const RigidTransform& a, const RigidTransform& b);

 private:
  Eigen::Matrix3d rotation_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d translation_ = Eigen::Vector3d::Zero();
};

/// JSON: {"matrix": [[r00,r01,r02,tx],[r10,r11,r12,ty],[r20,r21,r22,tz],[0,0,0,1]]}.
std::string transformToJson(const RigidTransform& t);
RigidTransform transformFromJson(const std::string& text, const std::filesystem::path& source = {});
/// Plain text: 4 lines of 4 numbers (CloudCompare's format).
std::string transformToText(const RigidTransform& t);
RigidTransform transformFromText(const std::string& text, const std::filesystem::path& source = {});

/// Reads a transform file: JSON if it starts with '{', else 4x4 text. Throws FileError.
RigidTransform readTransformFile(const std::filesystem::path& path);
/// Writes JSON for .json, 4x4 text otherwise; atomic.
void writeTransformFile(const std::filesystem::path& path, const RigidTransform& t);

std::ostream& operator<<(std::ostream& out, const RigidTransform& t);

}  // namespace plumb
