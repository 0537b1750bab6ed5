#pragma once
// Manual fallback: pick at least 3 point pairs (a point of the source, then the same point on
// the target), align by least squares (core alignPointPairs) with the residual of every pair
// shown, then refine with ICP through the Registration dock. The alignment goes on the undo
// stack like any applied transform.
#include <QWidget>

#include <Eigen/Core>

#include <vector>

class QLabel;
class QPushButton;
class QTableWidget;

namespace plumb::ui {

struct AppContext;
class Layer;

class ManualAlignPanel : public QWidget {
  Q_OBJECT
 public:
  ManualAlignPanel(AppContext& app, QWidget* parent = nullptr);

  /// A pair: source point in the source's data frame, target point in world coordinates.
  void addPair(const Eigen::Vector3d& source_data, const Eigen::Vector3d& target_world);
  /// A pair from world positions as shown (source converted with its current transform).
  void addWorldPair(const Eigen::Vector3d& source_world, const Eigen::Vector3d& target_world);
  void clearPairs();
  int pairCount() const { return int(target_.size()); }
  /// Fits and applies the transform; false with a log message when it cannot.
  bool align();
  /// Starts an ICP refinement of the source from where it is now (Registration dock).
  bool refine();
  /// Residual of pair i after the last align(), metres.
  double residual(int i) const;
  bool picking() const;
  void setPicking(bool on);

 private:
  void onClicked(int x, int y);
  void refreshTable();
  AppContext& app_;
  std::vector<Eigen::Vector3d> source_;  ///< data frame of the source layer
  std::vector<Eigen::Vector3d> target_;  ///< world
  std::vector<double> residuals_;
  bool have_source_pick_ = false;  ///< a source point waits for its target point
  QTableWidget* table_;
  QLabel* status_;
  QPushButton* pick_;
  QPushButton* align_;
  QPushButton* refine_;
};

}  // namespace plumb::ui
