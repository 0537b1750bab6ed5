#include "simulation/ground_truth_json.hpp"

#include <nlohmann/json.hpp>

#include <fstream>

#include "common/atomic_file.hpp"
#include "common/error.hpp"

namespace plumb {

namespace {

nlohmann::json vec(const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); }

Eigen::Vector3d vec(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != 3) throw InputError("expected [x, y, z]");
  return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

nlohmann::json segments(const std::vector<Segment3D>& s) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& e : s) out.push_back({vec(e.a), vec(e.b)});
  return out;
}

std::vector<Segment3D> segments(const nlohmann::json& j) {
  std::vector<Segment3D> out;
  for (const auto& e : j) {
    Segment3D s;
    s.a = vec(e.at(0));
    s.b = vec(e.at(1));
    out.push_back(s);
  }
  return out;
}

}  // namespace

nlohmann::json buildingTruthToJson(const BuildingTruth& t, const BimModel& model) {
  nlohmann::json j;
  j["format"] = "plumb-building-truth";
  j["version"] = 1;
  j["exterior_wall_thickness"] = t.exterior_wall_thickness;
  j["interior_wall_thickness"] = t.interior_wall_thickness;
  j["axis_angle_deg"] = t.axis_angle_deg;
  j["footprint"] = nlohmann::json::array();
  for (const auto& p : t.footprint) j["footprint"].push_back(vec(p));
  j["elements"] = nlohmann::json::array();
  for (std::size_t i = 0; i < model.elements.size(); ++i)
    j["elements"].push_back({{"id", i}, {"type", model.elements[i].type}, {"name", model.elements[i].name},
                             {"guid", model.elements[i].guid}});
  j["planes"] = nlohmann::json::array();
  for (const auto& p : t.planes)
    j["planes"].push_back({{"normal", vec(p.normal)}, {"offset", p.offset}, {"element", p.element},
                           {"type", p.element_type}, {"face", p.face}, {"area", p.area}});
  j["openings"] = nlohmann::json::array();
  for (const auto& o : t.openings) {
    nlohmann::json corners = nlohmann::json::array();
    for (const auto& c : o.corners) corners.push_back(vec(c));
    j["openings"].push_back({{"element", o.element}, {"type", o.element_type}, {"wall", o.wall},
                             {"face", o.face}, {"face_normal", vec(o.face_normal)}, {"storey", o.storey},
                             {"corners", corners}});
  }
  j["sharp_edges"] = segments(t.sharp_edges);
  j["glass_edges"] = segments(t.glass_edges);
  return j;
}

BuildingTruth buildingTruthFromJson(const nlohmann::json& j) {
  BuildingTruth t;
  try {
    if (j.value("format", "") != "plumb-building-truth") throw InputError("not a plumb building truth (\"format\")");
    t.exterior_wall_thickness = j.at("exterior_wall_thickness").get<double>();
    t.interior_wall_thickness = j.at("interior_wall_thickness").get<double>();
    t.axis_angle_deg = j.at("axis_angle_deg").get<double>();
    for (const auto& p : j.at("footprint")) t.footprint.push_back(vec(p));
    for (const auto& p : j.at("planes")) {
      TruthPlane q;
      q.normal = vec(p.at("normal"));
      q.offset = p.at("offset").get<double>();
      q.element = p.at("element").get<std::uint32_t>();
      q.element_type = p.at("type").get<std::string>();
      q.face = p.at("face").get<std::string>();
      q.area = p.at("area").get<double>();
      t.planes.push_back(q);
    }
    for (const auto& o : j.at("openings")) {
      TruthOpening q;
      q.element = o.at("element").get<std::uint32_t>();
      q.element_type = o.at("type").get<std::string>();
      q.wall = o.at("wall").get<std::uint32_t>();
      q.face = o.at("face").get<std::string>();
      q.face_normal = vec(o.at("face_normal"));
      q.storey = o.at("storey").get<int>();
      for (std::size_t k = 0; k < 4; ++k) q.corners[k] = vec(o.at("corners").at(k));
      t.openings.push_back(q);
    }
    t.sharp_edges = segments(j.at("sharp_edges"));
    t.glass_edges = segments(j.at("glass_edges"));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(std::string("building truth: ") + e.what());
  }
  return t;
}

void writeBuildingTruth(const std::filesystem::path& path, const GeneratedBuilding& building) {
  nlohmann::json j = buildingTruthToJson(building.truth, building.model);
  j["spec"] = buildingSpecToJson(building.spec);
  writeFileAtomically(path, [&](std::ostream& out) { out << j.dump(1) << "\n"; });
}

BuildingTruth readBuildingTruth(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw FileError(path, "cannot open ground truth file");
  try {
    return buildingTruthFromJson(nlohmann::json::parse(in));
  } catch (const nlohmann::json::parse_error& e) {
    throw FileError(path, std::string("invalid JSON: ") + e.what(), atByte(e.byte));
  } catch (const InputError& e) {
    throw FileError(path, e.what());
  }
}

}  // namespace plumb
