#include "station_models.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "common/stopwatch.hpp"
#include "io/io.hpp"
#include "registration/refine/icp_refinement.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"
#include "support/test_support.hpp"
#include "survey_catalogue.hpp"

namespace plumb::bimst {

namespace {

bool isIfc(const std::string& name) {
  return name.size() > 4 && name.substr(name.size() - 4) == ".ifc";
}

void loadGenerated(StationModel& m) {
  GeneratedBuilding g = generateBuilding(m.name == "open-office" ? openOfficeSpec() : buildingPreset(m.name));
  m.glass = std::move(g.glass_triangles);
  m.model = std::make_shared<BimModel>(std::move(g.model));
}

void loadIfc(StationModel& m) {
  try {
    m.model = std::make_shared<BimModel>(readModel(test::sharedData("ifc/" + m.name)));
  } catch (const std::exception& e) {
    m.problem = std::string("readModel failed: ") + e.what();
    return;
  }
  if (m.model->mesh.triangles.empty()) m.problem = "read without triangles";
}

void prepareTarget(StationModel& m, const PipelineParams& params) {
  RegistrationSide side;
  side.model = m.model.get();
  m.features = extractFeatures(side, params, /*with_segments=*/false);
  m.samples = sampleMeshSurface(m.model->mesh, params.model_sample_spacing, params.seed);
  std::vector<bool> bare_glass;
  m.bare = std::make_shared<const BimModel>(verdict::withoutFurniture(*m.model, m.glass, bare_glass));
  m.bare_scene = std::make_unique<ScanScene>(*m.bare, bare_glass);
  m.scene = std::make_unique<ScanScene>(*m.model, m.glass);
}

}  // namespace

BuildingSpec openOfficeSpec() {
  BuildingSpec s;
  s.name = "open-office";
  s.column_widths = {4.0, 16.0};
  s.row_depths = {5.0, 2.0, 7.0};  // halls of different depth: not copies of each other
  s.storey_height = 3.3;
  s.furniture_per_room = 1;
  return s;
}

std::vector<std::string> defaultModelNames() {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(test::sharedData("ifc")))
    if (isIfc(e.path().filename().string())) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  out.push_back("office-floor");
  out.push_back("open-office");
  return out;
}

std::unique_ptr<StationModel> loadStationModel(const std::string& name, const PipelineParams& params) {
  const auto t0 = std::chrono::steady_clock::now();
  auto m = std::make_unique<StationModel>();
  m->name = name;
  try {
    isIfc(name) ? loadIfc(*m) : loadGenerated(*m);
    if (m->usable()) prepareTarget(*m, params);
  } catch (const std::exception& e) {
    m->problem = e.what();
  }
  m->seconds = secondsSince(t0);
  if (m->usable())
    std::printf("  [model] %s: %zu triangles, %zu planes, %zu openings, %zu edges (%.1f s)\n", name.c_str(),
                m->model->mesh.triangles.size(), m->features.planes.size(), m->features.openings.size(),
                m->features.segments.size(), m->seconds);
  else
    std::printf("  [model] %s: skipped: %s\n", name.c_str(), m->problem.substr(0, 300).c_str());
  std::fflush(stdout);
  return m;
}

}  // namespace plumb::bimst
