#include "report_figures.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>

namespace plumb::verdict {

namespace {

using nlohmann::json;

bool leftOut(const std::string& key) {
  std::string k = key;
  std::transform(k.begin(), k.end(), k.begin(), [](unsigned char c) { return std::tolower(c); });
  return k.find("transform") != std::string::npos || k == "axis" ||
         k.find("seconds") != std::string::npos;
}

bool allNumbers(const json& a) {
  return !a.empty() && std::all_of(a.begin(), a.end(), [](const json& v) { return v.is_number(); });
}

void flatten(const json& node, const std::string& path, std::map<std::string, double>& out) {
  if (node.is_number()) {
    out[path] = node.get<double>();
  } else if (node.is_object()) {
    for (const auto& [k, v] : node.items())
      if (!leftOut(k)) flatten(v, path.empty() ? k : path + "." + k, out);
  } else if (node.is_array() && allNumbers(node)) {
    double lo = node[0].get<double>(), hi = lo;
    for (const auto& v : node) {
      lo = std::min(lo, v.get<double>());
      hi = std::max(hi, v.get<double>());
    }
    out[path + ".min"] = lo;
    out[path + ".max"] = hi;
  } else if (node.is_array() && !node.empty() && node[0].is_object()) {
    out[path + ".count"] = double(node.size());
    flatten(node[0], path + "[0]", out);
  } else if (node.is_array()) {
    out[path + ".count"] = double(node.size());
  }
}

Level levelFromName(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  if (name.find("check") != std::string::npos || name.find("caution") != std::string::npos)
    return Level::CheckVisually;
  if (name.rfind("usable", 0) == 0) return Level::Usable;
  return Level::FailedOrAmbiguous;
}

}  // namespace

std::string levelName(Level l) {
  switch (l) {
    case Level::Usable: return "usable";
    case Level::CheckVisually: return "check visually";
    case Level::FailedOrAmbiguous: return "failed or ambiguous";
  }
  return "?";
}

std::map<std::string, double> reportFigures(const std::string& report_json) {
  std::map<std::string, double> out;
  flatten(json::parse(report_json), "", out);
  return out;
}

Level reportLevel(const std::string& report_json) {
  const json j = json::parse(report_json);
  if (j.contains("verdict_level") && j["verdict_level"].is_string())
    return levelFromName(j["verdict_level"].get<std::string>());
  if (!j.value("success", false)) return Level::FailedOrAmbiguous;
  const bool warned = j.contains("warnings") && j["warnings"].is_array() && !j["warnings"].empty();
  return warned ? Level::CheckVisually : Level::Usable;
}

}  // namespace plumb::verdict
