#pragma once
// Pixel checks shared by the GUI tests: is the view drawn, and in which colours.
#include <QColor>
#include <QImage>

#include <algorithm>
#include <cstdlib>

namespace plumb::test {

/// Pixels of `image` within `tolerance` (per channel) of `color`.
inline int countColor(const QImage& image, QColor color, int tolerance = 8) {
  int n = 0;
  const QImage img = image.convertToFormat(QImage::Format_RGB32);
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const QColor c = img.pixelColor(x, y);
      if (std::abs(c.red() - color.red()) <= tolerance &&
          std::abs(c.green() - color.green()) <= tolerance &&
          std::abs(c.blue() - color.blue()) <= tolerance)
        ++n;
    }
  return n;
}

/// Pixels that are not part of the (grey-blue) background gradient: saturated or bright.
inline int countNonBackground(const QImage& image) {
  int n = 0;
  const QImage img = image.convertToFormat(QImage::Format_RGB32);
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const QColor c = img.pixelColor(x, y);
      if (c.saturation() > 90 || c.value() > 140) ++n;
    }
  return n;
}

/// Clearly saturated pixels whose hue is within 20 degrees of `hue`.
inline int countHue(const QImage& image, int hue) {
  int n = 0;
  const QImage img = image.convertToFormat(QImage::Format_RGB32);
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const QColor c = img.pixelColor(x, y);
      const int d = std::abs(c.hue() - hue);
      if (c.saturation() > 120 && c.value() > 80 && c.hue() >= 0 && std::min(d, 360 - d) <= 20) ++n;
    }
  return n;
}

/// Pixels of countHue's kind: the larger side (pixels) of their bounding box; 0 when none.
inline int hueSpan(const QImage& image, int hue) {
  const QImage img = image.convertToFormat(QImage::Format_RGB32);
  int x0 = img.width(), x1 = -1, y0 = img.height(), y1 = -1;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x) {
      const QColor c = img.pixelColor(x, y);
      const int d = std::abs(c.hue() - hue);
      if (!(c.saturation() > 120 && c.value() > 80 && c.hue() >= 0 && std::min(d, 360 - d) <= 20)) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  return x1 < 0 ? 0 : std::max(x1 - x0, y1 - y0) + 1;
}

}  // namespace plumb::test
