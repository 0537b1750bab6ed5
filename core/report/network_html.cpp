#include "report/network_html.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "report/html_report.hpp"
#include "report/html_style.hpp"
#include "report/svg_plots.hpp"

#ifndef PLUMB_VERSION_STRING
#define PLUMB_VERSION_STRING "dev"
#endif

namespace plumb::report {
namespace {

using nlohmann::json;

constexpr const char* kPlaced = "#2e7d32";
constexpr const char* kAmbiguous = "#f9a825";
constexpr const char* kKept = "#43a047";
constexpr const char* kBridge = "#1e88e5";
constexpr const char* kFlagged = "#fb8c00";
constexpr const char* kDropped = "#e53935";

std::string esc(const std::string& s) { return escapeXml(s); }

/// A table cell showing `text` for the JSON value at `path` (data-json / data-value).
std::string cell(const std::string& path, const json& value, const std::string& text) {
  return "<td class=\"v\" data-json=\"" + esc(path) + "\" data-value=\"" + esc(value.dump()) + "\">" + esc(text) +
         "</td>";
}

std::string cell(const json& object, const std::string& base, const std::string& key, const std::string& text) {
  if (!object.contains(key)) return "<td></td>";
  return cell(base + "." + key, object[key], text);
}

std::string yesNo(const json& v) { return v.is_boolean() ? (v.get<bool>() ? "yes" : "no") : v.dump(); }

std::string levelOf(int exit_code) {
  return exit_code == 0 ? "usable" : exit_code == 3 ? "check-visually" : "failed";
}

std::string names(const json& list) {
  std::string out;
  for (const auto& n : list) out += (out.empty() ? "" : ", ") + n.get<std::string>();
  return out;
}

void verdict(std::ostringstream& h, const json& r) {
  const int code = r.value("exit_code", 2);
  const json& n = r["network"];
  h << "<div class=\"verdict " << levelOf(code) << "\" id=\"verdict\"><h2>Verdict: " << levelOf(code) << "</h2><p>";
  if (code == 0) h << "Every station is placed and every kept link agrees with the network.";
  if (code == 3) h << "Every station is placed, but a kept link disagrees with the network (flagged below): check visually.";
  if (code == 2) h << "The network is incomplete: nothing was written. Stations listed below are not placed.";
  h << "</p><ul>";
  if (!n["unplaced"].empty())
    h << "<li>Not placed (no accepted link joins them to the reference): " << esc(names(n["unplaced"])) << "</li>";
  if (n.contains("ambiguous") && !n["ambiguous"].empty())
    h << "<li>Ambiguous (the links or the BIM place them in more than one way): " << esc(names(n["ambiguous"]))
      << "</li>";
  h << "</ul></div>\n";
}

Eigen::Vector2d planPosition(const json& station) {
  const auto& m = station["pose"]["matrix"];
  return {m[0][3].get<double>(), m[1][3].get<double>()};
}

void addLinkLines(const json& r, const std::map<std::string, Eigen::Vector2d>& at, PlanPicture& p) {
  for (const auto& l : r["links"]) {
    const std::string a = l["a"], b = l["b"];
    if (!l["accepted"].get<bool>() || !at.count(a) || !at.count(b)) continue;
    const bool dropped = l.value("dropped", false), flagged = l.value("flagged", false);
    const bool bridge = l.value("bridge", false);
    PlanLine line{at.at(a), at.at(b), dropped ? kDropped : flagged ? kFlagged : bridge ? kBridge : kKept,
                  a + " - " + b + (dropped ? ": dropped" : flagged ? ": flagged" : bridge ? ": no loop checks it" : ": kept"),
                  dropped};
    p.lines.push_back(line);
  }
}

void plan(std::ostringstream& h, const json& r) {
  PlanPicture p;
  p.title = "Plan view: stations and links (reference frame)";
  p.x_label = "x (m)";
  p.y_label = "y (m)";
  std::map<std::string, Eigen::Vector2d> at;
  for (const auto& s : r["stations"]) {
    if (s.value("model", false) || !s.contains("pose")) continue;
    at[s["name"]] = planPosition(s);
  }
  if (at.empty()) return;
  Eigen::Vector2d lo = at.begin()->second, hi = lo;
  for (const auto& [name, q] : at) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
  p.min = lo - Eigen::Vector2d(1, 1);
  p.max = hi + Eigen::Vector2d(1, 1);
  for (const auto& s : r["stations"])
    if (at.count(s["name"]))
      p.marks.push_back({at[s["name"]], s["name"], s.value("ambiguous", false) ? kAmbiguous : kPlaced});
  addLinkLines(r, at, p);
  p.legend = {{"station placed", kPlaced},     {"station ambiguous (not placed)", kAmbiguous},
              {"link kept, on a loop", kKept}, {"link kept, no loop checks it", kBridge},
              {"link flagged", kFlagged},      {"link dropped", kDropped}};
  h << "<h2>Plan view</h2><figure>" << planSvg(p)
    << "<figcaption>Stations at their adjusted positions; links between registered pairs, coloured by their "
       "status in the adjustment. Ambiguous stations are drawn where the adopted solution put them.</figcaption>"
       "</figure>\n";
}

void stations(std::ostringstream& h, const json& r) {
  h << "<h2>Stations</h2><table><tr><th>station</th><th>placed</th><th>ambiguous</th><th>x (m)</th><th>y (m)</th>"
       "<th>z (m)</th><th>sigma position (mm)</th><th>why</th></tr>";
  for (std::size_t i = 0; i < r["stations"].size(); ++i) {
    const json& s = r["stations"][i];
    const std::string base = "stations[" + std::to_string(i) + "]";
    h << "<tr>" << cell(s, base, "name", s["name"]) << cell(s, base, "placed", yesNo(s["placed"]))
      << cell(s, base, "ambiguous", yesNo(s.value("ambiguous", json(false))));
    if (s.contains("pose")) {
      const auto& m = s["pose"]["matrix"];
      for (int k = 0; k < 3; ++k) h << "<td class=\"v\">" << fixedDigits(m[k][3].get<double>(), 4) << "</td>";
    } else {
      h << "<td></td><td></td><td></td>";
    }
    if (s.contains("sigma_position_m")) {
      const auto& sp = s["sigma_position_m"];
      h << cell(base + ".sigma_position_m", sp,
                fixedDigits(1e3 * sp[0].get<double>(), 2) + ", " + fixedDigits(1e3 * sp[1].get<double>(), 2) + ", " +
                    fixedDigits(1e3 * sp[2].get<double>(), 2));
    } else {
      h << "<td></td>";
    }
    std::string why = s.value("ambiguous_why", std::string());
    if (s.value("unchecked", false)) why = "placed by one link no loop checks";
    if (s.contains("free_space"))  // what the free space of the confirmed stations decided
      why += (why.empty() ? "" : "; ") + s["free_space"]["why"].get<std::string>();
    h << "<td>" << esc(why) << "</td></tr>";
  }
  h << "</table>\n";
}

std::string linkState(const json& l) {
  if (!l["accepted"].get<bool>()) return "not used";
  if (l.value("dropped", false)) return "dropped";
  if (l.value("flagged", false)) return "flagged";
  return l.value("bridge", false) ? "kept, no loop checks it" : "kept";
}

void links(std::ostringstream& h, const json& r) {
  h << "<h2>Links</h2><table><tr><th>pair</th><th>why tried</th><th>verdict</th><th>overlap</th><th>RMS (mm)</th>"
       "<th>residual (mm)</th><th>residual (deg)</th><th>state</th></tr>";
  for (std::size_t k = 0; k < r["links"].size(); ++k) {
    const json& l = r["links"][k];
    const std::string base = "links[" + std::to_string(k) + "]";
    h << "<tr><td>" << esc(l["a"].get<std::string>() + " - " + l["b"].get<std::string>()) << "</td>"
      << cell(l, base, "reason", l["reason"]) << cell(l, base, "verdict_level", l["verdict_level"])
      << cell(l, base, "overlap", fixedDigits(l["overlap"].get<double>(), 3))
      << cell(l, base, "point_rms_m", fixedDigits(1e3 * l["point_rms_m"].get<double>(), 2));
    if (l.contains("residual_translation_m"))
      h << cell(l, base, "residual_translation_m", fixedDigits(1e3 * l["residual_translation_m"].get<double>(), 2))
        << cell(l, base, "residual_rotation_deg", fixedDigits(l["residual_rotation_deg"].get<double>(), 4));
    else
      h << "<td></td><td></td>";
    h << "<td>" << esc(linkState(l)) << "</td></tr>";
  }
  h << "</table>\n";
}

void residualHistogram(std::ostringstream& h, const json& r) {
  std::vector<double> mm;
  for (const auto& l : r["links"])
    if (l["accepted"].get<bool>() && !l.value("dropped", false) && l.contains("residual_translation_m"))
      mm.push_back(1e3 * l["residual_translation_m"].get<double>());
  if (mm.empty()) return;
  const double top = std::max(0.1, *std::max_element(mm.begin(), mm.end()));
  const int bins = 10;
  BarPicture p;
  p.title = "Residuals of the kept links after adjustment";
  p.x_label = "residual (0 to " + fixedDigits(top, 2) + " mm, " + std::to_string(bins) + " bins)";
  p.y_label = "links";
  std::vector<int> count(bins, 0);
  for (double v : mm) ++count[std::min(bins - 1, static_cast<int>(v / top * bins))];
  for (int b = 0; b < bins; ++b)
    p.bars.push_back({fixedDigits(top * b / bins, 2) + "-" + fixedDigits(top * (b + 1) / bins, 2) + " mm: " +
                          std::to_string(count[b]) + " links",
                      double(count[b]), "#5c6bc0"});
  h << "<h2>Residuals</h2><figure>" << barsSvg(p) << "</figure>\n";
}

/// Control and check points (a network georeferenced on control points): the figures a
/// surveyor signs on. Residual = adjusted minus given, grid units.
void control(std::ostringstream& h, const json& r) {
  if (!r.contains("georeference")) return;
  const json& g = r["georeference"];
  h << "<h2>Control and check points</h2><p>" << esc(g["message"].get<std::string>()) << ". Grid scale factor "
    << fixedDigits(g["scale_factor"].get<double>(), 8)
    << (g["crs"].get<std::string>().empty() ? "" : " (" + esc(g["crs"].get<std::string>()) + ")")
    << "; coordinates are grid coordinates at the origin " << fixedDigits(g["origin_grid"][0].get<double>(), 3) << ", "
    << fixedDigits(g["origin_grid"][1].get<double>(), 3) << ", " << fixedDigits(g["origin_grid"][2].get<double>(), 3)
    << " and ground distances about it.</p><table><tr><th>point</th><th>role</th><th>stations</th>"
       "<th>residual E, N, H (mm)</th><th>residual (mm)</th></tr>";
  for (std::size_t i = 0; i < g["points"].size(); ++i) {
    const json& p = g["points"][i];
    const std::string base = "georeference.points[" + std::to_string(i) + "]";
    h << "<tr>" << cell(p, base, "name", p["name"]) << cell(p, base, "role", p["role"])
      << cell(p, base, "observations", p["observations"].dump());
    if (p.contains("residual_grid_m")) {
      const auto& d = p["residual_grid_m"];
      h << cell(base + ".residual_grid_m", d,
                fixedDigits(1e3 * d[0].get<double>(), 1) + ", " + fixedDigits(1e3 * d[1].get<double>(), 1) + ", " +
                    fixedDigits(1e3 * d[2].get<double>(), 1))
        << cell(p, base, "residual_m", fixedDigits(1e3 * p["residual_m"].get<double>(), 1));
    } else {
      h << "<td>not seen by a placed station</td><td></td>";
    }
    h << "</tr>";
  }
  h << "<tr><th>control RMS</th><td></td><td></td><td></td>"
    << cell(g, "georeference", "control_rms_m", fixedDigits(1e3 * g["control_rms_m"].get<double>(), 1))
    << "</tr><tr><th>check max</th><td></td><td></td><td></td>"
    << cell(g, "georeference", "check_max_m", fixedDigits(1e3 * g["check_max_m"].get<double>(), 1)) << "</tr></table>\n";
}

void figures(std::ostringstream& h, const json& r) {
  h << "<h2>Network figures</h2><table><tr><th>figure</th><th>value</th></tr>";
  for (const auto& [path, value] : flattenReportJson(json{{"network", r["network"]}}.dump()))
    h << "<tr><td>" << esc(path) << "</td><td class=\"v\" data-json=\"" << esc(path) << "\" data-value=\""
      << esc(value) << "\">" << esc(value) << "</td></tr>";
  h << "</table>\n";
}

}  // namespace

std::string networkReportHtml(const json& r, const std::string& created_utc) {
  std::ostringstream h;
  h << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Network registration report</title>"
    << "<style>" << kReportStyle << "</style></head><body>\n<h1>Network registration report</h1><p>"
    << r["stations"].size() << " nodes, reference " << esc(r.value("reference", std::string())) << "<br>Created "
    << esc(created_utc) << " by Plumb " << PLUMB_VERSION_STRING << "</p>\n";
  verdict(h, r);
  plan(h, r);
  stations(h, r);
  links(h, r);
  control(h, r);
  residualHistogram(h, r);
  figures(h, r);
  h << "<h2>Sign-off</h2><table class=\"sign\"><tr><th>checked by</th><td></td></tr>"
       "<tr><th>date</th><td></td></tr><tr><th>signature</th><td></td></tr></table>\n</body></html>\n";
  return h.str();
}

}  // namespace plumb::report
