#pragma once
// Clicking in the 3D view as a user does, at the projection of a world point.
#include <QApplication>
#include <QPoint>
#include <QTest>

#include <vtkRenderer.h>

#include <Eigen/Core>

#include <cmath>

#include "ui/app_context.hpp"
#include "ui/layers/scene.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::test {

/// Widget position (logical pixels) of world point `world` in the current view.
inline QPoint projectToView(ui::AppContext& app, const Eigen::Vector3d& world) {
  vtkRenderer* r = app.view.renderer();
  const Eigen::Vector3d p = world - app.scene.origin();
  r->SetWorldPoint(p.x(), p.y(), p.z(), 1.0);
  r->WorldToDisplay();
  const double* d = r->GetDisplayPoint();
  const double dpr = app.view.devicePixelRatioF();
  const double device_h = std::floor(app.view.height() * dpr);
  return QPoint(static_cast<int>(std::lround(d[0] / dpr)),
                static_cast<int>(std::lround((device_h - 1.0 - d[1]) / dpr)));
}

/// A user's click (press + release, no drag) at widget position `p` of the view.
inline void clickView(ui::AppContext& app, QPoint p) {
  QTest::mouseClick(&app.view, Qt::LeftButton, Qt::NoModifier, p);
  QApplication::processEvents();
}

}  // namespace plumb::test
