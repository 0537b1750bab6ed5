// IFC coverage (issue 14): every IFC file read by assimp through Plumb's own isolated import
// (readMesh, ModelParser::assimp) and by IFC++ (in a forked child under a time limit), then by
// Plumb as it reads models (ModelParser::automatic: assimp, IFC++ where assimp refuses). One
// table row per file; the errors below the table. Exit status 1 when Plumb fails on a file that
// one of the two parsers reads.
//
//   bench_ifc_coverage [FILE_OR_DIR ...]   (default: shared data ifc/ and tests/data/ifc/)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "common/stopwatch.hpp"
#include "ifcpp_child.hpp"
#include "io/mesh/mesh_io.hpp"
#include "support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
constexpr unsigned kSeconds = 120;

struct AssimpRun {
  bool ok = false;
  std::size_t triangles = 0, elements = 0, windows = 0, doors = 0;
  double seconds = 0;
  std::string error;
};

AssimpRun runPlumb(const fs::path& file, plumb::ModelParser parser) {
  AssimpRun run;
  const auto t0 = std::chrono::steady_clock::now();
  try {
    plumb::ImportLimits limits;
    limits.seconds = kSeconds;
    const plumb::BimModel m = plumb::readMesh(file, nullptr, limits, parser);
    run = {true, m.mesh.triangleCount(), m.elements.size(), m.elementCountOfType("IfcWindow"),
           m.elementCountOfType("IfcDoor"), 0, ""};
  } catch (const std::exception& e) {
    run.error = e.what();
  }
  run.seconds = plumb::secondsSince(t0);
  return run;
}

std::vector<fs::path> ifcFiles(const std::vector<fs::path>& places) {
  std::vector<fs::path> files;
  for (const auto& p : places) {
    if (fs::is_regular_file(p)) files.push_back(p);
    if (!fs::is_directory(p)) continue;
    for (const auto& e : fs::directory_iterator(p))
      if (e.path().extension() == ".ifc") files.push_back(e.path());
  }
  std::sort(files.begin(), files.end(), [](const fs::path& a, const fs::path& b) { return a.filename() < b.filename(); });
  return files;
}

std::string shortError(const std::string& e) { return e.size() > 300 ? e.substr(0, 300) + " ..." : e; }

/// Which parser Plumb's automatic import matched, by its triangle count.
std::string plumbUses(const AssimpRun& plumb, const AssimpRun& assimp, const plumb::bench::IfcppRun& ifcpp) {
  if (!plumb.ok) return "fails";
  if (assimp.ok && plumb.triangles == assimp.triangles) return "assimp";
  if (ifcpp.ok && plumb.triangles == ifcpp.triangles) return "IFC++";
  return "? (" + std::to_string(plumb.triangles) + " tris)";
}

void header() {
  std::printf("| file | schema | MB | assimp | tris | elements | win/door | s | IFC++ | entities | products | tris | win/door | s | Plumb uses |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
}

void row(const fs::path& f, const AssimpRun& a, const plumb::bench::IfcppRun& i, const std::string& uses) {
  const double mb = static_cast<double>(fs::file_size(f)) / 1e6;
  std::printf("| %s | %s | %.2f | %s | %zu | %zu | %zu/%zu | %.2f | %s | %zu | %zu | %zu | %zu/%zu | %.2f | %s |\n",
              f.filename().c_str(), plumb::ifcFileSchema(f).c_str(), mb, a.ok ? "ok" : "fail", a.triangles,
              a.elements, a.windows, a.doors, a.seconds, i.ok ? "ok" : "fail", i.entities, i.products, i.triangles,
              i.windows, i.doors, i.seconds, uses.c_str());
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<fs::path> places(argv + 1, argv + argc);
  if (places.empty()) places = {plumb::test::sharedData("ifc"), fs::path(PLUMB_SOURCE_DIR) / "tests/data/ifc"};
  const auto files = ifcFiles(places);
  std::vector<std::string> errors;
  int inconsistent = 0;
  header();
  for (const auto& f : files) {
    const AssimpRun assimp = runPlumb(f, plumb::ModelParser::assimp);
    const plumb::bench::IfcppRun ifcpp = plumb::bench::runIfcppInChild(f, kSeconds);
    const AssimpRun plumb = runPlumb(f, plumb::ModelParser::automatic);
    row(f, assimp, ifcpp, plumbUses(plumb, assimp, ifcpp));
    if (!assimp.ok) errors.push_back(f.filename().string() + ", assimp: " + shortError(assimp.error));
    if (!ifcpp.ok) errors.push_back(f.filename().string() + ", IFC++: " + shortError(ifcpp.error));
    if (!plumb.ok && (assimp.ok || ifcpp.ok)) ++inconsistent;
  }
  std::printf("\n%zu files; errors:\n", files.size());
  for (const auto& e : errors) std::printf("- %s\n", e.c_str());
  if (inconsistent) std::printf("Plumb fails on %d file(s) that assimp or IFC++ reads\n", inconsistent);
  return files.empty() || inconsistent ? 1 : 0;
}
