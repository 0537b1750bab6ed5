#include "simulation/building_spec.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "common/error.hpp"

namespace plumb {

namespace {

void require(bool ok, const std::string& what) {
  if (!ok) throw InputError("building spec: " + what);
}

void requireRange(double v, double lo, double hi, const std::string& key) {
  std::ostringstream s;
  s << "'" << key << "' = " << v << " is outside [" << lo << ", " << hi << "]";
  require(std::isfinite(v) && v >= lo && v <= hi, s.str());
}

}  // namespace

bool BuildingSpec::isRoom(long c, long r) const {
  if (c < 0 || r < 0 || c >= static_cast<long>(columns()) || r >= static_cast<long>(rows()))
    return false;
  if (mask.empty()) return true;
  return mask[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] == '#';
}

void BuildingSpec::validate() const {
  require(!column_widths.empty() && column_widths.size() <= 64, "'column_widths' needs 1..64 values");
  require(!row_depths.empty() && row_depths.size() <= 64, "'row_depths' needs 1..64 values");
  for (double w : column_widths) requireRange(w, 1.0, 30.0, "column_widths");
  for (double d : row_depths) requireRange(d, 1.0, 30.0, "row_depths");
  if (!mask.empty()) {
    require(mask.size() == rows(), "'mask' must have one string per row");
    for (std::size_t r = 0; r < mask.size(); ++r) {
      require(mask[r].size() == columns(),
              "'mask' row " + std::to_string(r) + " must have one char per column");
      for (char ch : mask[r])
        require(ch == '#' || ch == '.', "'mask' row " + std::to_string(r) + " may hold only '#' and '.'");
    }
  }
  requireRange(storeys, 1, 20, "storeys");
  requireRange(storey_height, 2.2, 6.0, "storey_height");
  requireRange(slab_thickness, 0.1, 0.6, "slab_thickness");
  requireRange(exterior_wall_thickness, 0.05, 1.0, "exterior_wall_thickness");
  requireRange(interior_wall_thickness, 0.05, 1.0, "interior_wall_thickness");
  require(std::abs(axis_angle_deg - 90.0) < 1e-12 || (axis_angle_deg >= 20.0 && axis_angle_deg <= 90.0),
          "'axis_angle_deg' must be 90 or within [20, 90]");
  requireRange(window_width, 0.2, 10.0, "window_width");
  requireRange(window_height, 0.2, 5.0, "window_height");
  requireRange(sill_height, 0.0, 3.0, "sill_height");
  requireRange(window_spacing, 0.5, 50.0, "window_spacing");
  requireRange(door_width, 0.5, 5.0, "door_width");
  requireRange(door_height, 1.5, 5.0, "door_height");
  requireRange(furniture_per_room, 0, 20, "furniture_per_room");
  const double clear = storey_height - slab_thickness;
  require(sill_height + window_height < clear - 0.05,
          "'sill_height' + 'window_height' must stay 5 cm below the ceiling");
  require(door_height < clear - 0.05, "'door_height' must stay 5 cm below the ceiling");
  double min_room = 1e9;
  for (double w : column_widths) min_room = std::min(min_room, w);
  for (double d : row_depths) min_room = std::min(min_room, d);
  require(min_room > std::max(exterior_wall_thickness, interior_wall_thickness) / std::sin(axis_angle_deg * M_PI / 180.0) + 0.3,
          "rooms must be wider than the walls");
  // Rooms must be edge-connected (flood fill from the first room).
  std::vector<char> seen(columns() * rows(), 0);
  std::vector<std::pair<long, long>> stack;
  std::size_t room_count = 0;
  for (long r = 0; r < static_cast<long>(rows()); ++r)
    for (long c = 0; c < static_cast<long>(columns()); ++c)
      if (isRoom(c, r)) {
        ++room_count;
        if (stack.empty() && room_count == 1) stack.push_back({c, r});
      }
  require(room_count > 0, "'mask' has no room");
  std::size_t reached = 0;
  while (!stack.empty()) {
    auto [c, r] = stack.back();
    stack.pop_back();
    if (!isRoom(c, r) || seen[static_cast<std::size_t>(r) * columns() + static_cast<std::size_t>(c)]) continue;
    seen[static_cast<std::size_t>(r) * columns() + static_cast<std::size_t>(c)] = 1;
    ++reached;
    stack.insert(stack.end(), {{c + 1, r}, {c - 1, r}, {c, r + 1}, {c, r - 1}});
  }
  require(reached == room_count, "rooms in 'mask' must be edge-connected");
}

nlohmann::json buildingSpecToJson(const BuildingSpec& s) {
  nlohmann::json j;
  j["name"] = s.name;
  j["column_widths"] = s.column_widths;
  j["row_depths"] = s.row_depths;
  j["mask"] = s.mask;
  j["storeys"] = s.storeys;
  j["storey_height"] = s.storey_height;
  j["slab_thickness"] = s.slab_thickness;
  j["exterior_wall_thickness"] = s.exterior_wall_thickness;
  j["interior_wall_thickness"] = s.interior_wall_thickness;
  j["axis_angle_deg"] = s.axis_angle_deg;
  j["window_width"] = s.window_width;
  j["window_height"] = s.window_height;
  j["sill_height"] = s.sill_height;
  j["window_spacing"] = s.window_spacing;
  j["glass"] = s.glass;
  j["door_width"] = s.door_width;
  j["door_height"] = s.door_height;
  j["interior_doors"] = s.interior_doors;
  j["entrance_door"] = s.entrance_door;
  j["furniture_per_room"] = s.furniture_per_room;
  j["seed"] = s.seed;
  return j;
}

BuildingSpec buildingSpecFromJson(const nlohmann::json& j) {
  if (!j.is_object()) throw InputError("building spec: must be a JSON object");
  BuildingSpec s;
  for (const auto& [key, v] : j.items()) {
    try {
      if (key == "name") s.name = v.get<std::string>();
      else if (key == "column_widths") s.column_widths = v.get<std::vector<double>>();
      else if (key == "row_depths") s.row_depths = v.get<std::vector<double>>();
      else if (key == "mask") s.mask = v.get<std::vector<std::string>>();
      else if (key == "storeys") s.storeys = v.get<int>();
      else if (key == "storey_height") s.storey_height = v.get<double>();
      else if (key == "slab_thickness") s.slab_thickness = v.get<double>();
      else if (key == "exterior_wall_thickness") s.exterior_wall_thickness = v.get<double>();
      else if (key == "interior_wall_thickness") s.interior_wall_thickness = v.get<double>();
      else if (key == "axis_angle_deg") s.axis_angle_deg = v.get<double>();
      else if (key == "window_width") s.window_width = v.get<double>();
      else if (key == "window_height") s.window_height = v.get<double>();
      else if (key == "sill_height") s.sill_height = v.get<double>();
      else if (key == "window_spacing") s.window_spacing = v.get<double>();
      else if (key == "glass") s.glass = v.get<bool>();
      else if (key == "door_width") s.door_width = v.get<double>();
      else if (key == "door_height") s.door_height = v.get<double>();
      else if (key == "interior_doors") s.interior_doors = v.get<bool>();
      else if (key == "entrance_door") s.entrance_door = v.get<bool>();
      else if (key == "furniture_per_room") s.furniture_per_room = v.get<int>();
      else if (key == "seed") s.seed = v.get<std::uint64_t>();
      else throw InputError("building spec: unknown key '" + key + "'");
    } catch (const nlohmann::json::exception& e) {
      throw InputError("building spec: key '" + key + "' has a value of the wrong type");
    }
  }
  s.validate();
  return s;
}

BuildingSpec readBuildingSpec(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw FileError(path, "cannot open building spec");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw FileError(path, std::string("invalid JSON: ") + e.what(), atByte(e.byte));
  }
  try {
    return buildingSpecFromJson(j);
  } catch (const InputError& e) {
    throw FileError(path, e.what());
  }
}

}  // namespace plumb
