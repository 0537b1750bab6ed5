#pragma once
// The colour scale legend of the distance colouring (vtkScalarBarActor over the distance ramp,
// or the blue-white-red ramp from -max to +max for signed distances).
#include <QString>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

class vtkLookupTable;
class vtkRenderer;
class vtkScalarBarActor;

namespace plumb::ui {

struct DistanceScale;

class DistanceLegend {
 public:
  explicit DistanceLegend(vtkRenderer* renderer);
  ~DistanceLegend();
  void show(const DistanceScale& scale, const QString& title);
  void hide();
  bool visible() const;

 private:
  vtkSmartPointer<vtkRenderer> renderer_;  ///< kept alive: the view may go first
  vtkNew<vtkLookupTable> table_;
  vtkNew<vtkScalarBarActor> bar_;
};

}  // namespace plumb::ui
