#include "report/html_report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>

#include "report/figure_meanings.hpp"
#include "report/html_style.hpp"
#include "report/model_selection_report.hpp"
#include "report/svg_plots.hpp"

namespace plumb::report {
namespace {

using nlohmann::json;
using Leaf = std::pair<std::string, json>;

void flatten(const json& v, const std::string& path, std::vector<Leaf>& out) {
  if (v.is_object()) {
    for (auto it = v.begin(); it != v.end(); ++it)
      flatten(it.value(), path.empty() ? it.key() : path + "." + it.key(), out);
  } else if (v.is_array() && !v.empty() && v[0].is_object()) {
    for (std::size_t i = 0; i < v.size(); ++i) flatten(v[i], path + "[" + std::to_string(i) + "]", out);
  } else {
    out.emplace_back(path, v);
  }
}

std::string esc(const std::string& s) { return escapeXml(s); }

std::string mm(double metres) { return std::isfinite(metres) ? fixedDigits(metres * 1e3, 1) + " mm" : "-"; }

void header(std::ostringstream& h, const RegistrationReport& r) {
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Registration report: "
    << esc(r.source.file) << " onto " << esc(r.target.file) << "</title><style>" << kReportStyle
    << "</style></head><body>\n<h1>Registration report</h1><p>" << esc(r.source.file) << " onto "
    << esc(r.target.file) << "<br>Created " << esc(r.created_utc) << " by Plumb " << esc(r.plumb_version)
    << ", seed " << r.seed << "</p>\n";
}

void verdict(std::ostringstream& h, const QualityReport& q) {
  const std::string level = verdictLevelName(q.level);
  h << "<div class=\"verdict " << esc(level) << "\" id=\"verdict\"><h2>Verdict: " << esc(level)
    << "</h2><p>" << esc(q.verdict) << "</p>";
  if (!q.warnings.empty()) {
    h << "<ul>";
    for (const auto& w : q.warnings) h << "<li>" << esc(w) << "</li>";
    h << "</ul>";
  }
  h << "</div>\n";
}

void inputs(std::ostringstream& h, const RegistrationReport& r) {
  h << "<h2>Inputs</h2><table><tr><th>role</th><th>file</th><th>kind</th><th>size</th></tr>";
  for (const ReportSide* s : {&r.source, &r.target})
    h << "<tr><td>" << esc(s->role) << "</td><td>" << esc(s->file) << "</td><td>"
      << (s->model ? "model" : "point cloud") << "</td><td>"
      << (s->model ? std::to_string(s->triangles) + " triangles" : std::to_string(s->points) + " points")
      << "</td></tr>";
  h << "</table>\n";
}

void transform(std::ostringstream& h, const QualityReport& q) {
  const RigidTransform& t = q.transform;
  const Eigen::Matrix4d m = t.matrix();
  h << "<h2>Transform (source to target)</h2><table>";
  for (int i = 0; i < 4; ++i) {
    h << "<tr>";
    for (int j = 0; j < 4; ++j) h << "<td class=\"v\">" << fixedDigits(m(i, j), j == 3 && i < 3 ? 4 : 9) << "</td>";
    h << "</tr>";
  }
  const Eigen::Vector3d tr = t.translation();
  h << "</table><p>Rotation " << fixedDigits(t.rotationAngleDeg(), 4) << " deg; translation ("
    << fixedDigits(tr.x(), 4) << ", " << fixedDigits(tr.y(), 4) << ", " << fixedDigits(tr.z(), 4) << ") m.</p>\n";
}

void figures(std::ostringstream& h, const std::vector<Leaf>& leaves) {
  h << "<h2>Quality figures</h2><p>Every figure of the JSON report, with its meaning.</p><table>"
       "<tr><th>figure</th><th>value</th><th>meaning</th></tr>";
  for (const auto& [path, value] : leaves)
    h << "<tr><td>" << esc(path) << "</td><td class=\"v\" data-json=\"" << esc(path) << "\" data-value=\""
      << esc(value.dump()) << "\">" << esc(displayValue(path, value)) << "</td><td>"
      << esc(figureMeaning(path)) << "</td></tr>";
  h << "</table>\n";
}

void distances(std::ostringstream& h, const DistanceSummary& d) {
  h << "<h2>Distances from the registered source to the target</h2><table>"
    << "<tr><td>source points sampled</td><td class=\"v\">" << d.sampled << "</td></tr>"
    << "<tr><td>matched within " << mm(d.max_distance) << "</td><td class=\"v\">" << d.matched << "</td></tr>"
    << "<tr><td>mean</td><td class=\"v\">" << mm(d.mean) << "</td></tr>"
    << "<tr><td>RMS</td><td class=\"v\">" << mm(d.rms) << "</td></tr>"
    << "<tr><td>median</td><td class=\"v\">" << mm(d.median) << "</td></tr>"
    << "<tr><td>95th percentile</td><td class=\"v\">" << mm(d.p95) << "</td></tr></table>\n";
}

void residualSummary(std::ostringstream& h, const std::vector<FeatureResidual>& residuals) {
  h << "<h2>Per-feature residuals</h2><table><tr><th>kind</th><th>compared</th><th>matched</th>"
       "<th>median</th><th>max</th></tr>";
  for (const char* kind : {"plane", "opening", "segment"}) {
    std::vector<double> d;
    std::size_t n = 0;
    for (const auto& r : residuals)
      if (r.kind == kind) {
        ++n;
        if (r.matched) d.push_back(r.distance_m);
      }
    if (n == 0) continue;
    std::sort(d.begin(), d.end());
    h << "<tr><td>" << kind << "</td><td class=\"v\">" << n << "</td><td class=\"v\">" << d.size()
      << "</td><td class=\"v\">" << (d.empty() ? "-" : mm(d[d.size() / 2])) << "</td><td class=\"v\">"
      << (d.empty() ? "-" : mm(d.back())) << "</td></tr>";
  }
  h << "</table>\n";
}

void candidates(std::ostringstream& h, const QualityReport& q) {
  if (q.candidates.empty()) return;
  h << "<h2>Placements considered</h2><table><tr><th>#</th><th>role</th><th>rotation</th>"
       "<th>translation (m)</th><th>feature score</th><th>overlap</th><th>point RMS</th></tr>";
  for (std::size_t i = 0; i < q.candidates.size(); ++i) {
    const auto& c = q.candidates[i];
    const Eigen::Vector3d t = c.transform.translation();
    h << "<tr><td>" << i + 1 << "</td><td>" << esc(c.role) << "</td><td class=\"v\">"
      << fixedDigits(c.transform.rotationAngleDeg(), 3) << " deg</td><td class=\"v\">" << fixedDigits(t.x(), 3) << ", "
      << fixedDigits(t.y(), 3) << ", " << fixedDigits(t.z(), 3) << "</td><td class=\"v\">" << fixedDigits(c.feature_score, 3)
      << "</td><td class=\"v\">" << (c.refined ? fixedDigits(c.overlap * 100, 1) + " %" : "-")
      << "</td><td class=\"v\">" << (c.refined ? mm(c.point_rms) : "-") << "</td></tr>";
  }
  h << "</table>\n";
}

void pictures(std::ostringstream& h, const std::vector<Picture>& pics) {
  if (pics.empty()) {
    h << "<h2>Pictures</h2><p>None: the registration failed, so there is no result to show. The "
         "placements considered are listed below.</p>\n";
    return;
  }
  h << "<h2>Pictures</h2>";
  for (const auto& p : pics) h << "<figure>" << p.svg << "<figcaption>" << esc(p.caption) << "</figcaption></figure>\n";
}

void signOff(std::ostringstream& h) {
  h << "<h2>Sign-off</h2><table class=\"sign\"><tr><th>checked by</th><td></td></tr>"
       "<tr><th>date</th><td></td></tr><tr><th>signature</th><td></td></tr></table>\n";
}

}  // namespace

std::vector<std::pair<std::string, std::string>> flattenReportJson(const std::string& json_text) {
  std::vector<Leaf> leaves;
  flatten(json::parse(json_text), "", leaves);
  std::vector<std::pair<std::string, std::string>> out;
  for (const auto& [p, v] : leaves) out.emplace_back(p, v.dump());
  return out;
}

std::string reportHtml(const RegistrationReport& r) {
  std::vector<Leaf> leaves;
  flatten(json::parse(qualityReportToJson(r.quality)), "", leaves);
  std::ostringstream h;
  header(h, r);
  verdict(h, r.quality);
  inputs(h, r);
  if (r.target_selection) modelSelectionHtml(h, *r.target_selection);
  transform(h, r.quality);
  pictures(h, r.pictures);
  if (r.distances.sampled > 0) distances(h, r.distances);
  if (!r.residuals.empty()) residualSummary(h, r.residuals);
  candidates(h, r.quality);
  figures(h, leaves);
  signOff(h);
  h << "</body></html>\n";
  return h.str();
}

}  // namespace plumb::report
