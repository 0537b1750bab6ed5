// IFC names: node names as assimp writes them ("<IfcType>_<Name>_<GlobalId>"), IFC types as
// Plumb reports them, the schema a file declares (built into plumb_io_mesh and into the
// plumb-import helper, which names the elements it sends).
#include <algorithm>
#include <cctype>
#include <fstream>

#include "io/mesh/mesh_io.hpp"

namespace plumb {

BimElement elementFromIfcNodeName(const std::string& node_name) {
  BimElement e;
  if (node_name.rfind("Ifc", 0) != 0) {
    e.name = node_name;
    return e;
  }
  const auto first = node_name.find('_');
  e.type = node_name.substr(0, first);
  std::string rest = first == std::string::npos ? "" : node_name.substr(first + 1);
  // GlobalId: 22 characters of IFC's base-64 alphabet at the end, after an underscore.
  if (rest.size() >= 23 && rest[rest.size() - 23] == '_') {
    e.guid = rest.substr(rest.size() - 22);
    rest = rest.substr(0, rest.size() - 23);
  } else if (rest.size() == 22) {
    e.guid = rest;
    rest.clear();
  }
  e.name = rest;
  e.type = ifcBaseType(e.type);
  return e;
}

bool looksLikeIfcNodeName(const std::string& node_name) {
  const std::string type = node_name.substr(0, node_name.find('_'));
  if (type.size() < 4 || type.rfind("Ifc", 0) != 0 || !std::isupper(static_cast<unsigned char>(type[3])))
    return false;
  return std::all_of(type.begin(), type.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)); });
}

std::string ifcBaseType(std::string type) {
  for (const char* suffix : {"StandardCase", "ElementedCase"}) {
    const std::string s(suffix);
    if (type.size() > s.size() && type.compare(type.size() - s.size(), s.size(), s) == 0)
      type.erase(type.size() - s.size());
  }
  return type;
}

std::string ifcFileSchema(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::string line;
  for (int i = 0; i < 200 && std::getline(in, line); ++i) {
    const auto k = line.find("FILE_SCHEMA");
    if (k == std::string::npos) continue;
    const auto a = line.find('\'', k);
    const auto b = a == std::string::npos ? a : line.find('\'', a + 1);
    if (b != std::string::npos) return line.substr(a + 1, b - a - 1);
  }
  return "";
}

}  // namespace plumb
