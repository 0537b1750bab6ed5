#include "report/svg_plots.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace plumb::report {
namespace {

constexpr int kMargin = 44;

/// Pixel coordinates: a tenth of a pixel.
std::string num(double v) { return fixedDigits(v, 1); }

/// A round length near a fifth of `span`: 1, 2 or 5 times a power of ten.
double niceStep(double span) {
  const double raw = std::max(span, 1e-9) / 5.0;
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * p >= raw) return m * p;
  return 10.0 * p;
}

void openSvg(std::ostringstream& s, int w, int h, const std::string& title) {
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << w << "\" height=\"" << h
    << "\" viewBox=\"0 0 " << w << " " << h << "\" role=\"img\"><title>" << escapeXml(title)
    << "</title><rect width=\"" << w << "\" height=\"" << h << "\" fill=\"white\" stroke=\"#ccc\"/>"
    << "<text x=\"" << w / 2 << "\" y=\"16\" text-anchor=\"middle\" font-size=\"13\">"
    << escapeXml(title) << "</text>";
}

void axisLabels(std::ostringstream& s, int w, int h, const std::string& x, const std::string& y) {
  s << "<text x=\"" << w / 2 << "\" y=\"" << h - 6 << "\" text-anchor=\"middle\" font-size=\"11\">"
    << escapeXml(x) << "</text><text x=\"12\" y=\"" << h / 2 << "\" font-size=\"11\" "
    << "text-anchor=\"middle\" transform=\"rotate(-90 12 " << h / 2 << ")\">" << escapeXml(y) << "</text>";
}

void legend(std::ostringstream& s, const std::vector<ScatterLayer>& layers, int w) {
  int y = 30;
  for (const auto& l : layers) {
    s << "<rect x=\"" << w - 215 << "\" y=\"" << y - 9 << "\" width=\"10\" height=\"10\" fill=\""
      << escapeXml(l.colour) << "\"/><text x=\"" << w - 200 << "\" y=\"" << y << "\" font-size=\"11\">"
      << escapeXml(l.name) << " (" << l.points.size() << " shown)</text>";
    y += 15;
  }
}

/// Equal scales on both axes: metres -> pixels, and the pixel position of the extent's corner.
struct Frame {
  double scale, x0, y0;
};
Frame pictureFrame(const Eigen::Vector2d& span, int w, int h) {
  const double scale = std::min((w - 2.0 * kMargin) / span.x(), (h - 2.0 * kMargin) / span.y());
  return {scale, kMargin + 0.5 * ((w - 2.0 * kMargin) - scale * span.x()),
          h - kMargin - 0.5 * ((h - 2.0 * kMargin) - scale * span.y())};
}

}  // namespace

std::string fixedDigits(double value, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, value);
  return buf;
}

std::string escapeXml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') out += ' ';
        else out += c;
    }
  }
  return out;
}

std::string scatterSvg(const ScatterPicture& p, int w, int h) {
  std::ostringstream s;
  openSvg(s, w, h, p.title);
  const Eigen::Vector2d span = (p.max - p.min).cwiseMax(1e-6);
  const auto [scale, x0, y0] = pictureFrame(span, w, h);
  for (const auto& layer : p.layers) {
    s << "<g fill=\"" << escapeXml(layer.colour) << "\" fill-opacity=\"0.6\">";
    for (const auto& q : layer.points) {
      if (q.x() < p.min.x() || q.y() < p.min.y() || q.x() > p.max.x() || q.y() > p.max.y()) continue;
      s << "<rect x=\"" << num(x0 + (q.x() - p.min.x()) * scale) << "\" y=\""
        << num(y0 - (q.y() - p.min.y()) * scale) << "\" width=\"1.6\" height=\"1.6\"/>";
    }
    s << "</g>";
  }
  const double bar = niceStep(span.x());
  s << "<g stroke=\"black\"><line x1=\"" << kMargin << "\" y1=\"" << h - 24 << "\" x2=\""
    << num(kMargin + bar * scale) << "\" y2=\"" << h - 24 << "\" stroke-width=\"2\"/></g>"
    << "<text x=\"" << kMargin << "\" y=\"" << h - 28 << "\" font-size=\"11\">" << bar << " m</text>";
  legend(s, p.layers, w);
  axisLabels(s, w, h, p.x_label, p.y_label);
  s << "</svg>";
  return s.str();
}

