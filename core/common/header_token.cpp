#include "common/header_token.hpp"

#include <algorithm>

namespace plumb {

std::string headerToken(std::string name, std::string_view delimiters) {
  for (auto& ch : name) {
    const auto c = static_cast<unsigned char>(ch);
    if (c <= ' ' || c == 0x7F || delimiters.find(ch) != std::string_view::npos) ch = '_';
  }
  return name.empty() ? "field" : name;
}

std::vector<std::string> headerTokens(const std::vector<std::string>& names,
                                      std::vector<std::string> taken, std::string_view delimiters) {
  std::vector<std::string> out;
  auto used = [&](const std::string& s) { return std::find(taken.begin(), taken.end(), s) != taken.end(); };
  for (const auto& n : names) {
    const std::string base = headerToken(n, delimiters);
    std::string token = base;
    for (int k = 2; used(token); ++k) token = base + "_" + std::to_string(k);
    taken.push_back(token);
    out.push_back(token);
  }
  return out;
}

}  // namespace plumb
