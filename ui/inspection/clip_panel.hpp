#pragma once
// The Clipping dock (issue 17, inspection): a plan slice (a horizontal slab around a height), a
// section across X or Y (a vertical slab), or a box, in world coordinates; the view draws only
// what is inside (Scene::setClipBox) and the dock counts the points inside (core countInside,
// exact). "Fit to data" centres it on the visible data's robust extent. Choosing a slice turns
// the camera to look at it square on (plan from the top, a section along its normal).
#include <QWidget>

#include <array>

#include "model/clip_box.hpp"

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace plumb::ui {

struct AppContext;

class ClipPanel : public QWidget {
  Q_OBJECT
 public:
  enum class Mode { Off, PlanSlice, SectionX, SectionY, Box };
  explicit ClipPanel(AppContext& app, QWidget* parent = nullptr);

  /// Centre and size (thickness of a slab) along axis 0, 1, 2 (world, metres).
  void setAxis(int axis, double centre, double size);
  /// Centres on the visible data's robust extent: sizes of a box, 0.1 m thick slabs.
  void fitToData();
  /// The box drawn (nullopt: Off).
  std::optional<ClipBox> box() const;
  /// Points of the visible datasets inside the box (0 when Off).
  std::size_t pointsInside() const { return inside_; }

 private:
  void apply();
  /// A slice chosen is seen square on: a plan slice from the top, a section along its normal.
  void lookAtSlice();
  AppContext& app_;
  QComboBox* mode_;
  std::array<QDoubleSpinBox*, 3> centre_{}, size_{};
  QLabel* count_;
  std::size_t inside_ = 0;
  bool updating_ = false;
};

}  // namespace plumb::ui
