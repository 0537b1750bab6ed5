#include "station_type.hpp"

#include <stdexcept>

namespace plumb::bimst {

const char* typeName(StationType t) {
  switch (t) {
    case StationType::Room: return "room";
    case StationType::Corridor: return "corridor";
    case StationType::Hall: return "hall";
    case StationType::Stair: return "stair";
    case StationType::Other: break;
  }
  return "other";
}

std::vector<StationType> benchTypes() {
  return {StationType::Room, StationType::Corridor, StationType::Hall, StationType::Stair};
}

std::vector<std::string> splitList(const std::string& list) {
  std::vector<std::string> out;
  for (std::size_t s = 0, e; s <= list.size(); s = e + 1) {
    e = std::min(list.find(',', s), list.size());
    if (e > s) out.push_back(list.substr(s, e - s));
  }
  return out;
}

std::vector<StationType> parseTypes(const std::string& list) {
  std::vector<StationType> out;
  for (const std::string& name : splitList(list)) {
    bool known = false;
    for (StationType t : benchTypes())
      if (name == typeName(t)) {
        out.push_back(t);
        known = true;
      }
    if (!known) throw std::invalid_argument("unknown station type '" + name + "' (room, corridor, hall, stair)");
  }
  return out;
}

}  // namespace plumb::bimst
