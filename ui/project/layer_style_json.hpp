#pragma once
// A layer's display style as a project keeps it: a point dataset's colour mode, scalar field
// and point size ({"colour": "Elevation", "scalar-field": "", "point-size": 2}), a model's
// edges and opacity ({"edges": true, "opacity": 0.5}). The Distance colour mode is not kept
// (the distances are not saved): a layer coloured by distance keeps the mode it had before.
#include <nlohmann/json.hpp>

#include <optional>

#include "ui/layers/model_layer.hpp"
#include "ui/layers/point_style.hpp"

namespace plumb::ui {

class Layer;
class Scene;

struct SavedStyle {
  std::optional<PointStyle> points;
  std::optional<MeshStyle> mesh;
};

/// The style of a dataset or model layer; null for other layers.
nlohmann::json styleToJson(const Layer& layer);
/// Reads what styleToJson wrote. Throws InputError naming the bad key.
SavedStyle styleFromJson(const nlohmann::json& j);
/// Gives `layer` the saved style of its kind (a dataset recolours in the background).
void applySavedStyle(Scene& scene, Layer& layer, const SavedStyle& style);

}  // namespace plumb::ui
