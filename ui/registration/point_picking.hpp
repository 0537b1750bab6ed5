#pragma once
// Picking a point of a layer under the mouse for manual alignment: the view ray through the
// pixel, then the point of the dataset closest to the ray in angle (points), or the picked
// position on a model's surface (VTK cell picker).
#include <Eigen/Core>

#include <optional>

class vtkRenderer;

namespace plumb::ui {

class Layer;
class Scene;

/// World position of the point of `layer` (dataset or model) under display position (x, y)
/// (VTK convention: y up, device pixels): the front-most point within about a pixel of the
/// cursor, else the point nearest the ray within `tolerance_deg` of it (seen from the eye; in a
/// parallel view as many pixels as in a perspective one): clicks beside a sparse point snap to
/// it. nullopt if none.
std::optional<Eigen::Vector3d> pickLayerPoint(vtkRenderer* renderer, const Scene& scene,
                                              const Layer& layer, int x, int y,
                                              double tolerance_deg = 0.5);

/// A point picked in the view and the layer it belongs to.
struct ScenePick {
  Eigen::Vector3d world;
  const Layer* layer = nullptr;
};

/// The front-most point of any visible dataset or model under display position (x, y), within
/// `tolerance_deg` of the view ray for points (about 13 px on an 800 px high view: no need to
/// hit a point exactly); nullopt if none.
std::optional<ScenePick> pickScenePoint(vtkRenderer* renderer, const Scene& scene, int x, int y,
                                        double tolerance_deg = 0.5);

}  // namespace plumb::ui
