#pragma once
#include <limits>
// The acceptance scenarios of the registration engine (issue 6), shared by the acceptance test
// and bench_registration. Each scenario is simulated once (core/simulation, 3 mm TLS range
// noise); every case moves the source cloud by a random pose (yaw uniform in [-180, 180] deg,
// shift up to 20 m) and registers it end to end (cloud -> features -> global -> refinement).
//   indoor-indoor  "house": station A at the centre of a ground-floor room, station B in the
//                  doorway to the next room (sees both rooms): A -> B.
//   indoor-outdoor "house": TLS in every ground-floor room (merged, sensor origins) -> MMS loop.
//   bim-generated  "house": TLS in every ground-floor room -> the generated model.
//   bim-duplex     duplex.ifc read with plumb::readModel, TLS stations inside -> the model.
// Not in scenarioNames() (symmetric placements, issue 13):
//   bim-duplex-unit-a / -unit-b  one station in the living room of one of the duplex's two
//                  mirrored dwellings -> the whole model (the room exists twice).
#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/bim_model.hpp"
#include "model/feature_set.hpp"
#include "model/point_cloud.hpp"
#include "model/rigid_transform.hpp"
#include "registration/auto/registration_pipeline.hpp"

namespace plumb::test {

struct Scenario {
  std::string name;
  PointCloud source;                 ///< model frame (the truth of every case is the pose's inverse)
  PointCloud target;                 ///< model frame; empty for a model target
  std::shared_ptr<BimModel> model;   ///< the model target (scan/BIM), else null
  FeatureSet target_features;        ///< extracted once (the target does not move)
  PointCloud target_samples;         ///< points sampled on the model (refinement), BIM only
  double seconds_simulation = 0.0;
  double seconds_target_features = 0.0;
  bool isBim() const { return model != nullptr; }
};

/// Names in the order of the issue: indoor-indoor, indoor-outdoor, bim-generated, bim-duplex.
std::vector<std::string> scenarioNames();
/// Simulates a scenario and extracts its target features with `params`. Throws on bad name.
Scenario makeScenario(const std::string& name, const PipelineParams& params,
                      double noise_mm = 3.0);

/// A preset's indoor survey: a TLS station at every ground-floor room centre (merged, sensor
/// origins), 3 mm noise, 0.5 deg steps.
PointCloud presetIndoorScans(const std::string& preset, std::uint64_t seed);
/// A preset's outdoor survey: the MMS street loop (per-point sensor origins).
PointCloud presetOutdoorScan(const std::string& preset, std::uint64_t seed);

/// n random poses: yaw uniform in [-180, 180] deg, horizontal shift uniform in a disc of
/// radius `max_shift` m, vertical shift uniform in [-1, 1] m. Deterministic for a seed.
std::vector<RigidTransform> randomPoses(int n, std::uint64_t seed, double max_shift = 20.0);

/// The shifts of randomPoses with rotations uniform on the sphere of 3D rotations (any tilt,
/// any yaw; issue 14). Deterministic for a seed.
std::vector<RigidTransform> randomPoses3d(int n, std::uint64_t seed, double max_shift = 20.0);

/// Errors of an estimate against the truth: rotation angle of est^-1 truth (deg), and the
/// displacement difference |est(c) - truth(c)| at the centroid c of the (moved) source data
/// (m), which does not grow with the distance of the data from the origin.
struct PoseError {
  double rotation_deg = 0.0;
  double translation_m = 0.0;
};
PoseError poseError(const RigidTransform& estimate, const RigidTransform& truth,
                    const Eigen::Vector3d& centroid);

/// Success criterion of the issue: < 0.1 deg and < 2 cm.
inline bool withinTolerance(const PoseError& e) {
  return e.rotation_deg < 0.1 && e.translation_m < 0.02;
}

struct CaseOutcome {
  bool reported_success = false;  ///< the pipeline said success (report.success)
  PoseError error;                ///< of the returned transform (meaningful when reported)
  bool correct() const { return reported_success && withinTolerance(error); }
  /// A wrong answer that was not reported as a failure.
  bool confidentWrong() const { return reported_success && !withinTolerance(error); }
  std::string method;
  std::string verdict;
  std::string status;
  VisibilitySummary visibility;  ///< free-space evidence (QualityReport::visibility)
  double overlap = 0.0;          ///< refined overlap ratio
  std::string level;       ///< verdictLevelName of the report
  /// The refined candidates (role, overlap, RMS, fit cost), one line; empty without runner-up.
  std::string candidates;
  /// Smallest slide resistance of the six directions (QualityReport::direction_resistance);
  /// the degeneracy evidence: NaN when refinement did not run.
  double min_resistance = std::numeric_limits<double>::quiet_NaN();
  double seconds_features = 0, seconds_global = 0, seconds_refine = 0, seconds_total = 0;
  QualityReport report;  ///< the whole report (bench_verdict reads every figure of its JSON)
  std::vector<std::string> log;  ///< the pipeline's log (PipelineResult::log)
};

/// Moves the source by `pose` and registers it onto the target with the Plumb pipeline
/// (source features extracted from the moved cloud; target features reused).
CaseOutcome runPlumbCase(const Scenario& s, const RigidTransform& pose, const PipelineParams& params);

/// Default pipeline parameters of the acceptance runs (the product defaults).
PipelineParams acceptanceParams();

}  // namespace plumb::test
