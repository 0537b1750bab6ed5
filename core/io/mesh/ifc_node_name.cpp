// IFC node names as assimp writes them: "<IfcType>_<Name>_<GlobalId>" (built into plumb_io_mesh
// for tests and into the plumb-import helper, which names the elements it sends).
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
  for (const char* suffix : {"StandardCase", "ElementedCase"}) {
    const std::string s(suffix);
    if (e.type.size() > s.size() && e.type.compare(e.type.size() - s.size(), s.size(), s) == 0)
      e.type.erase(e.type.size() - s.size());
  }
  return e;
}

}  // namespace plumb
