#pragma once
// The demo's truth (plumb-cli simulate --demo: truth.json, ground_truth.json) and the error of
// a registered indoor -> outdoor transform against it: shared by the plumb-cli end-to-end
// tests of the indoor/outdoor registration.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "support/test_support.hpp"

namespace plumb::test {

inline nlohmann::json readJson(const std::filesystem::path& p) { return nlohmann::json::parse(readAll(p)); }

/// A 4x4 row-major JSON matrix.
inline Eigen::Isometry3d transformOf(const nlohmann::json& matrix) {
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = matrix.at(r).at(c).get<double>();
  return Eigen::Isometry3d(m);
}

/// truth.json: the transform mapping dataset `name` back to the model frame.
inline Eigen::Isometry3d truthOf(const nlohmann::json& truth, const std::string& name) {
  for (const auto& d : truth.at("datasets"))
    if (d.at("name") == name) return transformOf(d.at("transform").at("matrix"));
  ADD_FAILURE() << "truth.json has no dataset '" << name << "'";
  return Eigen::Isometry3d::Identity();
}

struct RegistrationError {
  double rotation_deg = 0.0;
  double translation_m = 0.0;  ///< worst building outline corner (ground and z = 3 m)
  std::size_t corners = 0;     ///< outline corners (or given points) checked
};

/// Error of `T` (indoor -> outdoor, from `register indoor outdoor --transform`) against the
/// demo directory's truth: expected = (outdoor -> model)^-1 (indoor -> model). The translation
/// error is taken at the building's outline corners (ground_truth.json footprint, z 0 and
/// 3 m) in the indoor frame: the worst place of the whole building, not only its centre.
inline RegistrationError indoorOutdoorError(const std::filesystem::path& demo_dir, const Eigen::Isometry3d& T) {
  const nlohmann::json truth = readJson(demo_dir / "truth.json");
  const Eigen::Isometry3d expected = truthOf(truth, "outdoor").inverse() * truthOf(truth, "indoor");
  RegistrationError e;
  e.rotation_deg = Eigen::AngleAxisd(T.linear() * expected.linear().transpose()).angle() * 180.0 / M_PI;
  const nlohmann::json gt = readJson(demo_dir / "ground_truth.json");
  const Eigen::Isometry3d model_to_indoor = truthOf(truth, "indoor").inverse();
  for (const auto& v : gt.at("footprint")) {
    ++e.corners;
    for (double z : {0.0, 3.0}) {
      const Eigen::Vector3d p = model_to_indoor * Eigen::Vector3d(v.at(0).get<double>(), v.at(1).get<double>(), z);
      e.translation_m = std::max(e.translation_m, (T * p - expected * p).norm());
    }
  }
  return e;
}

/// Error of `T` (dataset `name` -> model frame, from `register DATASET MODEL --transform`)
/// against truth.json: the rotation, and the translation error at `model_points` (model frame).
inline RegistrationError modelFrameError(const nlohmann::json& truth, const std::string& name,
                                         const Eigen::Isometry3d& T,
                                         const std::vector<Eigen::Vector3d>& model_points) {
  const Eigen::Isometry3d expected = truthOf(truth, name);
  RegistrationError e;
  e.rotation_deg = Eigen::AngleAxisd(T.linear() * expected.linear().transpose()).angle() * 180.0 / M_PI;
  for (const Eigen::Vector3d& x : model_points) {
    ++e.corners;
    e.translation_m = std::max(e.translation_m, (T * (expected.inverse() * x) - x).norm());
  }
  return e;
}

}  // namespace plumb::test
