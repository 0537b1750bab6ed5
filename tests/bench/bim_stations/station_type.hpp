#pragma once
// The station types of issue 14's per-station-type acceptance (docs/BIM_STATIONS.md).
#include <string>
#include <vector>

namespace plumb::bimst {

enum class StationType { Room, Corridor, Hall, Stair, Other };

/// "room", "corridor", "hall", "stair", "other".
const char* typeName(StationType t);
/// The types a run can ask for (every type but Other).
std::vector<StationType> benchTypes();
/// Parses "room,corridor,...". Throws std::invalid_argument naming a bad type.
std::vector<StationType> parseTypes(const std::string& list);
/// Splits "a,b,c" at commas (no empty items).
std::vector<std::string> splitList(const std::string& list);

}  // namespace plumb::bimst
