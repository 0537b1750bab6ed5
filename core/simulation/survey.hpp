#pragma once
// A whole simulated survey of one model: indoor TLS stations grouped in one dataset
// ("indoor"), an MMS pass in another ("outdoor"), each moved by a random rigid perturbation,
// with the transform that maps each perturbed dataset back to the model frame (the truth a
// registration must find). Used by `plumb-cli simulate` and for the demo data.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "model/bim_model.hpp"
#include "model/dataset.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/mms_scanner.hpp"
#include "simulation/tls_scanner.hpp"

namespace plumb {

struct SurveyRequest {
  std::vector<Eigen::Vector3d> tls_stations;  ///< model frame
  TlsParams tls;
  bool mms = false;                           ///< run the MMS
  std::optional<Trajectory> trajectory;       ///< else an automatic street loop
  MmsParams mms_params;
  double perturb_yaw_deg = 0.0;  ///< max |yaw| of the random perturbation, deg
  double perturb_shift_m = 0.0;  ///< max |shift| per axis (z: a quarter), m
  bool perturb_mms = false;      ///< also move the outdoor dataset (default: it is the reference)
  /// Each TLS station moved by its own random perturbation (issue 15, a network to register):
  /// max |yaw|, deg, and max |shift| per axis (z: a quarter), m; 0 = off. Applied before the
  /// dataset-wide perturbation above.
  double perturb_station_yaw_deg = 0.0;
  double perturb_station_shift_m = 0.0;
  bool glass_transparent = true;
  std::uint64_t seed = 1;
};

struct SimulatedDataset {
  std::string name;       ///< "indoor" or "outdoor"
  Dataset data;           ///< perturbed: scans' poses include the perturbation
  RigidTransform truth;   ///< perturbed dataset frame -> model frame
  /// Per scan: the transform mapping that perturbed scan (in the dataset frame) to the model
  /// frame. Equal to `truth` for every scan unless stations were perturbed independently.
  std::vector<RigidTransform> scan_truths;
  /// Per scan: its true pose (scan frame -> model frame).
  std::vector<RigidTransform> true_poses;
};

struct SimulatedSurvey {
  std::vector<SimulatedDataset> datasets;
  /// The trajectory the MMS drove (model frame; request.trajectory or the automatic street
  /// loop), when it ran.
  std::optional<Trajectory> mms_trajectory;
};

/// Scans `model` (glass flags per triangle, may be empty). `outline` is the building outline
/// for the automatic MMS trajectory (BuildingTruth::footprint; empty = model bounds).
SimulatedSurvey simulateSurvey(const BimModel& model, const std::vector<bool>& glass,
                               const std::vector<Eigen::Vector3d>& outline, const SurveyRequest& request,
                               Progress* progress = nullptr);

/// The demo: preset "house", a TLS station in each ground-floor room (0.5 deg grid), an MMS
/// loop, indoor perturbed by up to 30 deg / 2 m. Small (~1.4 M points), a few seconds.
SurveyRequest demoSurveyRequest(const BuildingSpec& spec, std::uint64_t seed = 1);

}  // namespace plumb
