#include "ui/view/distance_legend.hpp"

#include <vtkLookupTable.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextProperty.h>

#include "ui/layers/point_coloring.hpp"

namespace plumb::ui {

DistanceLegend::DistanceLegend(vtkRenderer* renderer) : renderer_(renderer) {
  bar_->SetLookupTable(table_);
  bar_->SetNumberOfLabels(5);
  bar_->SetLabelFormat("%.3f");
  bar_->SetPosition(0.88, 0.1);
  bar_->SetWidth(0.1);
  bar_->SetHeight(0.8);
  bar_->GetTitleTextProperty()->SetFontSize(14);
  bar_->GetLabelTextProperty()->SetFontSize(12);
  bar_->SetVisibility(false);
  renderer_->AddViewProp(bar_);
}

DistanceLegend::~DistanceLegend() { renderer_->RemoveViewProp(bar_); }

void DistanceLegend::show(const DistanceScale& scale, const QString& title) {
  constexpr int kColors = 64;
  table_->SetNumberOfTableValues(kColors);
  for (int i = 0; i < kColors; ++i) {
    const Rgb c = rampColor(scale.ramp(), (i + 0.5) / kColors);
    table_->SetTableValue(i, c[0] / 255.0, c[1] / 255.0, c[2] / 255.0, 1.0);
  }
  table_->SetRange(scale.lo(), scale.max);
  table_->Build();
  bar_->SetTitle(title.toUtf8().constData());
  bar_->SetVisibility(true);
}

void DistanceLegend::hide() { bar_->SetVisibility(false); }
bool DistanceLegend::visible() const { return bar_->GetVisibility() != 0; }

}  // namespace plumb::ui
