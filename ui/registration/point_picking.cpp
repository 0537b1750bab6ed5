#include "ui/registration/point_picking.hpp"

#include <vtkCamera.h>
#include <vtkCellPicker.h>
#include <vtkRenderer.h>

#include <cmath>
#include <limits>
#include <span>

#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/model_layer.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/layers/scene.hpp"
#include "ui/lod/detail_layer.hpp"

namespace plumb::ui {

namespace {

Eigen::Vector3d displayToRender(vtkRenderer* r, double x, double y, double z) {
  r->SetDisplayPoint(x, y, z);
  r->DisplayToWorld();
  const double* w = r->GetWorldPoint();
  return Eigen::Vector3d(w[0], w[1], w[2]) / (w[3] != 0.0 ? w[3] : 1.0);
}

/// The view ray under display (x, y), world coordinates, and how far from it a point may lie.
/// Perspective: the ray starts at the eye and the tolerance is a cone opening from there (not
/// from the near clipping plane, which VTK puts just in front of the data: a cone from there
/// closes on the nearest points and clicks beside them missed). Parallel: a cylinder as wide
/// as the cone of a perspective view of the same height.
struct PickRay {
  Eigen::Vector3d from, dir;
  double radius_per_metre = 0.0;  ///< perspective: radius = this * distance along the ray
  double radius = 0.0;            ///< parallel: a fixed radius, metres
};

PickRay pickRay(vtkRenderer* r, const Eigen::Vector3d& origin, int x, int y, double tolerance_deg) {
  vtkCamera* camera = r->GetActiveCamera();
  const Eigen::Vector3d near = displayToRender(r, x, y, 0.0) + origin;
  const Eigen::Vector3d far = displayToRender(r, x, y, 1.0) + origin;
  if (camera->GetParallelProjection())
    return {near, (far - near).normalized(), 0.0, 2.0 * camera->GetParallelScale() * tolerance_deg / camera->GetViewAngle()};
  double eye[3];
  camera->GetPosition(eye);
  const Eigen::Vector3d from = Eigen::Vector3d(eye[0], eye[1], eye[2]) + origin;
  return {from, (far - from).normalized(), std::tan(tolerance_deg * M_PI / 180.0), 0.0};
}

enum class PickRule { FrontMost, NearestToRay };

/// The best point on the ray so far: its score (pickRule) and world position.
struct RayBest {
  float score = std::numeric_limits<float>::infinity();
  std::optional<Eigen::Vector3d> world;
};

/// Updates `best` with the points `pts` (local coordinates, `m`: local -> world) within
/// `widen` times the ray's tolerance: the front-most one or the one nearest the ray (relative
/// to the tolerance there).
void scanPoints(std::span<const Eigen::Vector3f> pts, const Eigen::Matrix4d& m, const PickRay& ray,
                double widen, PickRule rule, RayBest& best) {
  const float per_metre = float(widen * ray.radius_per_metre), fixed = float(widen * ray.radius);
  const Eigen::Matrix4d inv = m.inverse();  // rigid: distances along the ray are preserved
  const Eigen::Vector3f fa = (inv * ray.from.homogeneous()).head<3>().cast<float>();
  const Eigen::Vector3f fd = (inv.topLeftCorner<3, 3>() * ray.dir).normalized().cast<float>();
  std::size_t best_i = pts.size();
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3f v = pts[i] - fa;
    const float along = v.dot(fd);
    if (!(along > 0.0f)) continue;
    const float off = (v - along * fd).norm() / (fixed + per_metre * along);
    const float score = rule == PickRule::FrontMost ? along : off;
    if (off <= 1.0f && score < best.score) best.score = score, best_i = i;
  }
  if (best_i < pts.size()) best.world = (m * pts[best_i].cast<double>().homogeneous()).head<3>();
}

/// Of the visible points of `layer` (its scans, and the full-resolution detail drawn over
/// them when the file is shown as a subsample) within `widen` times the ray's tolerance, in
/// world coordinates.
std::optional<Eigen::Vector3d> pointOnRay(const DatasetLayer& layer, const PickRay& ray, double widen, PickRule rule) {
  RayBest best;
  for (const ScanLayer* scan : layer.scans())
    if (scan->effectivelyVisible()) scanPoints(scan->scan().cloud.positions, scan->localToWorld(), ray, widen, rule, best);
  for (const auto& child : layer.children()) {
    if (child->kind() != LayerKind::Detail || !child->effectivelyVisible()) continue;
    const auto& detail = static_cast<const DetailLayer&>(*child);
    if (detail.drawnPointCount() > 0) scanPoints(detail.drawn().positions, detail.localToWorld(), ray, widen, rule, best);
  }
  return best.world;
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
  // A point under the cursor (about a pixel): the front-most one, so dense surfaces pick
  // what is seen. None: snap to the point nearest the ray within the whole tolerance.
  const auto& dataset = static_cast<const DatasetLayer&>(layer);
  const PickRay ray = pickRay(renderer, origin, x, y, tolerance_deg);
  if (auto under = pointOnRay(dataset, ray, 0.1, PickRule::FrontMost)) return under;
  return pointOnRay(dataset, ray, 1.0, PickRule::NearestToRay);
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
