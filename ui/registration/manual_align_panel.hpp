#pragma once
// Manual fallback: pick at least 3 point pairs (a point of the source, then the same point on
// the target), align by least squares (core alignPointPairs) with the residual of every pair
// shown, then refine with ICP through the Registration dock. The alignment goes on the undo
// stack like any applied transform.
// As surveyors use it: the pairs are labelled markers in the view (S1/T1, ...), each pair can be
// left out of the fit (a doubtful pick, or a check point: its residual is still shown), the fit
// and its RMS update live as pairs are picked or toggled, and "Levelled" turns the source about
// the vertical only (2 pairs suffice).
#include <QWidget>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <vector>

#include "registration/common/pair_alignment.hpp"

class QCheckBox;
class QLabel;
class QPushButton;
class QTableWidget;

namespace plumb::ui {

struct AppContext;
class Layer;
class PairMarkers;

class ManualAlignPanel : public QWidget {
  Q_OBJECT
 public:
  ManualAlignPanel(AppContext& app, QWidget* parent = nullptr);
  ~ManualAlignPanel() override;

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
  /// Residual of pair i in the current fit (live, or the last align()), metres; -1 when none.
  double residual(int i) const;
  /// The current fit (nullptr when the pairs do not make one: too few, collinear).
  const PairAlignmentResult* fit() const { return fit_ ? &*fit_ : nullptr; }
  /// Pair i in the fit (true) or a check point (false); the fit updates.
  void setPairUsed(int i, bool used);
  bool pairUsed(int i) const;
  /// Rotation about the vertical only; the fit updates.
  void setLevelled(bool levelled);
  /// The marker labels drawn in the view, in order (S1, T1, S2, ...).
  QStringList markerLabels() const;
  bool picking() const;
  void setPicking(bool on);

 private:
  void onClicked(int x, int y);
  /// Fits the complete pairs with the current choices (fit_, or the reason in the status).
  void updateFit();
  PairAlignmentParams fitParams() const;
  void refreshTable();
  void refreshMarkers();
  AppContext& app_;
  std::vector<Eigen::Vector3d> source_;  ///< data frame of the source layer
  std::vector<Eigen::Vector3d> target_;  ///< world
  std::vector<bool> used_;               ///< per pair: in the fit
  std::optional<PairAlignmentResult> fit_;
  bool have_source_pick_ = false;  ///< a source point waits for its target point
  bool filling_table_ = false;     ///< refreshTable is writing (ignore itemChanged)
  std::unique_ptr<PairMarkers> markers_;
  QTableWidget* table_;
  QCheckBox* levelled_;
  QLabel* status_;
  QPushButton* pick_;
  QPushButton* align_;
  QPushButton* refine_;
};

}  // namespace plumb::ui
