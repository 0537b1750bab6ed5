#pragma once
// The models of bench_bim_stations, each loaded once: every IFC file of ../shared/data/ifc that
// Plumb reads (readModel; a file it cannot read is kept with the reason, and skipped), and
// generated buildings: the presets by name, plus "open-office", a bench-only spec (an office
// floor with a single 16 m corridor cell between two open-plan halls of 16 x 5 and 16 x 7 m,
// and four 4 m offices: no preset has a hall or a corridor in one cell; office-floor's
// corridor is four 4 x 2 m cells with doors between them).
#include <memory>
#include <string>
#include <vector>

#include "model/bim_model.hpp"
#include "model/feature_set.hpp"
#include "model/point_cloud.hpp"
#include "registration/auto/registration_pipeline.hpp"
#include "simulation/building_spec.hpp"
#include "simulation/scan_scene.hpp"

namespace plumb::bimst {

struct StationModel {
  std::string name;     ///< IFC file name, preset name or "open-office"
  std::string problem;  ///< why it is skipped ("" = usable)
  std::shared_ptr<BimModel> model;  ///< as modelled (presets with their furniture)
  std::vector<bool> glass;                ///< per triangle of model (generated only)
  /// The registration target: the model's features and surface samples, extracted once.
  FeatureSet features;
  PointCloud samples;
  /// The model without furniture, glass transparent: the placement oracle's scene.
  std::shared_ptr<const BimModel> bare;
  std::unique_ptr<ScanScene> bare_scene;
  /// The scanner's scene (glass transparent).
  std::unique_ptr<ScanScene> scene;
  double seconds = 0.0;  ///< loading + target features
  bool usable() const { return problem.empty(); }
};

/// The bench-only "open-office" floor (above): columns 4 and 16 m, rows 5, 2 and 7 m, storey
/// 3.3 m, one furniture box per room.
BuildingSpec openOfficeSpec();

/// The default model list: every *.ifc in ../shared/data/ifc (sorted), office-floor and
/// open-office.
std::vector<std::string> defaultModelNames();

/// Loads `name` (an IFC file name, a preset or "open-office") and prepares it as a target
/// with `params`. Never throws: a model that cannot be read gets `problem`.
std::unique_ptr<StationModel> loadStationModel(const std::string& name, const PipelineParams& params);

}  // namespace plumb::bimst
