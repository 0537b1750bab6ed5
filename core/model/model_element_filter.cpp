#include "model/model_element_filter.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

#include "common/error.hpp"

namespace plumb {
namespace {

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// The element index of every triangle, or none when the model has no element tags.
bool tagged(const BimModel& m) {
  return !m.elements.empty() && m.triangle_element.size() == m.mesh.triangles.size();
}

/// Which elements are on the filter's storeys (all when it names none); throws when a storey
/// names none of the model's.
std::vector<bool> onStoreys(const BimModel& model, const ModelElementFilter& filter) {
  std::vector<bool> on(model.elements.size(), filter.storeys.empty());
  if (filter.storeys.empty()) return on;
  std::set<std::string> present;
  for (const auto& e : model.elements)
    if (!e.storey.empty()) present.insert(e.storey);
  for (const auto& s : filter.storeys) {
    bool found = false;
    for (std::size_t i = 0; i < model.elements.size(); ++i)
      if ((!model.elements[i].storey.empty() && lower(model.elements[i].storey) == lower(s)) ||
          (!model.elements[i].storey_guid.empty() && model.elements[i].storey_guid == s))
        on[i] = found = true;
    if (!found)
      throw InputError(model.source.string() + ": no element on a storey named '" + s + "' (" +
                       (present.empty() ? std::string("the model names no storeys")
                                        : "the model's storeys: " + joinNameList({present.begin(), present.end()})) + ")");
  }
  return on;
}

/// Which elements the filter keeps; throws when a requested type, id or storey names nothing.
std::vector<bool> keptElements(const BimModel& model, const ModelElementFilter& filter) {
  std::set<std::string> present;
  for (const auto& e : model.elements)
    if (!e.type.empty()) present.insert(e.type);
  std::set<std::string> wanted_types;
  for (const auto& t : filter.types) {
    const auto it = std::find_if(present.begin(), present.end(),
                                 [&](const std::string& p) { return lower(p) == lower(t); });
    if (it == present.end())
      throw InputError(model.source.string() + ": no element of type '" + t + "' (the model has " +
                       (present.empty() ? std::string("no typed elements")
                                        : joinNameList({present.begin(), present.end()})) + ")");
    wanted_types.insert(*it);
  }
  std::vector<bool> keep(model.elements.size(), false);
  for (const auto& id : filter.elements) {
    bool found = false;
    for (std::size_t i = 0; i < model.elements.size(); ++i)
      if (model.elements[i].guid == id || model.elements[i].name == id) keep[i] = found = true;
    if (!found) throw InputError(model.source.string() + ": no element has the GlobalId or name '" + id + "'");
  }
  for (std::size_t i = 0; i < model.elements.size(); ++i)
    if (wanted_types.count(model.elements[i].type)) keep[i] = true;
  const bool by_identity = !filter.types.empty() || !filter.elements.empty();
  const std::vector<bool> on = onStoreys(model, filter);
  for (std::size_t i = 0; i < keep.size(); ++i) keep[i] = (keep[i] || !by_identity) && on[i];
  return keep;
}

/// The triangles of kept elements, with their vertices renumbered; elements keep their indices.
BimModel keepTriangles(const BimModel& model, const std::vector<bool>& keep) {
  BimModel out;
  out.source = model.source;
  out.format = model.format;
  out.elements = model.elements;
  const TriangleMesh& in = model.mesh;
  const bool normals = in.vertex_normals.size() == in.vertices.size();
  const bool colors = in.vertex_colors.size() == in.vertices.size();
  std::vector<std::uint32_t> renumbered(in.vertices.size(), UINT32_MAX);
  for (std::size_t t = 0; t < in.triangles.size(); ++t) {
    const std::uint32_t e = model.triangle_element[t];
    if (e >= keep.size() || !keep[e]) continue;
    std::array<std::uint32_t, 3> tri{};
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = in.triangles[t][k];
      if (renumbered[v] == UINT32_MAX) {
        renumbered[v] = static_cast<std::uint32_t>(out.mesh.vertices.size());
        out.mesh.vertices.push_back(in.vertices[v]);
        if (normals) out.mesh.vertex_normals.push_back(in.vertex_normals[v]);
        if (colors) out.mesh.vertex_colors.push_back(in.vertex_colors[v]);
      }
      tri[k] = renumbered[v];
    }
    out.mesh.triangles.push_back(tri);
    out.triangle_element.push_back(model.triangle_element[t]);
  }
  return out;
}

}  // namespace

