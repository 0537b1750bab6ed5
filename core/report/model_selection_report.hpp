#pragma once
// What a registration onto chosen model elements rests on (issue 14), as the report files say
// it: the filter, and the elements and triangles used per IFC type against the whole model.
#include <nlohmann/json_fwd.hpp>

#include <sstream>

#include "model/model_element_filter.hpp"

namespace plumb::report {

/// {"filter": {"types": [...], "elements": [...]}, "description": "...", "used": [{"type",
///  "elements", "triangles"}...], "elements_used", "triangles_used", "elements_in_model",
///  "triangles_in_model"}
nlohmann::json modelSelectionJson(const ModelSelection& s);

/// The quality report's JSON text with "model_elements" added.
std::string withModelSelection(const std::string& quality_json, const ModelSelection& s);

/// The HTML section "Registration rests on": the filter and a table per IFC type.
void modelSelectionHtml(std::ostringstream& h, const ModelSelection& s);

}  // namespace plumb::report
