#include "ui/project/layer_style_json.hpp"

#include <algorithm>

#include "common/error.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scene.hpp"

namespace plumb::ui {

using nlohmann::json;

namespace {

json pointStyleToJson(const DatasetLayer& layer) {
  const PointStyle& s = layer.style();
  const auto mode = static_cast<std::size_t>(layer.modeWithoutDistances());
  return {{"colour", pointColorModeNames().at(mode)},
          {"scalar-field", s.scalar_field},
          {"point-size", s.point_size}};
}

PointColorMode modeNamed(const std::string& name) {
  const auto& names = pointColorModeNames();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end() || name == "Distance")
    throw InputError("style.colour: unknown colour mode '" + name + "'");
  return static_cast<PointColorMode>(it - names.begin());
}

template <class T>
T number(const json& j, const char* key, T fallback) {
  if (!j.contains(key)) return fallback;
  if (!j.at(key).is_number()) throw InputError(std::string("style.") + key + " must be a number");
  return j.at(key).get<T>();
}

}  // namespace

json styleToJson(const Layer& layer) {
  if (layer.kind() == LayerKind::Dataset)
    return pointStyleToJson(static_cast<const DatasetLayer&>(layer));
  if (layer.kind() == LayerKind::Model) {
    const MeshStyle& s = static_cast<const ModelLayer&>(layer).style();
    return {{"edges", s.edges}, {"opacity", s.opacity}};
  }
  return nullptr;
}

SavedStyle styleFromJson(const json& j) {
  if (!j.is_object()) throw InputError("style must be an object");
  SavedStyle out;
  if (j.contains("colour") || j.contains("point-size") || j.contains("scalar-field")) {
    PointStyle p;
    if (j.contains("colour")) {
      if (!j.at("colour").is_string()) throw InputError("style.colour must be a string");
      p.mode = modeNamed(j.at("colour").get<std::string>());
    }
    if (j.contains("scalar-field")) {
      if (!j.at("scalar-field").is_string()) throw InputError("style.scalar-field must be a string");
      p.scalar_field = j.at("scalar-field").get<std::string>();
    }
    p.point_size = number(j, "point-size", p.point_size);
    out.points = p;
  }
  if (j.contains("edges") || j.contains("opacity")) {
    MeshStyle m;
    if (j.contains("edges")) {
      if (!j.at("edges").is_boolean()) throw InputError("style.edges must be true or false");
      m.edges = j.at("edges").get<bool>();
    }
    m.opacity = std::clamp(number(j, "opacity", m.opacity), 0.0, 1.0);
    out.mesh = m;
  }
  return out;
}

void applySavedStyle(Scene& scene, Layer& layer, const SavedStyle& style) {
  if (layer.kind() == LayerKind::Dataset && style.points) {
    scene.requestStyle(static_cast<DatasetLayer&>(layer), *style.points);
  } else if (layer.kind() == LayerKind::Model && style.mesh) {
    static_cast<ModelLayer&>(layer).setStyle(*style.mesh);
    scene.layerChanged(&layer);
  }
}

}  // namespace plumb::ui