std::string barsSvg(const BarPicture& p, int w, int h) {
  std::ostringstream s;
  openSvg(s, w, h, p.title);
  double top = 0.0;
  for (const auto& b : p.bars) top = std::max(top, std::isfinite(b.value) ? b.value : 0.0);
  if (!(top > 0)) top = 1.0;
  const double plot_w = w - 2.0 * kMargin, plot_h = h - 2.0 * kMargin;
  const double bw = p.bars.empty() ? plot_w : plot_w / static_cast<double>(p.bars.size());
  for (std::size_t i = 0; i < p.bars.size(); ++i) {
    const auto& b = p.bars[i];
    const double v = std::isfinite(b.value) ? std::max(0.0, b.value) : 0.0;
    const double bh = v / top * plot_h;
    s << "<rect x=\"" << num(kMargin + i * bw) << "\" y=\"" << num(h - kMargin - bh) << "\" width=\""
      << num(std::max(1.0, bw - 1.0)) << "\" height=\"" << num(bh) << "\" fill=\"" << escapeXml(b.colour)
      << "\"><title>" << escapeXml(b.label) << "</title></rect>";
  }
  // Each marker's label a line below the previous one: close markers (RMS and 95 %) would
  // write over each other.
  for (std::size_t m = 0; m < p.markers.size(); ++m) {
    const auto& [label, at] = p.markers[m];
    const double x = kMargin + at * bw;
    s << "<line x1=\"" << num(x) << "\" y1=\"" << kMargin << "\" x2=\"" << num(x) << "\" y2=\""
      << h - kMargin << "\" stroke=\"#c00\" stroke-dasharray=\"4 3\"/><text x=\"" << num(x + 3)
      << "\" y=\"" << kMargin + 10 + 12 * int(m) << "\" font-size=\"10\" fill=\"#c00\">" << escapeXml(label)
      << "</text>";
  }
  s << "<line x1=\"" << kMargin << "\" y1=\"" << h - kMargin << "\" x2=\"" << w - kMargin << "\" y2=\""
    << h - kMargin << "\" stroke=\"black\"/><text x=\"" << kMargin - 4 << "\" y=\"" << kMargin + 4
    << "\" font-size=\"10\" text-anchor=\"end\">" << num(top) << "</text>";
  axisLabels(s, w, h, p.x_label, p.y_label);
  s << "</svg>";
  return s.str();
}

std::string planSvg(const PlanPicture& p, int w, int h) {
  std::ostringstream s;
  openSvg(s, w, h, p.title);
  const Eigen::Vector2d span = (p.max - p.min).cwiseMax(1e-6);
  const auto [scale, x0, y0] = pictureFrame(span, w, h);
  auto x = [&](const Eigen::Vector2d& q) { return num(x0 + (q.x() - p.min.x()) * scale); };
  auto y = [&](const Eigen::Vector2d& q) { return num(y0 - (q.y() - p.min.y()) * scale); };
  for (const auto& l : p.lines)
    s << "<line x1=\"" << x(l.from) << "\" y1=\"" << y(l.from) << "\" x2=\"" << x(l.to) << "\" y2=\"" << y(l.to)
      << "\" stroke=\"" << escapeXml(l.colour) << "\" stroke-width=\"2\"" << (l.dashed ? " stroke-dasharray=\"5 4\"" : "")
      << "><title>" << escapeXml(l.title) << "</title></line>";
  for (const auto& m : p.marks)
    s << "<circle cx=\"" << x(m.at) << "\" cy=\"" << y(m.at) << "\" r=\"4\" fill=\"" << escapeXml(m.colour)
      << "\" stroke=\"black\" stroke-width=\"0.6\"/><text x=\"" << x(m.at) << "\" y=\"" << y(m.at)
      << "\" dx=\"5\" dy=\"-5\" font-size=\"10\">" << escapeXml(m.label) << "</text>";
  const double bar = niceStep(span.x());
  s << "<line x1=\"" << kMargin << "\" y1=\"" << h - 24 << "\" x2=\"" << num(kMargin + bar * scale) << "\" y2=\""
    << h - 24 << "\" stroke=\"black\" stroke-width=\"2\"/><text x=\"" << kMargin << "\" y=\"" << h - 28
    << "\" font-size=\"11\">" << bar << " m</text>";
  int ly = 30;
  for (const auto& [text, colour] : p.legend) {
    s << "<rect x=\"" << w - 215 << "\" y=\"" << ly - 9 << "\" width=\"10\" height=\"10\" fill=\"" << escapeXml(colour)
      << "\"/><text x=\"" << w - 200 << "\" y=\"" << ly << "\" font-size=\"11\">" << escapeXml(text) << "</text>";
    ly += 15;
  }
  axisLabels(s, w, h, p.x_label, p.y_label);
  s << "</svg>";
  return s.str();
}

}  // namespace plumb::report
