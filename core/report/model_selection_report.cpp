#include "report/model_selection_report.hpp"

#include <nlohmann/json.hpp>

#include "report/svg_plots.hpp"

namespace plumb::report {

nlohmann::json modelSelectionJson(const ModelSelection& s) {
  nlohmann::json j;
  j["filter"] = {{"types", s.filter.types}, {"elements", s.filter.elements}, {"storeys", s.filter.storeys}};
  j["description"] = s.filter.describe();
  std::size_t elements = 0, triangles = 0;
  j["used"] = nlohmann::json::array();
  for (const auto& u : s.used) {
    j["used"].push_back({{"type", u.type}, {"elements", u.elements}, {"triangles", u.triangles}});
    elements += u.elements;
    triangles += u.triangles;
  }
  j["elements_used"] = elements;
  j["triangles_used"] = triangles;
  j["elements_in_model"] = s.elements_in_model;
  j["triangles_in_model"] = s.triangles_in_model;
  return j;
}

std::string withModelSelection(const std::string& quality_json, const ModelSelection& s) {
  nlohmann::json j = nlohmann::json::parse(quality_json);
  j["model_elements"] = modelSelectionJson(s);
  return j.dump(2) + "\n";
}

void modelSelectionHtml(std::ostringstream& h, const ModelSelection& s) {
  h << "<h2 id=\"model-elements\">Registration rests on</h2><p>The target model was restricted to "
    << escapeXml(selectionSummary(s)) << ". Features and refinement used only these; deviations of "
       "the other elements do not pull the result.</p><table><tr><th>IFC type</th><th>elements</th>"
       "<th>triangles</th></tr>";
  for (const auto& u : s.used)
    h << "<tr><td>" << escapeXml(u.type.empty() ? "(untyped)" : u.type) << "</td><td class=\"v\">"
      << u.elements << "</td><td class=\"v\">" << u.triangles << "</td></tr>";
  h << "</table>\n";
}

}  // namespace plumb::report
