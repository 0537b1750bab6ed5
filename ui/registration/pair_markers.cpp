#include "ui/registration/pair_markers.hpp"

#include <vtkActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCellArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>

namespace plumb::ui {

namespace {
struct Rgb {
  unsigned char r, g, b;
};
Rgb colourOf(const PairMarker& m) {
  if (!m.used) return {150, 150, 150};
  return m.source ? Rgb{255, 140, 0} : Rgb{0, 200, 255};
}
}  // namespace

PairMarkers::PairMarkers(vtkRenderer* renderer) : renderer_(renderer) {
  vtkNew<vtkPolyDataMapper> mapper;
  points_->SetMapper(mapper);
  points_->GetProperty()->SetPointSize(12.0f);
  points_->GetProperty()->SetRenderPointsAsSpheres(true);
  points_->PickableOff();
  points_->VisibilityOff();
  renderer_->AddActor(points_);
}

PairMarkers::~PairMarkers() {
  renderer_->RemoveActor(points_);
  for (auto& t : texts_) renderer_->RemoveActor(t);
}

void PairMarkers::show(const std::vector<PairMarker>& markers, const Eigen::Vector3d& origin) {
  for (auto& t : texts_) renderer_->RemoveActor(t);
  texts_.clear();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> verts;
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetNumberOfComponents(3);
  for (const PairMarker& m : markers) {
    const Eigen::Vector3d r = m.world - origin;
    verts->InsertNextCell(1);
    verts->InsertCellPoint(pts->InsertNextPoint(r.data()));
    const Rgb c = colourOf(m);
    colours->InsertNextTuple3(c.r, c.g, c.b);
    auto text = vtkSmartPointer<vtkBillboardTextActor3D>::New();
    text->SetInput(m.label.toUtf8().constData());
    text->SetPosition(r.x(), r.y(), r.z());
    text->SetDisplayOffset(8, 8);
    text->GetTextProperty()->SetFontSize(16);
    text->GetTextProperty()->SetBold(true);
    text->GetTextProperty()->SetColor(c.r / 255.0, c.g / 255.0, c.b / 255.0);
    text->PickableOff();
    renderer_->AddActor(text);
    texts_.push_back(text);
  }
  vtkNew<vtkPolyData> poly;
  poly->SetPoints(pts);
  poly->SetVerts(verts);
  poly->GetPointData()->SetScalars(colours);
  static_cast<vtkPolyDataMapper*>(points_->GetMapper())->SetInputData(poly);
  points_->SetVisibility(!markers.empty());
  if (!renderer_->HasViewProp(points_)) renderer_->AddActor(points_);  // a cleared scene removes props
}

QStringList PairMarkers::labels() const {
  QStringList out;
  for (const auto& t : texts_) out << QString::fromUtf8(t->GetInput());
  return out;
}

}  // namespace plumb::ui
