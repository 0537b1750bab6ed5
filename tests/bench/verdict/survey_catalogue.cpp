#include "survey_catalogue.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "io/io.hpp"
#include "model/dataset.hpp"
#include "registration/refine/icp_refinement.hpp"
#include "room_stations.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/mms_scanner.hpp"
#include "simulation/presets.hpp"
#include "simulation/tls_scanner.hpp"
#include "support/test_support.hpp"
#include "common/stopwatch.hpp"

namespace plumb::verdict {

namespace {

bool isIfc(const std::string& name) {
  return name.size() > 4 && name.substr(name.size() - 4) == ".ifc";
}

/// At most n of `all`, spread evenly over the list (first, ..., last).
std::vector<Eigen::Vector3d> spread(const std::vector<Eigen::Vector3d>& all, int n) {
  if (int(all.size()) <= n) return all;
  std::vector<Eigen::Vector3d> out;
  for (int i = 0; i < n; ++i) out.push_back(all[std::size_t(i * (all.size() - 1) / (n - 1))]);
  return out;
}

Building generatedBuilding(const std::string& name, int max_stations) {
  Building b;
  b.name = name;
  GeneratedBuilding g = generateBuilding(buildingPreset(name));
  b.stations = spread(roomCentres(g.spec, 0), max_stations);
  b.footprint = g.truth.footprint;
  b.glass = g.glass_triangles;
  b.model = std::make_shared<const BimModel>(std::move(g.model));
  return b;
}

Building ifcBuilding(const std::string& name, int max_stations) {
  Building b;
  b.name = name;
  try {
    b.model = std::make_shared<const BimModel>(readModel(test::sharedData("ifc/" + name)));
  } catch (const std::exception& e) {
    b.problem = std::string("import failed: ") + e.what();
    return b;
  }
  if (b.model->mesh.triangles.empty()) {
    b.problem = "imported without triangles";
    return b;
  }
  StationSearch s;
  s.max_stations = max_stations;
  b.stations = findRoomStations(*b.model, s);
  if (b.stations.empty()) b.problem = "no enclosed room found (no station without escaping rays)";
  return b;
}

/// cache[name], made by make() the first time.
template <class Make>
const SideData& memo(std::map<std::string, SideData>& cache, const std::string& name, Make make) {
  auto it = cache.find(name);
  if (it != cache.end()) return it->second;
  return cache.emplace(name, make()).first->second;
}

}  // namespace

std::vector<std::string> ifcModelNames() {
  return {"duplex.ifc", "AC20-FZK-Haus.ifc", "IfcOpenHouse_IFC4.ifc", "example.ifc",
          "tested_sample_project.ifc"};
}

BimModel withoutFurniture(const BimModel& model, const std::vector<bool>& glass,
                          std::vector<bool>& bare_glass) {
  BimModel out;
  out.source = model.source;
  out.format = model.format;
  out.elements = model.elements;
  out.mesh.vertices = model.mesh.vertices;
  bare_glass.clear();
  for (std::size_t t = 0; t < model.mesh.triangles.size(); ++t) {
    const std::uint32_t e = t < model.triangle_element.size() ? model.triangle_element[t] : 0;
    const std::string type = e < model.elements.size() ? model.elements[e].type : "";
    if (type == "IfcFurnishingElement" || type == "IfcFurniture") continue;
    out.mesh.triangles.push_back(model.mesh.triangles[t]);
    if (t < model.triangle_element.size()) out.triangle_element.push_back(e);
    if (!glass.empty()) bare_glass.push_back(glass[t]);
  }
  return out;
}

SurveyCatalogue::SurveyCatalogue(const PipelineParams& params, int max_stations,
                                 double tls_step_deg)
    : params_(params), max_stations_(max_stations), tls_step_deg_(tls_step_deg) {}

const Building& SurveyCatalogue::building(const std::string& name) {
  auto it = buildings_.find(name);
  if (it != buildings_.end()) return it->second;
  const auto t0 = std::chrono::steady_clock::now();
  Building b = isIfc(name) ? ifcBuilding(name, max_stations_) : generatedBuilding(name, max_stations_);
  if (b.model)
    b.bare = std::make_shared<const BimModel>(withoutFurniture(*b.model, b.glass, b.bare_glass));
  const double s = secondsSince(t0);
  seconds_ += s;
  std::printf("  [data] %s: %s, %zu stations (%.1f s)\n", name.c_str(),
              b.usable() ? (std::to_string(b.model->mesh.triangles.size()) + " triangles").c_str()
                         : b.problem.substr(0, 140).c_str(),
              b.stations.size(), s);
  return buildings_.emplace(name, std::move(b)).first->second;
}

SideData SurveyCatalogue::scanSide(PointCloud cloud, double seconds_so_far) {
  const auto t0 = std::chrono::steady_clock::now();
  SideData d;
  d.cloud = std::move(cloud);
  d.cloud.removeNonFinite();
  RegistrationSide side;
  side.cloud = &d.cloud;
  d.features = extractFeatures(side, params_, /*with_segments=*/true);
  d.seconds = seconds_so_far + secondsSince(t0);
  seconds_ += d.seconds;
  return d;
}

SideData SurveyCatalogue::modelSide(const std::string& label,
                                    std::shared_ptr<const BimModel> model) {
  const auto t0 = std::chrono::steady_clock::now();
  SideData d;
  d.model = std::move(model);
  RegistrationSide side;
  side.model = d.model.get();
  d.features = extractFeatures(side, params_, /*with_segments=*/false);
  d.samples = sampleMeshSurface(d.model->mesh, params_.model_sample_spacing, params_.seed);
  d.seconds = secondsSince(t0);
  seconds_ += d.seconds;
  std::printf("  [data] %s target: %zu edges, %zu surface samples (%.1f s)\n", label.c_str(),
              d.features.segments.size(), d.samples.size(), d.seconds);
  return d;
}

const SideData& SurveyCatalogue::indoor(const std::string& name) {
  return memo(indoor_, name, [&] {
    const Building& b = building(name);
    const auto t0 = std::chrono::steady_clock::now();
    const ScanScene scene(*b.model, b.glass);
    TlsParams tp;
    tp.azimuth_step_deg = tp.elevation_step_deg = tls_step_deg_;
    tp.noise_mm = 3.0;
    Dataset d;
    const std::uint64_t seed = 500 + std::hash<std::string>{}(name) % 1000;
    for (std::size_t i = 0; i < b.stations.size(); ++i)
      d.scans.push_back(simulateTls(scene, b.stations[i], tp, seed + i));
    SideData side = scanSide(d.merged(true), secondsSince(t0));
    std::printf("  [data] %s indoor: %zu points, %zu planes, %zu openings, %zu segments (%.1f s)\n",
                name.c_str(), side.cloud.size(), side.features.planes.size(),
                side.features.openings.size(), side.features.segments.size(), side.seconds);
    return side;
  });
}

const SideData& SurveyCatalogue::mms(const std::string& name) {
  return memo(mms_, name, [&] {
    const Building& b = building(name);
    const auto t0 = std::chrono::steady_clock::now();
    const ScanScene scene(*b.model, b.glass);
    MmsParams mp;
    Scan scan = simulateMms(scene, streetTrajectory(b.footprint, mp), mp, 11);
    SideData side = scanSide(std::move(scan.cloud), secondsSince(t0));
    std::printf("  [data] %s MMS: %zu points (%.1f s)\n", name.c_str(), side.cloud.size(),
                side.seconds);
    return side;
  });
}

const SideData& SurveyCatalogue::modelTarget(const std::string& name) {
  return memo(models_, name, [&] { return modelSide(name + " model", building(name).model); });
}

const SideData& SurveyCatalogue::bareModelTarget(const std::string& name) {
  return memo(bare_models_, name,
              [&] { return modelSide(name + " bare model", building(name).bare); });
}

const ScanScene& SurveyCatalogue::bareScene(const std::string& name) {
  auto it = bare_scenes_.find(name);
  if (it != bare_scenes_.end()) return *it->second;
  const Building& b = building(name);
  auto scene = std::make_unique<ScanScene>(*b.bare, b.bare_glass);
  return *bare_scenes_.emplace(name, std::move(scene)).first->second;
}

}  // namespace plumb::verdict
