#pragma once
// The visual check of a registration (the dock's "Colour by distance"): the source dataset
// coloured by its distance to the target, the colour legend in the view, the histogram and the
// statistics line. Cleared when it no longer describes what is shown (the source moved: undo,
// a new registration; a layer went away).
#include <QString>

#include <memory>

#include "ui/layers/layer.hpp"

class QLabel;
class vtkRenderer;

namespace plumb::ui {

class DatasetLayer;
class DistanceLegend;
class HistogramWidget;
class Scene;
struct LayerDistances;

class DistanceCheck {
 public:
  DistanceCheck(Scene& scene, vtkRenderer* renderer, HistogramWidget& histogram, QLabel& stats);
  ~DistanceCheck();

  /// Shows `distances` of `source` to `target`: signed ones on the blue-white-red ramp over
  /// [-max_distance, max_distance] (the legend and statistics say which side is which),
  /// unsigned ones on the distance ramp over [0, max_distance].
  void show(std::shared_ptr<const LayerDistances> distances, DatasetLayer& source,
            const Layer& target, double max_distance);
  /// Removes the colours, legend, histogram and statistics.
  void clear();
  /// Whether the check shown involves `layer` (as source or target).
  bool involves(const Layer* layer) const;
  std::shared_ptr<const LayerDistances> distances() const { return distances_; }
  bool legendVisible() const;
  /// The statistics line (empty when cleared).
  QString statistics() const;

 private:
  Scene& scene_;
  HistogramWidget& histogram_;
  QLabel& stats_;
  std::unique_ptr<DistanceLegend> legend_;
  std::shared_ptr<const LayerDistances> distances_;
  LayerRef source_, target_;
};

}  // namespace plumb::ui
