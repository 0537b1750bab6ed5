#pragma once
// Labelled markers of the manual alignment's point pairs in the 3D view (issue 17): each source
// pick drawn where the source is now (it follows the applied transform) in orange with "S<n>",
// each target pick in cyan with "T<n>"; pairs left out of the fit are drawn grey.
#include <QStringList>

#include <Eigen/Core>

#include <vector>

#include <vtkNew.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

class vtkActor;
class vtkBillboardTextActor3D;

namespace plumb::ui {

struct PairMarker {
  Eigen::Vector3d world;  ///< where it is drawn
  QString label;          ///< "S1", "T1", ...
  bool source = true;
  bool used = true;
};

class PairMarkers {
 public:
  explicit PairMarkers(vtkRenderer* renderer);
  ~PairMarkers();
  PairMarkers(const PairMarkers&) = delete;
  PairMarkers& operator=(const PairMarkers&) = delete;

  /// Replaces the markers; `origin` is the scene's render origin (render = world - origin).
  void show(const std::vector<PairMarker>& markers, const Eigen::Vector3d& origin);
  /// The labels drawn, in order.
  QStringList labels() const;

 private:
  vtkSmartPointer<vtkRenderer> renderer_;  ///< held: the view may be destroyed before the dock
  vtkNew<vtkActor> points_;
  std::vector<vtkSmartPointer<vtkBillboardTextActor3D>> texts_;
};

}  // namespace plumb::ui
