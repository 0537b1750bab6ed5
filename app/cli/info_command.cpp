// plumb-cli info FILE... [--json]: what each file holds (format, scans, points, fields, bounds;
// triangles and element types for models). One block per file; a file that cannot be read
// gets a one-line error on stderr, the others are still reported, and the exit code is 1.
// E57 and LAS files are streamed (io/stream/stream_statistics.hpp): memory stays bounded by
// the chunk size however large the file; other formats are read whole, then counted the same
// way. --memory-budget MB: a file that must be read whole is refused above the budget, and
// the chunk size of a streamed file never exceeds a quarter of it.
#include <nlohmann/json.hpp>

#include <iomanip>
#include <iostream>
#include <sstream>

#include "cli/command.hpp"
#include "cli/option_checks.hpp"
#include "io/io.hpp"
#include "io/stream/point_convert.hpp"
#include "io/stream/point_stream.hpp"
#include "io/stream/stream_statistics.hpp"

namespace plumb::cli {
namespace {

nlohmann::json boundsJson(const Bounds& b) {
  if (b.empty()) return nullptr;
  return {{"min", {b.min.x(), b.min.y(), b.min.z()}}, {"max", {b.max.x(), b.max.y(), b.max.z()}}};
}

std::string vec(const Eigen::Vector3d& v) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(4) << v.x() << " " << v.y() << " " << v.z();
  return s.str();
}

nlohmann::json describePoints(const std::filesystem::path& path, const DatasetStatistics& d) {
  nlohmann::json j;
  j["file"] = path.string();
  j["kind"] = "points";
  j["format"] = d.format;
  j["points"] = d.points;
  j["bounds"] = boundsJson(d.bounds);
  if (!d.coordinate_system.empty()) j["coordinate_system"] = d.coordinate_system;
  nlohmann::json scans = nlohmann::json::array();
  for (const auto& s : d.scans) {
    nlohmann::json sj{{"name", s.name}, {"points", s.points}, {"fields", s.fields}};
    if (s.finite_points != s.points) sj["finite_points"] = s.finite_points;
    if (s.grid_rows > 0) sj["grid"] = {s.grid_rows, s.grid_columns};
    if (s.has_pose) {
      const auto& t = s.pose.translation();
      sj["pose_translation"] = {t.x(), t.y(), t.z()};
    }
    scans.push_back(sj);
  }
  j["scans"] = scans;
  nlohmann::json meta = nlohmann::json::object();
  for (const auto& [k, v] : d.metadata) meta[k] = v;
  j["metadata"] = meta;
  return j;
}

nlohmann::json describeModel(const std::filesystem::path& path, const BimModel& m) {
  nlohmann::json j;
  j["file"] = path.string();
  j["kind"] = "model";
  j["format"] = m.format;
  j["vertices"] = m.mesh.vertices.size();
  j["triangles"] = m.mesh.triangleCount();
  j["elements"] = m.elements.size();
  j["bounds"] = boundsJson(m.mesh.bounds());
  nlohmann::json types = nlohmann::json::object();
  for (const auto& [type, count] : m.elementTypeCounts()) types[type.empty() ? "(untyped)" : type] = count;
  j["element_types"] = types;
  return j;
}

// E57 and LAS are streamed; other files are read whole.
nlohmann::json describe(const std::filesystem::path& path, std::uint64_t budget) {
  if (streamsInChunks(path) && !isModelFormat(formatFromExtension(path)))
    return describePoints(path, datasetStatistics(path, streamOptionsWithin(budget)));
  if (!isModelFormat(formatFromExtension(path))) checkWholeReadFits(path, budget, "describing it");
  LoadedData data = readFile(path);
  if (auto* d = std::get_if<Dataset>(&data)) return describePoints(path, datasetStatistics(std::move(*d)));
  return describeModel(path, std::get<BimModel>(data));
}

void printText(const nlohmann::json& j) {
  std::cout << j["file"].get<std::string>() << "\n";
  std::cout << "  format:    " << j["format"].get<std::string>() << "\n";
  if (j["kind"] == "points") {
    std::cout << "  scans:     " << j["scans"].size() << "\n";
    std::cout << "  points:    " << j["points"].get<std::size_t>() << "\n";
    for (const auto& s : j["scans"]) {
      std::cout << "  scan \"" << s["name"].get<std::string>() << "\": " << s["points"].get<std::size_t>() << " points";
      if (s.contains("finite_points")) std::cout << " (" << s["finite_points"].get<std::size_t>() << " finite)";
      if (s.contains("grid")) std::cout << ", grid " << s["grid"][0] << " x " << s["grid"][1];
      if (s.contains("pose_translation"))
        std::cout << ", sensor at " << s["pose_translation"][0] << " " << s["pose_translation"][1] << " "
                  << s["pose_translation"][2];
      std::cout << "\n    fields: ";
      for (const auto& f : s["fields"]) std::cout << f.get<std::string>() << " ";
      std::cout << "\n";
    }
  } else {
    std::cout << "  vertices:  " << j["vertices"].get<std::size_t>() << "\n";
    std::cout << "  triangles: " << j["triangles"].get<std::size_t>() << "\n";
    std::cout << "  elements:  " << j["elements"].get<std::size_t>() << "\n";
    for (const auto& [type, count] : j["element_types"].items())
      std::cout << "    " << type << ": " << count.get<std::size_t>() << "\n";
  }
  if (!j["bounds"].is_null()) {
    const auto& b = j["bounds"];
    Eigen::Vector3d lo(b["min"][0], b["min"][1], b["min"][2]), hi(b["max"][0], b["max"][1], b["max"][2]);
    std::cout << "  bounds:    min " << vec(lo) << "\n             max " << vec(hi) << "\n             size "
              << vec(hi - lo) << "\n";
  } else {
    std::cout << "  bounds:    (empty)\n";
  }
  if (j.contains("metadata"))
    for (const auto& [k, v] : j["metadata"].items()) std::cout << "  " << k << ": " << v.get<std::string>() << "\n";
}

}  // namespace

void addInfoCommand(CLI::App& app, Action& action) {
  auto* cmd = app.add_subcommand("info", "Describe point cloud / model files (format, points, fields, bounds)");
  auto files = std::make_shared<std::vector<std::string>>();
  auto json = std::make_shared<bool>(false);
  cmd->add_option("files", *files, "Files to describe")->required();
  cmd->add_flag("--json", *json, "Print a JSON array (one object per file)");
  auto budget = std::make_shared<std::string>();
  cmd->add_option("--memory-budget", *budget, memoryBudgetHelp());
  cmd->callback([&action, files, json, budget] {
    action = [files, json, budget]() {
      const std::uint64_t bytes = memoryBudgetBytes(memoryParamsFromOption(*budget));
      int rc = 0;
      nlohmann::json all = nlohmann::json::array();
      for (const auto& f : *files) {
        try {
          const auto j = describe(f, bytes);
          if (*json) all.push_back(j);
          else printText(j);
        } catch (const std::exception& e) {
          std::cerr << "plumb-cli: error: " << e.what() << "\n";
          if (*json) all.push_back({{"file", f}, {"error", e.what()}});
          rc = 1;
        }
      }
      if (*json) std::cout << all.dump(2) << "\n";
      return rc;
    };
  });
}

}  // namespace plumb::cli
