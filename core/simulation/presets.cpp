#include "simulation/presets.hpp"

#include <cmath>
#include <utility>

#include "common/error.hpp"
#include "simulation/building_layout.hpp"

namespace plumb {

namespace {

struct Preset {
  const char* name;
  const char* description;
  BuildingSpec (*make)();
};

BuildingSpec grid(const char* name, std::vector<double> columns, std::vector<double> rows) {
  BuildingSpec s;
  s.name = name;
  s.column_widths = std::move(columns);
  s.row_depths = std::move(rows);
  return s;
}

BuildingSpec twoRooms() { return grid("two-rooms", {4.0, 4.0}, {5.0}); }

BuildingSpec house() {
  BuildingSpec s = grid("house", {4.5, 4.5}, {4.0, 4.0});
  s.storeys = 2;
  s.furniture_per_room = 2;
  return s;
}

BuildingSpec officeFloor() {
  BuildingSpec s = grid("office-floor", {4.0, 4.0, 4.0, 4.0}, {5.0, 2.0, 5.0});  // offices, corridor, offices
  s.storey_height = 3.3;
  s.furniture_per_room = 1;
  return s;
}

BuildingSpec lShaped() {
  BuildingSpec s = grid("l-shaped", {4.0, 4.0, 4.0}, {5.0, 5.0});
  s.mask = {"###", "#.."};
  s.exterior_wall_thickness = 0.45;
  return s;
}

BuildingSpec uShaped() {
  BuildingSpec s = grid("u-shaped", {4.0, 4.0, 4.0}, {4.0, 4.0});
  s.mask = {"###", "#.#"};
  return s;
}

BuildingSpec nonManhattan() {
  BuildingSpec s = grid("non-manhattan", {5.0, 5.0}, {5.0, 5.0});
  s.axis_angle_deg = 60.0;
  return s;
}

BuildingSpec bigOffice() {
  BuildingSpec s = grid("big-office", std::vector<double>(9, 4.0), {5.0, 2.0, 5.0});
  s.storeys = 5;
  s.storey_height = 3.3;
  s.window_spacing = 2.0;
  s.window_width = 0.9;
  s.furniture_per_room = 3;
  return s;
}

const Preset kPresets[] = {
    {"two-rooms", "1 storey, 2 rooms of 4 x 5 m, windows, an entrance and an interior door", twoRooms},
    {"house", "2 storeys of 2 x 2 rooms (9 x 8 m), windows on every facade, furniture", house},
    {"office-floor", "1 storey: 4 offices, a 2 m corridor, 4 offices; furniture", officeFloor},
    {"l-shaped", "1 storey, L footprint of 5 rooms, 0.45 m exterior walls", lShaped},
    {"u-shaped", "1 storey, U footprint of 5 rooms", uShaped},
    {"non-manhattan", "1 storey, 2 x 2 rooms on a 60-degree parallelogram plan", nonManhattan},
    {"big-office", "5 storeys of 9 x 3 cells with furniture (~50k triangles, benchmarks)", bigOffice},
};

const Preset* findPreset(const std::string& name) {
  for (const auto& p : kPresets)
    if (name == p.name) return &p;
  return nullptr;
}

}  // namespace

std::vector<std::string> buildingPresetNames() {
  std::vector<std::string> names;
  for (const auto& p : kPresets) names.emplace_back(p.name);
  return names;
}

std::string buildingPresetDescription(const std::string& name) {
  const Preset* p = findPreset(name);
  return p ? p->description : "";
}

BuildingSpec buildingPreset(const std::string& name) {
  const Preset* p = findPreset(name);
  if (!p) {
    std::string list;
    for (const auto& n : buildingPresetNames()) list += (list.empty() ? "" : ", ") + n;
    throw InputError("unknown building preset '" + name + "' (valid: " + list + ")");
  }
  return p->make();
}

std::vector<Eigen::Vector3d> roomCentres(const BuildingSpec& spec, int storey, double height) {
  const auto U = sim::planLines(spec.column_widths);
  const auto V = sim::planLines(spec.row_depths);
  const double a = spec.axis_angle_deg * M_PI / 180.0;
  const bool manhattan = std::abs(spec.axis_angle_deg - 90.0) < 1e-12;
  const double c = manhattan ? 0.0 : std::cos(a), s = manhattan ? 1.0 : std::sin(a);
  const double z = storey * spec.storey_height + spec.slab_thickness + height;
  std::vector<Eigen::Vector3d> out;
  for (std::size_t r = 0; r < spec.rows(); ++r)
    for (std::size_t col = 0; col < spec.columns(); ++col)
      if (spec.isRoom(static_cast<long>(col), static_cast<long>(r))) {
        const double u = 0.5 * (U[col] + U[col + 1]), v = 0.5 * (V[r] + V[r + 1]);
        out.emplace_back(u + v * c, v * s, z);
      }
  return out;
}

}  // namespace plumb
