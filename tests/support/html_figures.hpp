#pragma once
// Reads the figures of an HTML registration report (core/report/html_report.hpp): each value
// cell carries data-json="<path>" data-value="<JSON value>". Shared by the report tests.
#include <cstring>
#include <map>
#include <regex>
#include <string>

namespace plumb::test {

inline std::string unescapeXml(std::string s) {
  const std::pair<const char*, const char*> entities[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : entities)
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1))
      s.replace(at, std::strlen(from), to);
  return s;
}

/// data-json path -> data-value, as a browser reads the attributes.
inline std::map<std::string, std::string> htmlFigures(const std::string& html) {
  static const std::regex cell(R"re(data-json="([^"]*)" data-value="([^"]*)")re");
  std::map<std::string, std::string> out;
  for (auto it = std::sregex_iterator(html.begin(), html.end(), cell); it != std::sregex_iterator(); ++it)
    out[unescapeXml((*it)[1])] = unescapeXml((*it)[2]);
  return out;
}

}  // namespace plumb::test
