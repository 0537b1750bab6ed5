#pragma once
// View > Measure (issue 17, inspection): a click on any visible point shows its coordinates
// (exact, national grid included) in the Properties dock; a second click the distance from the
// first as surveyors read it: slope distance, horizontal distance, height difference, and the
// differences along X, Y, Z, with the two points marked and joined in the view. A third click
// starts a new measurement. Picking snaps to the nearest point within 0.5 deg of the ray.
#include <QObject>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <vector>

#include "ui/layers/layer.hpp"

namespace plumb::ui {

struct AppContext;
class PairMarkers;
struct MeasureToolLine;

/// The figures between two points (metres).
struct Measurement {
  Eigen::Vector3d a, b;
  double slope = 0.0, horizontal = 0.0, height = 0.0;  ///< |b-a|, |(b-a)_xy|, (b-a)_z
};
Measurement measure(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
/// Rows for the Properties dock: the point (or both points) and the figures.
std::vector<PropertyRow> pointRows(const Eigen::Vector3d& p, const QString& layer);
std::vector<PropertyRow> measurementRows(const Measurement& m);

class MeasureTool : public QObject {
  Q_OBJECT
 public:
  MeasureTool(AppContext& app, QObject* parent = nullptr);
  ~MeasureTool() override;
  bool active() const { return active_; }
  /// On: view clicks measure (feature and pair picking pause); off: the marks are removed.
  void setActive(bool on);
  /// The last complete measurement (two points), if any.
  const std::optional<Measurement>& last() const { return last_; }

 private:
  void onClicked(int x, int y);
  void showMarks();
  AppContext& app_;
  bool active_ = false;
  std::vector<Eigen::Vector3d> points_;  ///< 0, 1 or 2 picked points (world)
  std::optional<Measurement> last_;
  std::unique_ptr<PairMarkers> marks_;
  std::unique_ptr<MeasureToolLine> line_;
};

}  // namespace plumb::ui
