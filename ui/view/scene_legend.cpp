#include "ui/view/scene_legend.hpp"

#include <vtkCellArray.h>
#include <vtkLegendBoxActor.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty2D.h>
#include <vtkRenderer.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <utility>

#include "ui/layers/color_ramp.hpp"
#include "ui/layers/dataset_layer.hpp"
#include "ui/layers/scan_layer.hpp"
#include "ui/layers/scene.hpp"

namespace plumb::ui {

namespace {

/// Height of one entry and of the whole box at most (fractions of the view's height).
constexpr double kEntryHeight = 0.045;
constexpr double kMaxHeight = 0.6;

void appendEntries(const DatasetLayer& d, std::vector<LegendEntry>& out) {
  if (d.style().mode == PointColorMode::Dataset) {
    out.push_back({d.name(), d.datasetColour()});
    return;
  }
  if (d.style().mode != PointColorMode::Scan) return;
  const auto scans = d.scans();
  for (const ScanLayer* s : scans) {
    if (!s->effectivelyVisible()) continue;
    const QString label = scans.size() > 1 ? d.name() + ": " + s->name() : d.name();
    out.push_back({label, categoryColor(s->colourIndex())});
  }
}

bool sameEntries(const std::vector<LegendEntry>& a, const std::vector<LegendEntry>& b) {
  return std::equal(a.begin(), a.end(), b.begin(), b.end(), [](const LegendEntry& x, const LegendEntry& y) {
    return x.label == y.label && x.colour == y.colour;
  });
}

}  // namespace

std::vector<LegendEntry> sceneLegendEntries(const Scene& scene) {
  std::vector<LegendEntry> out;
  for (const auto& layer : scene.layers())
    if (layer->kind() == LayerKind::Dataset && layer->effectivelyVisible())
      appendEntries(static_cast<const DatasetLayer&>(*layer), out);
  return out;
}

SceneLegend::SceneLegend(Scene& scene, vtkRenderer* renderer, QObject* parent)
    : QObject(parent), scene_(scene), renderer_(renderer) {
  vtkNew<vtkPoints> corners;
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}) corners->InsertNextPoint(x, y, 0.0);
  vtkNew<vtkCellArray> square;
  const vtkIdType ids[4] = {0, 1, 2, 3};
  square->InsertNextCell(4, ids);
  swatch_->SetPoints(corners);
  swatch_->SetPolys(square);
  box_->SetBorder(true);
  box_->SetPadding(4);
  box_->SetUseBackground(true);
  box_->SetBackgroundColor(0.08, 0.08, 0.1);
  box_->SetBackgroundOpacity(0.7);
  box_->GetEntryTextProperty()->SetColor(1.0, 1.0, 1.0);
  box_->GetEntryTextProperty()->SetFontSize(14);
  box_->SetVisibility(false);
  renderer_->AddViewProp(box_);
  connect(&scene, &Scene::layersChanged, this, &SceneLegend::update);
  connect(&scene, &Scene::renderNeeded, this, &SceneLegend::update);
}

SceneLegend::~SceneLegend() { renderer_->RemoveViewProp(box_); }

bool SceneLegend::visible() const { return box_->GetVisibility() != 0; }

void SceneLegend::update() {
  std::vector<LegendEntry> entries = sceneLegendEntries(scene_);
  if (sameEntries(entries, entries_)) return;
  entries_ = std::move(entries);
  const int n = static_cast<int>(entries_.size());
  box_->SetNumberOfEntries(n);
  for (int i = 0; i < n; ++i) {
    const LegendEntry& e = entries_[std::size_t(i)];
    double colour[3] = {e.colour[0] / 255.0, e.colour[1] / 255.0, e.colour[2] / 255.0};
    box_->SetEntry(i, swatch_.Get(), e.label.toUtf8().constData(), colour);
  }
  const double height = std::min(kMaxHeight, kEntryHeight * n);
  box_->SetPosition(0.01, 0.99 - height);
  box_->SetPosition2(0.24, height);
  box_->SetVisibility(n > 0);
}

}  // namespace plumb::ui
