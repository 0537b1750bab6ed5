#include "ui/registration/point_picking.hpp"

#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkRenderer.h>

#include <cmath>
#include <limits>

#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/layers/scene.hpp"

namespace plumb::ui {

namespace {

Eigen::Vector3d displayToRender(vtkRenderer* r, double x, double y, double z) {
  r->SetDisplayPoint(x, y, z);
  r->DisplayToWorld();
  const double* w = r->GetWorldPoint();
  return Eigen::Vector3d(w[0], w[1], w[2]) / (w[3] != 0.0 ? w[3] : 1.0);
}

}  // namespace

std::optional<Eigen::Vector3d> pickLayerPoint(vtkRenderer* renderer, const Scene& scene,
                                              const Layer& layer, int x, int y,
                                              double tolerance_deg) {
  const Eigen::Vector3d origin = scene.origin();
  if (layer.kind() == LayerKind::Model) {
    vtkNew<vtkCellPicker> picker;
    picker->SetTolerance(0.002);
    picker->PickFromListOn();
    for (vtkProp* p : layer.props()) picker->AddPickList(p);
    if (!picker->Pick(x, y, 0.0, renderer)) return std::nullopt;
    const double* p = picker->GetPickPosition();
    return Eigen::Vector3d(p[0], p[1], p[2]) + origin;
  }
  if (layer.kind() != LayerKind::Dataset) return std::nullopt;
  // The ray in world coordinates.
  const Eigen::Vector3d a = displayToRender(renderer, x, y, 0.0) + origin;
  const Eigen::Vector3d b = displayToRender(renderer, x, y, 1.0) + origin;
  const Eigen::Vector3d dir = (b - a).normalized();
  const double tol = std::tan(tolerance_deg * M_PI / 180.0);
  // The front-most point within the angular tolerance of the ray.
  std::optional<Eigen::Vector3d> best;
  double best_along = std::numeric_limits<double>::infinity();
  for (const ScanLayer* scan : static_cast<const DatasetLayer&>(layer).scans()) {
    if (!scan->effectivelyVisible()) continue;
    const Eigen::Matrix4d m = scan->localToWorld();
    const Eigen::Matrix4d inv = m.inverse();  // rigid: distances along the ray are preserved
    const Eigen::Vector3f fa = (inv * a.homogeneous()).head<3>().cast<float>();
    const Eigen::Vector3f fd = (inv.topLeftCorner<3, 3>() * dir).normalized().cast<float>();
    const auto& pts = scan->scan().cloud.positions;
    const float ftol = float(tol);
    std::size_t best_i = pts.size();
    float scan_best = float(best_along);
    for (std::size_t i = 0; i < pts.size(); ++i) {
      const Eigen::Vector3f v = pts[i] - fa;
      const float along = v.dot(fd);
      if (!(along > 0.0f) || along >= scan_best) continue;
      if ((v - along * fd).norm() <= ftol * along) {
        scan_best = along;
        best_i = i;
      }
    }
    if (best_i < pts.size()) {
      best_along = scan_best;
      best = (m * pts[best_i].cast<double>().homogeneous()).head<3>();
    }
  }
  return best;
}

std::optional<ScenePick> pickScenePoint(vtkRenderer* renderer, const Scene& scene, int x, int y,
                                        double tolerance_deg) {
  double cam[3];
  renderer->GetActiveCamera()->GetPosition(cam);
  const Eigen::Vector3d eye = Eigen::Vector3d(cam[0], cam[1], cam[2]) + scene.origin();
  std::optional<ScenePick> best;
  for (const auto& l : scene.layers()) {
    if (!l->effectivelyVisible() || (l->kind() != LayerKind::Dataset && l->kind() != LayerKind::Model)) continue;
    const auto p = pickLayerPoint(renderer, scene, *l, x, y, tolerance_deg);
    if (p && (!best || (*p - eye).norm() < (best->world - eye).norm())) best = ScenePick{*p, l.get()};
  }
  return best;
}

}  // namespace plumb::ui
