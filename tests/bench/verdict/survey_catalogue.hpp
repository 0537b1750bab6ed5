#pragma once
// The buildings of bench_verdict and their simulated data, each made once per run and reused
// across pairs: the presets (generated, with ground truth) and the IFC models of
// ../shared/data/ifc (stations found by findRoomStations). Per building: its model as scanned,
// the same model without furniture (the oracle's and the symmetric suite's reference), indoor
// TLS stations, the merged indoor scan with its features, an MMS loop (generated buildings),
// and the model as a registration target (features, surface samples).
#include <Eigen/Core>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "model/bim_model.hpp"
#include "model/feature_set.hpp"
#include "model/point_cloud.hpp"
#include "registration/auto/registration_pipeline.hpp"
#include "simulation/building_spec.hpp"
#include "simulation/scan_scene.hpp"

namespace plumb::verdict {

struct Building {
  std::string name;       ///< preset name, or the IFC file name
  std::string problem;    ///< why the building cannot be used ("" = usable)
  std::shared_ptr<const BimModel> model;  ///< as scanned (presets: with furniture)
  std::vector<bool> glass;                ///< per triangle of model
  std::shared_ptr<const BimModel> bare;   ///< furniture removed
  std::vector<bool> bare_glass;
  std::vector<Eigen::Vector3d> stations;   ///< TLS stations, model frame
  std::vector<Eigen::Vector3d> footprint;  ///< outline for the MMS loop (generated only)
  bool usable() const { return problem.empty(); }
};

/// Data a registration runs on: a cloud or a model, with features extracted once.
struct SideData {
  PointCloud cloud;                      ///< empty for a model
  std::shared_ptr<const BimModel> model; ///< null for a cloud
  FeatureSet features;                   ///< scans: planes + openings + segments
  PointCloud samples;                    ///< model only: surface samples for refinement
  double seconds = 0.0;                  ///< simulation + features
};

/// A copy of `model` without IfcFurnishingElement / IfcFurniture triangles; `glass` filtered
/// alongside into `bare_glass`.
BimModel withoutFurniture(const BimModel& model, const std::vector<bool>& glass,
                          std::vector<bool>& bare_glass);

class SurveyCatalogue {
 public:
  /// `tls_step_deg`: the indoor scans' angular step (azimuth and elevation).
  SurveyCatalogue(const PipelineParams& params, int max_stations, double tls_step_deg);
  /// "two-rooms", ... (presets) or "duplex.ifc", ... (../shared/data/ifc). Loaded once.
  const Building& building(const std::string& name);
  /// TLS from each station (tls_step_deg, 3 mm noise), merged with sensor origins.
  const SideData& indoor(const std::string& name);
  /// The MMS street loop around a generated building (the demo's outdoor scan for "house").
  const SideData& mms(const std::string& name);
  /// The building's model as a target (as scanned: presets keep their furniture).
  const SideData& modelTarget(const std::string& name);
  /// The building's model without furniture as a target.
  const SideData& bareModelTarget(const std::string& name);
  /// Scene of the model without furniture (glass transparent, ground on): the oracle's.
  const ScanScene& bareScene(const std::string& name);
  const PipelineParams& params() const { return params_; }
  double secondsSpent() const { return seconds_; }

 private:
  SideData scanSide(PointCloud cloud, double seconds_so_far);
  SideData modelSide(const std::string& label, std::shared_ptr<const BimModel> model);
  PipelineParams params_;
  int max_stations_;
  double tls_step_deg_;
  double seconds_ = 0.0;
  std::map<std::string, Building> buildings_;
  std::map<std::string, SideData> indoor_, mms_, models_, bare_models_;
  std::map<std::string, std::unique_ptr<ScanScene>> bare_scenes_;
};

/// The IFC models of the wrong-pair suite, in ../shared/data/ifc.
std::vector<std::string> ifcModelNames();

}  // namespace plumb::verdict
