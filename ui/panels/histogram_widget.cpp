#include "ui/panels/histogram_widget.hpp"

#include <QPainter>

#include <algorithm>

#include "ui/layers/color_ramp.hpp"

namespace plumb::ui {

HistogramWidget::HistogramWidget(QWidget* parent) : QWidget(parent) {
  setObjectName("distanceHistogram");
  setMinimumHeight(90);
  histogram_.counts.clear();
}

void HistogramWidget::setHistogram(const DistanceHistogram& histogram) {
  histogram_ = histogram;
  update();
}

void HistogramWidget::paintEvent(QPaintEvent*) {
  QPainter p(this);
  p.fillRect(rect(), palette().base());
  const auto& counts = histogram_.counts;
  if (counts.empty()) {
    p.drawText(rect(), Qt::AlignCenter, tr("no distances yet"));
    return;
  }
  const int label_h = fontMetrics().height() + 2;
  const QRectF area(4, 4, width() - 8, height() - 8 - label_h);
  const double peak = double(*std::max_element(counts.begin(), counts.end()));
  const double w = area.width() / double(counts.size());
  // A range starting below zero holds signed distances: the diverging ramp, as in the view.
  const bool signed_values = histogram_.lo < 0;
  const RampKind ramp = signed_values ? RampKind::Diverging : RampKind::Distance;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    const double h = peak > 0 ? area.height() * double(counts[i]) / peak : 0.0;
    const Rgb c = rampColor(ramp, (double(i) + 0.5) / double(counts.size()));
    p.fillRect(QRectF(area.left() + double(i) * w, area.bottom() - h, std::max(1.0, w - 1), h),
               QColor(c[0], c[1], c[2]));
  }
  p.setPen(palette().text().color());
  const QRectF labels(area.left(), area.bottom() + 2, area.width(), label_h);
  const QString lo = QString::number(histogram_.lo, 'f', 2) + " m";
  const QString hi = (signed_values ? "+" : "") + QString::number(histogram_.hi, 'f', 2) + " m";
  p.drawText(labels, Qt::AlignLeft, signed_values ? tr("%1 behind").arg(lo) : lo);
  p.drawText(labels, Qt::AlignRight, signed_values ? tr("in front %1").arg(hi) : hi);
  const std::size_t outside = histogram_.below + histogram_.above + histogram_.invalid;
  if (outside > 0) p.drawText(labels, Qt::AlignHCenter, tr("%1 beyond / unmatched").arg(outside));
}

}  // namespace plumb::ui