std::string ModelElementFilter::describe() const {
  if (empty()) return "all elements";
  std::string out;
  if (!types.empty()) out = "types " + joinNameList(types);
  if (!elements.empty()) out += (out.empty() ? "" : "; ") + std::string("elements ") + joinNameList(elements);
  if (!storeys.empty()) out += (out.empty() ? "" : "; ") + std::string("storeys ") + joinNameList(storeys);
  return out;
}

const std::vector<ModelElementOption>& modelElementOptions() {
  static const std::vector<ModelElementOption> options{
      {"model-elements", "Model element types",
       "Register onto these IFC types of a model target only, comma-separated "
       "(IfcColumn,IfcSlab); the report says what the registration rests on",
       &ModelElementFilter::types},
      {"model-element-ids", "Model elements (GlobalId or name)",
       "Register onto these elements of a model target only (IFC GlobalId or element name, "
       "comma-separated); with --model-elements, either one keeps an element",
       &ModelElementFilter::elements},
      {"model-storeys", "Model storeys",
       "Register onto the elements of these storeys of a model target only (IfcBuildingStorey "
       "names, comma-separated); with --model-elements or --model-element-ids, only those "
       "elements on these storeys",
       &ModelElementFilter::storeys},
  };
  return options;
}

std::string joinNameList(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

std::vector<std::string> splitNameList(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(',', start), text.size());
    std::string item = text.substr(start, end - start);
    item.erase(0, item.find_first_not_of(" \t"));
    item.erase(item.find_last_not_of(" \t") + 1);
    if (!item.empty()) out.push_back(item);
    start = end + 1;
  }
  return out;
}

std::vector<ElementTypeUse> elementTypeUse(const BimModel& model) {
  std::map<std::string, ElementTypeUse> by_type;
  if (!tagged(model)) {
    if (!model.mesh.triangles.empty()) by_type[""] = {"", 0, model.mesh.triangles.size()};
  } else {
    std::vector<bool> counted(model.elements.size(), false);
    for (const std::uint32_t e : model.triangle_element) {
      if (e >= model.elements.size()) {
        ++by_type[""].triangles;
        continue;
      }
      ElementTypeUse& u = by_type[model.elements[e].type];
      u.type = model.elements[e].type;
      ++u.triangles;
      if (!counted[e]) ++u.elements;
      counted[e] = true;
    }
  }
  std::vector<ElementTypeUse> out;
  for (auto& [type, use] : by_type) out.push_back(use);
  return out;
}

std::string selectionSummary(const ModelSelection& s) {
  std::size_t elements = 0, triangles = 0;
  for (const auto& u : s.used) {
    elements += u.elements;
    triangles += u.triangles;
  }
  return s.filter.describe() + ": " + std::to_string(elements) + " of " + std::to_string(s.elements_in_model) +
         " elements, " + std::to_string(triangles) + " of " + std::to_string(s.triangles_in_model) + " triangles";
}

FilteredModel filterModelElements(const BimModel& model, const ModelElementFilter& filter) {
  FilteredModel out;
  out.selection.filter = filter;
  const std::vector<ElementTypeUse> all = elementTypeUse(model);
  for (const auto& u : all) {
    out.selection.elements_in_model += u.elements;
    out.selection.triangles_in_model += u.triangles;
  }
  if (filter.empty()) {
    out.model = model;
  } else {
    if (!tagged(model))
      throw InputError(model.source.string() + ": the model has no element types or ids, so it cannot "
                       "be restricted to " + filter.describe());
    out.model = keepTriangles(model, keptElements(model, filter));
    if (out.model.mesh.triangles.empty())
      throw InputError(model.source.string() + ": the element filter (" + filter.describe() +
                       ") keeps no triangle: nothing to register onto");
  }
  out.selection.used = elementTypeUse(out.model);
  return out;
}

}  // namespace plumb
