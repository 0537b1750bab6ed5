#include "model/rigid_transform.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace plumb {

RigidTransform::RigidTransform(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& translation)
    : rotation_(rotation), translation_(translation) {}

RigidTransform RigidTransform::fromMatrix(const Eigen::Matrix4d& m, double tolerance) {
  const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
  if (!m.allFinite()) throw InputError("transform matrix has non-finite values");
  const double orth = (r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff();
  if (orth > tolerance || std::abs(r.determinant() - 1.0) > tolerance) {
    std::ostringstream msg;
    msg << "transform matrix is not rigid (R^T R differs from I by " << orth << ", det(R) = "
        << r.determinant() << "); scaling and shear are not supported";
    throw InputError(msg.str());
  }
  const Eigen::RowVector4d last = m.row(3);
  if ((last - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > tolerance)
    throw InputError("transform matrix's last row must be 0 0 0 1");
  // Re-orthonormalise to remove the rounding of a printed matrix.
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(r, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return RigidTransform(svd.matrixU() * svd.matrixV().transpose(), m.topRightCorner<3, 1>());
}

RigidTransform RigidTransform::fromQuaternion(const Eigen::Quaterniond& q,
                                              const Eigen::Vector3d& t) {
  return RigidTransform(q.normalized().toRotationMatrix(), t);
}

RigidTransform RigidTransform::fromYaw(double yaw, const Eigen::Vector3d& t) {
  return RigidTransform(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix(), t);
}

Eigen::Matrix4d RigidTransform::matrix() const {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = rotation_;
  m.topRightCorner<3, 1>() = translation_;
  return m;
}

Eigen::Isometry3d RigidTransform::isometry() const { return Eigen::Isometry3d(matrix()); }

RigidTransform RigidTransform::operator*(const RigidTransform& o) const {
  return RigidTransform(rotation_ * o.rotation_, rotation_ * o.translation_ + translation_);
}

RigidTransform RigidTransform::inverse() const {
  const Eigen::Matrix3d rt = rotation_.transpose();
  return RigidTransform(rt, -rt * translation_);
}

bool RigidTransform::isIdentity(double tolerance) const {
  return (rotation_ - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= tolerance &&
         translation_.cwiseAbs().maxCoeff() <= tolerance;
}

double RigidTransform::rotationAngleDeg() const {
  // atan2 of (sin, cos) stays accurate for tiny angles, where acos(trace) loses digits.
  const Eigen::Matrix3d& r = rotation_;
  const Eigen::Vector3d axis(r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1));
  const double s = 0.5 * axis.norm();
  const double c = (r.trace() - 1.0) / 2.0;
  return std::atan2(s, c) * 180.0 / M_PI;
}

double RigidTransform::rotationErrorDeg(const RigidTransform& a, const RigidTransform& b) {
  return (a.inverse() * b).rotationAngleDeg();
}

double RigidTransform::translationError(const RigidTransform& a, const RigidTransform& b) {
  return (a.translation_ - b.translation_).norm();
}

std::string transformToJson(const RigidTransform& t) {
  const Eigen::Matrix4d m = t.matrix();
  std::ostringstream out;
  out << std::setprecision(17) << "{\n  \"matrix\": [\n";
  for (int r = 0; r < 4; ++r) {
    out << "    [";
    for (int c = 0; c < 4; ++c) out << (c ? ", " : "") << m(r, c);
    out << "]" << (r < 3 ? "," : "") << "\n";
  }
  out << "  ]\n}\n";
  return out.str();
}

namespace {
RigidTransform fromMatrixIn(const Eigen::Matrix4d& m, const std::filesystem::path& source) {
  try {
    return RigidTransform::fromMatrix(m, 1e-4);
  } catch (const InputError& e) {
    throw FileError(source, e.what());
  }
}
}  // namespace

RigidTransform transformFromJson(const std::string& text, const std::filesystem::path& source) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw FileError(source, std::string("invalid JSON: ") + e.what(), atByte(e.byte));
  }
  if (!j.is_object() || !j.contains("matrix"))
    throw FileError(source, "expected an object with a \"matrix\" member (4x4 array)");
  const auto& jm = j["matrix"];
  if (!jm.is_array() || jm.size() != 4)
    throw FileError(source, "\"matrix\" must be an array of 4 rows", {.element = "matrix"});
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r) {
    const auto& row = jm[r];
    if (!row.is_array() || row.size() != 4)
      throw FileError(source, "each matrix row must hold 4 numbers",
                      {.element = "matrix[" + std::to_string(r) + "]"});
    for (int c = 0; c < 4; ++c) {
      if (!row[c].is_number())
        throw FileError(source, "matrix entry is not a number",
                        {.element = "matrix[" + std::to_string(r) + "][" + std::to_string(c) + "]"});
      m(r, c) = row[c].get<double>();
    }
  }
  return fromMatrixIn(m, source);
}

std::string transformToText(const RigidTransform& t) {
  const Eigen::Matrix4d m = t.matrix();
  std::ostringstream out;
  out << std::setprecision(17);
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) out << (c ? " " : "") << m(r, c);
    out << "\n";
  }
  return out.str();
}

RigidTransform transformFromText(const std::string& text, const std::filesystem::path& source) {
  std::istringstream in(text);
  Eigen::Matrix4d m;
  std::string line;
  int row = 0;
  std::uint64_t lineNo = 0;
  while (row < 4 && std::getline(in, line)) {
    ++lineNo;
    if (line.find_first_not_of(" \t\r,;") == std::string::npos) continue;
    for (char& ch : line)
      if (ch == ',' || ch == ';') ch = ' ';
    std::istringstream ls(line);
    for (int c = 0; c < 4; ++c) {
      if (!(ls >> m(row, c)))
        throw FileError(source, "expected 4 numbers per row of a 4x4 matrix", atLine(lineNo));
    }
    std::string rest;
    if (ls >> rest)
      throw FileError(source, "more than 4 values on a matrix row", atLine(lineNo));
    ++row;
  }
  if (row < 4)
    throw FileError(source, "expected a 4x4 matrix, found " + std::to_string(row) + " rows");
  return fromMatrixIn(m, source);
}

RigidTransform readTransformFile(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  if (text.empty()) throw FileError(path, "file is empty, expected a transform");
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '{') return transformFromJson(text, path);
  return transformFromText(text, path);
}

void writeTransformFile(const std::filesystem::path& path, const RigidTransform& t) {
  const bool json = path.extension() == ".json";
  writeFileAtomically(path, [&](std::ostream& out) {
    out << (json ? transformToJson(t) : transformToText(t));
  });
}

std::ostream& operator<<(std::ostream& out, const RigidTransform& t) {
  return out << transformToText(t);
}

}  // namespace plumb
