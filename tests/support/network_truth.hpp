#pragma once
// Station errors of a network registration against a simulation's truth.json (plumb-cli
// simulate --perturb-stations): the registered frame is the reference station's file frame,
// so station i's true pose there is G_ref^-1 * true_pose_i (G: file frame -> model frame); with
// --model it is the model frame, where the true pose is true_pose_i.
// Shared by the network integration test and bench_network.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "model/rigid_transform.hpp"

namespace plumb::test {

struct StationError {
  std::string name;
  bool placed = false;
  double rotation_deg = 0.0, translation_m = 0.0;
  Eigen::Vector3d sigma_position = Eigen::Vector3d::Zero();  ///< reported, m
};

inline nlohmann::json readJsonFile(const std::filesystem::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

inline RigidTransform matrixOf(const nlohmann::json& j) { return transformFromJson(j.dump()); }

/// Errors of poses[name] (station -> registered frame; nullopt: not placed). `model_to_registered`:
/// when given, the registered frame (a georeferenced network), else the reference's frame.
inline std::vector<StationError> stationErrors(const nlohmann::json& truth, const std::string& reference,
                                               const std::map<std::string, std::optional<RigidTransform>>& poses,
                                               const std::optional<RigidTransform>& model_to_registered = {}) {
  std::map<std::string, nlohmann::json> scans;
  for (const auto& s : truth["scans"]) scans[s["scan"].get<std::string>()] = s;
  // With a model as the reference (network --model), the registered frame is the model frame.
  const RigidTransform to_registered =
      model_to_registered ? *model_to_registered
      : scans.count(reference) ? matrixOf(scans.at(reference)["transform"]).inverse()
                               : RigidTransform();
  std::vector<StationError> out;
  for (const auto& [name, pose] : poses) {
    StationError e;
    e.name = name;
    e.placed = pose.has_value();
    if (pose) {
      const RigidTransform expected = to_registered * matrixOf(scans.at(name)["true_pose"]);
      e.rotation_deg = RigidTransform::rotationErrorDeg(expected, *pose);
      e.translation_m = RigidTransform::translationError(expected, *pose);
    }
    out.push_back(e);
  }
  return out;
}

/// A georeferenced network's frame (control points, simulate --control-points): the ground frame
/// moved to the report's grid origin O. A model point m has grid coordinates g0 + k m (E, N) and
/// H0 + m_z, so its registered position is O + (g0 - O) / k + m horizontally and H0 + m_z
/// vertically: a translation of the model frame.
inline std::optional<RigidTransform> georeferencedFrame(const nlohmann::json& truth, const nlohmann::json& report) {
  if (!report.contains("georeference") || !report["georeference"]["done"].get<bool>() || !truth.contains("control"))
    return std::nullopt;
  const auto& g0 = truth["control"]["grid_origin"];
  const double k = truth["control"]["grid_scale"].get<double>();
  const auto& o = report["georeference"]["origin_grid"];
  Eigen::Vector3d t;
  for (int a = 0; a < 2; ++a) t[a] = o[a].get<double>() + (g0[a].get<double>() - o[a].get<double>()) / k;
  t.z() = g0[2].get<double>();
  return RigidTransform(Eigen::Matrix3d::Identity(), t);
}

/// The errors of a plumb-cli network --report JSON.
inline std::vector<StationError> reportErrors(const nlohmann::json& truth, const nlohmann::json& report) {
  std::map<std::string, std::optional<RigidTransform>> poses;
  std::map<std::string, Eigen::Vector3d> sigma;
  for (const auto& s : report["stations"]) {
    if (s.value("model", false)) continue;  // the BIM node
    const std::string name = s["name"];
    poses[name] = s["placed"].get<bool>() ? std::optional<RigidTransform>(matrixOf(s["pose"])) : std::nullopt;
    if (s.contains("sigma_position_m"))
      sigma[name] = Eigen::Vector3d(s["sigma_position_m"][0].get<double>(), s["sigma_position_m"][1].get<double>(),
                                    s["sigma_position_m"][2].get<double>());
  }
  auto errors = stationErrors(truth, report["reference"], poses, georeferencedFrame(truth, report));
  for (auto& e : errors)
    if (sigma.count(e.name)) e.sigma_position = sigma[e.name];
  return errors;
}

}  // namespace plumb::test
