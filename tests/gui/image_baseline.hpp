#pragma once
// Image-baseline checks for the GUI tests: a rendered view against a PNG stored under
// tests/gui/baselines/. The tolerance absorbs what differs between OpenGL implementations
// (Mesa versions, llvmpipe or softpipe): a pixel counts as different only when no pixel within
// one pixel of it in the baseline has a colour close to it, and a few such pixels may differ
// (anti-aliased text, edges). A wrong colour or a moved object differs over whole areas.
//
// Regenerating a baseline after an intended change of the picture: run the test with
// PLUMB_UPDATE_BASELINES=1 (it writes the PNGs into the source tree instead of comparing), look
// at them, commit them.
#include <QColor>
#include <QImage>
#include <QString>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>

#ifndef PLUMB_GUI_BASELINE_DIR
#error "PLUMB_GUI_BASELINE_DIR must name tests/gui/baselines (set by the test's CMakeLists)"
#endif

namespace plumb::test {

struct ImageDifference {
  QString problem;         ///< non-empty: the images cannot be compared (sizes differ)
  double differing = 1.0;  ///< fraction of the pixels that differ
  QImage map;              ///< the actual image dimmed, its differing pixels magenta
};

/// Squared RGB distance between two colours (0 .. 3 * 255^2).
inline int colourDistance2(QRgb a, QRgb b) {
  const int dr = qRed(a) - qRed(b), dg = qGreen(a) - qGreen(b), db = qBlue(a) - qBlue(b);
  return dr * dr + dg * dg + db * db;
}

/// Whether some pixel of `image` within one pixel of (x, y) is within `max_distance` of `c`.
inline bool closeColourNear(const QImage& image, int x, int y, QRgb c, int max_distance) {
  for (int v = std::max(0, y - 1); v <= std::min(image.height() - 1, y + 1); ++v)
    for (int u = std::max(0, x - 1); u <= std::min(image.width() - 1, x + 1); ++u)
      if (colourDistance2(image.pixel(u, v), c) <= max_distance * max_distance) return true;
  return false;
}

/// Compares `actual` with `expected` pixel by pixel (closeColourNear, Euclidean RGB distance).
inline ImageDifference compareImages(const QImage& actual_in, const QImage& expected_in,
                                     int max_distance = 40) {
  ImageDifference out;
  const QImage actual = actual_in.convertToFormat(QImage::Format_RGB32);
  const QImage expected = expected_in.convertToFormat(QImage::Format_RGB32);
  if (actual.size() != expected.size()) {
    out.problem = QString("the image is %1 x %2 pixels, the baseline %3 x %4")
                      .arg(actual.width()).arg(actual.height()).arg(expected.width()).arg(expected.height());
    return out;
  }
  out.map = QImage(actual.size(), QImage::Format_RGB32);
  long differing = 0;
  for (int y = 0; y < actual.height(); ++y)
    for (int x = 0; x < actual.width(); ++x) {
      const QRgb c = actual.pixel(x, y);
      const bool same = closeColourNear(expected, x, y, c, max_distance);
      differing += same ? 0 : 1;
      out.map.setPixel(x, y, same ? qRgb(qRed(c) / 3, qGreen(c) / 3, qBlue(c) / 3) : qRgb(255, 0, 255));
    }
  out.differing = double(differing) / double(std::max(1LL, 1LL * actual.width() * actual.height()));
  return out;
}

/// Whether PLUMB_UPDATE_BASELINES asks to write the baselines (set, not empty, not "0").
inline bool updatingBaselines() {
  const char* v = std::getenv("PLUMB_UPDATE_BASELINES");
  return v && *v && std::string(v) != "0";
}

inline std::filesystem::path baselinePath(const QString& name) {
  return std::filesystem::path(PLUMB_GUI_BASELINE_DIR) / (name.toStdString() + ".png");
}

struct BaselineCheck {
  bool ok = false;
  QString message;  ///< what differs and where the artefacts are (or that it was written)
};

/// `actual` against baselines/<name>.png: ok when at most `max_fraction` of the pixels differ
/// (compareImages). Otherwise writes <artefacts>/<name>.actual.png and <name>.diff.png and
/// names them. While updatingBaselines(), writes the baseline from `actual` instead.
inline BaselineCheck checkBaseline(const QImage& actual, const QString& name,
                                   const std::filesystem::path& artefacts, double max_fraction = 0.015) {
  const auto baseline = baselinePath(name);
  const QString where = QString::fromStdString(baseline.string());
  if (updatingBaselines()) {
    const bool written = actual.save(where, "PNG");
    return {written, written ? "baseline written to " + where : "cannot write the baseline " + where};
  }
  const QImage expected(where);
  if (expected.isNull())
    return {false, "no baseline " + where + ": run with PLUMB_UPDATE_BASELINES=1 to write it"};
  const ImageDifference d = compareImages(actual, expected);
  if (d.problem.isEmpty() && d.differing <= max_fraction) return {true, {}};
  const auto stem = artefacts / name.toStdString();
  actual.save(QString::fromStdString(stem.string() + ".actual.png"), "PNG");
  if (!d.map.isNull()) d.map.save(QString::fromStdString(stem.string() + ".diff.png"), "PNG");
  const QString what = d.problem.isEmpty()
                           ? QString("%1% of the pixels differ (at most %2% may)")
                                 .arg(100.0 * d.differing, 0, 'f', 2).arg(100.0 * max_fraction, 0, 'f', 2)
                           : d.problem;
  return {false, where + ": " + what + "; see " + QString::fromStdString(stem.string()) + ".actual.png / .diff.png"};
}

}  // namespace plumb::test
