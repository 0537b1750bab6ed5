#include "io/mesh/ifc_storeys.hpp"

#include <cctype>
#include <cstdint>

#include "common/utf8.hpp"
#include "io/mesh/step_entities.hpp"

namespace plumb::ifc_storeys {

namespace {

bool hexDigits(std::string_view s, std::size_t at, std::size_t n) {
  if (at + n > s.size()) return false;
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isxdigit(static_cast<unsigned char>(s[at + i]))) return false;
  return true;
}

std::uint32_t hexValue(std::string_view s, std::size_t at, std::size_t n) {
  return static_cast<std::uint32_t>(std::stoul(std::string(s.substr(at, n)), nullptr, 16));
}

/// \X2\ hhhh... \X0\ at `i` (pointing at the first backslash): appends the characters and
/// returns the index after \X0\, or `i` when it is not such an escape.
std::size_t utf16Escape(std::string_view s, std::size_t i, std::string& out) {
  if (s.compare(i, 4, "\\X2\\") != 0) return i;
  const std::size_t end = s.find("\\X0\\", i + 4);
  if (end == std::string_view::npos || (end - i - 4) % 4 != 0 || !hexDigits(s, i + 4, end - i - 4)) return i;
  for (std::size_t k = i + 4; k < end; k += 4) appendUtf8(out, hexValue(s, k, 4));
  return end + 4;
}

}  // namespace

std::string decodeString(std::string_view quoted) {
  std::string_view s = quoted;
  if (s.size() >= 2 && s.front() == '\'' && s.back() == '\'') s = s.substr(1, s.size() - 2);
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    if (s[i] == '\'' && i + 1 < s.size() && s[i + 1] == '\'') {
      out += '\'';
      i += 2;
    } else if (const std::size_t next = utf16Escape(s, i, out); next != i) {
      i = next;
    } else if (s.compare(i, 3, "\\X\\") == 0 && hexDigits(s, i + 3, 2)) {
      appendUtf8(out, hexValue(s, i + 3, 2));
      i += 5;
    } else {
      out += s[i++];
    }
  }
  return out;
}

std::map<std::string, std::string> storeyNames(std::string_view ifc_text) {
  std::map<std::string, std::string> names;
  step::forEachEntity(ifc_text, [&](const step::Entity& e) {
    if (e.type != "IFCBUILDINGSTOREY") return;
    const auto args = step::splitArguments(e.args);  // GlobalId, OwnerHistory, Name, ...
    if (args.size() < 3 || args[0].empty() || args[0].front() != '\'') return;
    const std::string guid = decodeString(args[0]);
    names[guid] = args[2].empty() || args[2].front() != '\'' ? guid : decodeString(args[2]);
  });
  return names;
}

void nameStoreys(BimModel& model, const std::map<std::string, std::string>& names) {
  for (BimElement& e : model.elements)
    if (const auto it = names.find(e.storey_guid); !e.storey_guid.empty() && it != names.end()) e.storey = it->second;
}

}  // namespace plumb::ifc_storeys
