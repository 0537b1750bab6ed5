#pragma once
// The scene legend: while datasets are coloured by dataset or by scan, a box in the view's
// top-left corner names every visible one with its colour. Drawn by VTK (vtkLegendBoxActor)
// so screenshots and exported pictures show it too. It follows the scene on its own: layers
// added, removed, hidden or recoloured.
#include <QObject>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <vector>

#include "ui/layers/layer.hpp"

class vtkLegendBoxActor;
class vtkPolyData;
class vtkRenderer;

namespace plumb::ui {

class Scene;

/// What tells the visible layers apart: each visible dataset drawn in the Dataset colour mode
/// (its name and colour), each visible scan of a dataset drawn in the Scan mode (the dataset's
/// name, with the scan's when it holds several). Empty when no dataset uses either mode.
std::vector<LegendEntry> sceneLegendEntries(const Scene& scene);

class SceneLegend : public QObject {
  Q_OBJECT
 public:
  SceneLegend(Scene& scene, vtkRenderer* renderer, QObject* parent = nullptr);
  ~SceneLegend() override;
  /// The entries shown (empty: the box is hidden).
  const std::vector<LegendEntry>& entries() const { return entries_; }
  bool visible() const;

 private:
  void update();
  Scene& scene_;
  vtkSmartPointer<vtkRenderer> renderer_;  ///< kept alive: the view may go first
  vtkNew<vtkLegendBoxActor> box_;
  vtkNew<vtkPolyData> swatch_;  ///< the filled square drawn before each name
  std::vector<LegendEntry> entries_;
};

}  // namespace plumb::ui
