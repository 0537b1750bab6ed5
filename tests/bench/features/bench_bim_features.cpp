// The BIM's own planes, façades and openings (features/bim) on the real IFC files of the
// shared data and on the generated benchmark building: how many come out and how long it
// takes. Prints one table row per model. Usage: bench_bim_features [IFC_DIR]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <vector>

#include "common/stopwatch.hpp"
#include "features/bim/bim_features.hpp"
#include "features/mesh_edges/mesh_edges.hpp"
#include "io/io.hpp"
#include "simulation/building_generator.hpp"
#include "simulation/presets.hpp"
#include "support/test_support.hpp"

namespace {

std::size_t countOfPrefix(const plumb::BimModel& m, const char* prefix) {
  std::size_t n = 0;
  for (const auto& e : m.elements) n += e.type.rfind(prefix, 0) == 0 ? 1 : 0;
  return n;
}

void row(const std::string& name, const plumb::BimModel& m, double seconds_read) {
  const auto t0 = std::chrono::steady_clock::now();
  const plumb::BimFeatureResult r = plumb::extractBimFeatures(m);
  const double seconds = plumb::secondsSince(t0);
  const auto t1 = std::chrono::steady_clock::now();
  const auto edges = plumb::extractSharpEdges(m.mesh).segments.size();
  const double seconds_edges = plumb::secondsSince(t1);
  double area = 0.0;
  for (const auto& p : r.features.planes) area += p.area;
  std::printf("%-40s %9zu %7zu %7zu %6zu %8zu %9.0f %7zu %9zu %8zu %7.2f %7.2f %7zu %6.2f\n",
              name.c_str(), m.mesh.triangleCount(), countOfPrefix(m, "IfcWindow"),
              countOfPrefix(m, "IfcDoor"), countOfPrefix(m, "IfcWall"), r.features.planes.size(),
              area, r.features.facades.size(), r.features.openings.size(),
              r.openings_without_host, seconds_read, seconds, edges, seconds_edges);
}

}  // namespace

int main(int argc, char** argv) {
  const std::filesystem::path dir = argc > 1 ? argv[1] : plumb::test::sharedData("ifc");
  std::printf("%-40s %9s %7s %7s %6s %8s %9s %7s %9s %8s %7s %7s %7s %6s\n", "model", "triangles",
              "windows", "doors", "walls", "polygons", "area_m2", "facades", "openings", "no_host",
              "s_read", "s_bim", "edges", "s_edge");
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(dir))
    for (const auto& e : std::filesystem::directory_iterator(dir))
      if (e.path().extension() == ".ifc") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto& f : files) {
    try {
      const auto t0 = std::chrono::steady_clock::now();
      const plumb::BimModel m = plumb::readModel(f);
      row(f.filename().string(), m, plumb::secondsSince(t0));
    } catch (const std::exception& e) {
      std::printf("%-40s cannot be read: %s\n", f.filename().string().c_str(), e.what());
    }
  }
  for (const char* preset : {"house", "office-floor", "big-office"}) {
    const auto t0 = std::chrono::steady_clock::now();
    const plumb::GeneratedBuilding b = plumb::generateBuilding(plumb::buildingPreset(preset));
    row(std::string("generated ") + preset, b.model, plumb::secondsSince(t0));
  }
  return 0;
}
