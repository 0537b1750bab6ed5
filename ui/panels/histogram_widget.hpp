#pragma once
// A small bar chart of the distance histogram (registration QA), bars coloured like the points:
// a range starting below zero is of signed distances (blue-white-red, "behind" / "in front").
#include <QWidget>

#include "quality/cloud_distance.hpp"

namespace plumb::ui {

class HistogramWidget : public QWidget {
  Q_OBJECT
 public:
  explicit HistogramWidget(QWidget* parent = nullptr);
  void setHistogram(const DistanceHistogram& histogram);
  const DistanceHistogram& histogram() const { return histogram_; }
  QSize sizeHint() const override { return {240, 110}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  DistanceHistogram histogram_;
};

}  // namespace plumb::ui
