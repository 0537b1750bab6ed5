#pragma once
// One scan of a dataset drawn as points by two actors: a "moving" subset shown while the camera
// moves and a "still" subset shown otherwise (the whole scan by default: full detail). Their
// sizes follow the view's two adaptive budgets (LodController). The scan's points are stored
// once in a random order (PermutedPoints), so a subset is a prefix of that order: changing a
// size makes a new poly data aliasing the prefix (no copy, sort or gather), and switching
// between moving and still only toggles the actors' visibility.
#include <Eigen/Core>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <cstdint>
#include <memory>
#include <vector>

#include "model/dataset.hpp"
#include "ui/layers/layer.hpp"
#include "ui/layers/point_coloring.hpp"
#include "ui/layers/point_geometry.hpp"
#include "ui/layers/prepared_dataset.hpp"
#include "ui/layers/scan_colors.hpp"

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;

namespace plumb::ui {

class ScanLayer : public ActorLayer {
 public:
  /// `data` must hold scan `scan_index`; `lod_points` is the moving subset's size. The still
  /// subset starts as the whole scan. `prepared` holds the scan's points in their random order
  /// (built off the UI thread, see prepareDataset): the layer's VTK arrays wrap its buffers.
  ScanLayer(std::shared_ptr<const Dataset> data, std::size_t scan_index,
            const Eigen::Vector3d& origin, std::size_t lod_points, PreparedScan prepared);
  ~ScanLayer() override;

  const Scan& scan() const { return data_->scans[scan_index_]; }
  std::size_t scanIndex() const { return scan_index_; }
  /// The Scan colour mode's colour (categoryColor of this index): its number in the scene.
  std::size_t colourIndex() const { return colour_index_; }
  /// The scan's Scan colour index and its dataset's Dataset colour index.
  void setColourIndices(std::size_t scan, std::size_t dataset) {
    colour_index_ = scan;
    dataset_colour_index_ = dataset;
  }
  /// Size of the moving subset (drawn while the camera moves).
  std::size_t lodPointCount() const { return moving_count_; }
  /// Changes the moving subset's size (clamped to [1, size]).
  void setLodPointCount(std::size_t points);
  /// Size of the still subset (the scan's size: full detail).
  std::size_t stillPointCount() const { return still_count_; }
  /// Changes the still subset's size (clamped to [1, size]; >= size: full detail).
  void setStillPointCount(std::size_t points);
  /// Points drawn now (moving or still subset, 0 when hidden).
  std::size_t drawnPointCount() const;
  /// Cloud index of each vertex of either actor's poly data (both are prefixes of one random
  /// order): what a picked vertex id means. Computed on demand, O(points).
  std::vector<std::uint32_t> originalIndices() const { return points_.originalIndices(); }

  /// Dataset frame -> world (a registration result; identity by default).
  void setDatasetTransform(const RigidTransform& t);
  /// Swaps in a dataset holding the same points (e.g. with sensor origins added): the display
  /// data stays. Throws std::invalid_argument if this scan's point count differs.
  void replaceData(std::shared_ptr<const Dataset> data);
  /// Recolours both representations now (on this thread: colorJob + applyColors). z range is
  /// world elevation for the Elevation mode.
  void setStyle(const PointStyle& style, double z_min, double z_max);
  /// What setStyle computes, as a thread-safe job (for a background task).
  ScanColorJob colorJob(const PointStyle& style, double z_min, double z_max) const;
  /// Shows colours computed by colorJob (random order; ignored when the size differs): swaps
  /// the buffer and re-points both actors' colour arrays at it (only colours re-upload).
  void applyColors(std::vector<Rgba> permuted);
  void setPointSize(double pixels);
  /// Per-point distances (Distance colour mode) drawn on `scale`; NaN drawn grey.
  void setDistances(std::vector<float> distances, const DistanceScale& scale);
  /// The distances set (null before any).
  std::shared_ptr<const std::vector<float>> distances() const { return distances_; }
  /// Scan points -> world.
  Eigen::Matrix4d localToWorld() const;

  std::vector<vtkProp*> props() const override;
  Bounds bounds() const override;
  std::vector<PropertyRow> describe() const override;

 protected:
  void updateActors() override;

 private:
  bool usesMoving() const;
  /// Points `count`/`poly` of one actor at the prefix of `points` points (clamped).
  void setPrefix(std::size_t& count, vtkSmartPointer<vtkPolyData>& poly,
                 vtkPolyDataMapper* mapper, std::size_t points);
  std::shared_ptr<const Dataset> data_;
  std::size_t scan_index_;
  std::size_t colour_index_ = scan_index_;
  std::size_t dataset_colour_index_ = 0;
  Eigen::Vector3d origin_;
  RigidTransform dataset_transform_;
  PermutedPoints points_;  ///< the scan's points in random order (positions, colours)
  Bounds local_bounds_;  ///< of the scan's local (offset-relative) positions
  std::size_t still_count_ = 0;
  std::size_t moving_count_ = 0;
  vtkSmartPointer<vtkPolyData> still_poly_;   ///< prefix [0, still_count_)
  vtkSmartPointer<vtkPolyData> moving_poly_;  ///< prefix [0, moving_count_)
  vtkNew<vtkPolyDataMapper> still_mapper_;
  vtkNew<vtkPolyDataMapper> moving_mapper_;
  vtkNew<vtkActor> still_actor_;
  vtkNew<vtkActor> moving_actor_;
  std::shared_ptr<const std::vector<float>> distances_;  ///< shared with colour jobs
  DistanceScale distance_scale_;
};

}  // namespace plumb::ui
