#include "ui/inspection/measure_tool.hpp"

#include <vtkActor.h>
#include <vtkLineSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include "ui/app_context.hpp"
#include "ui/layers/scene.hpp"
#include "ui/panels/properties_panel.hpp"
#include "ui/registration/pair_markers.hpp"
#include "ui/registration/point_picking.hpp"
#include "ui/view/vtk_view_widget.hpp"

namespace plumb::ui {

Measurement measure(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  return {a, b, d.norm(), d.head<2>().norm(), d.z()};
}

namespace {
QString metres(double v) { return QString::number(v, 'f', 3); }
}  // namespace

/// The line between the two measured points (render coordinates).
struct MeasureToolLine {
  explicit MeasureToolLine(vtkRenderer* renderer) : renderer_(renderer) {
    mapper_->SetInputConnection(line_->GetOutputPort());
    actor_->SetMapper(mapper_);
    actor_->GetProperty()->SetColor(1.0, 0.9, 0.1);
    actor_->GetProperty()->SetLineWidth(3.0f);
    actor_->PickableOff();
    actor_->VisibilityOff();
    renderer_->AddActor(actor_);
  }
  ~MeasureToolLine() { renderer_->RemoveActor(actor_); }
  void show(const Eigen::Vector3d* a, const Eigen::Vector3d* b, const Eigen::Vector3d& origin) {
    if (!renderer_->HasViewProp(actor_)) renderer_->AddActor(actor_);
    actor_->SetVisibility(a && b);
    if (!a || !b) return;
    const Eigen::Vector3d ra = *a - origin, rb = *b - origin;
    line_->SetPoint1(ra.data());
    line_->SetPoint2(rb.data());
  }

  vtkSmartPointer<vtkRenderer> renderer_;
  vtkNew<vtkLineSource> line_;
  vtkNew<vtkPolyDataMapper> mapper_;
  vtkNew<vtkActor> actor_;
};

std::vector<PropertyRow> pointRows(const Eigen::Vector3d& p, const QString& layer) {
  return {{"Layer", layer}, {"X (m)", metres(p.x())}, {"Y (m)", metres(p.y())}, {"Z (m)", metres(p.z())}};
}

std::vector<PropertyRow> measurementRows(const Measurement& m) {
  const Eigen::Vector3d d = m.b - m.a;
  return {{"Distance (m)", metres(m.slope)},
          {"Horizontal distance (m)", metres(m.horizontal)},
          {"Height difference (m)", metres(m.height)},
          {"dX (m)", metres(d.x())},
          {"dY (m)", metres(d.y())},
          {"dZ (m)", metres(d.z())},
          {"From", QString("%1, %2, %3").arg(metres(m.a.x()), metres(m.a.y()), metres(m.a.z()))},
          {"To", QString("%1, %2, %3").arg(metres(m.b.x()), metres(m.b.y()), metres(m.b.z()))}};
}

MeasureTool::MeasureTool(AppContext& app, QObject* parent)
    : QObject(parent),
      app_(app),
      marks_(std::make_unique<PairMarkers>(app.view.renderer())),
      line_(std::make_unique<MeasureToolLine>(app.view.renderer())) {
  connect(&app_.view, &VtkViewWidget::clicked, this, &MeasureTool::onClicked);
}

MeasureTool::~MeasureTool() = default;

void MeasureTool::setActive(bool on) {
  active_ = on;
  points_.clear();
  showMarks();
}

void MeasureTool::onClicked(int x, int y) {
  if (!active_) return;
  const auto hit = pickScenePoint(app_.view.renderer(), app_.scene, x, y);
  if (!hit) return;  // nothing near the cursor: the measurement stays as it is
  if (points_.size() == 2) points_.clear();
  points_.push_back(hit->world);
  if (points_.size() == 1) {
    app_.properties.showRows(tr("Point"), pointRows(hit->world, hit->layer->name()));
  } else {
    last_ = measure(points_[0], points_[1]);
    app_.properties.showRows(tr("Measurement"), measurementRows(*last_));
  }
  showMarks();
}

void MeasureTool::showMarks() {
  std::vector<PairMarker> marks;
  const char* names[] = {"A", "B"};
  for (std::size_t i = 0; i < points_.size(); ++i) marks.push_back({points_[i], names[i], i == 0, true});
  marks_->show(marks, app_.scene.origin());
  line_->show(points_.size() == 2 ? &points_[0] : nullptr, points_.size() == 2 ? &points_[1] : nullptr,
              app_.scene.origin());
  app_.view.requestRender();
}

}  // namespace plumb::ui
