#include "io/mesh/step_entities.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>

namespace plumb::step {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

/// Index just past the string starting at `i` (text[i] == '\''); npos if unterminated.
std::size_t stringEnd(std::string_view text, std::size_t i) {
  for (++i; i < text.size(); ++i) {
    if (text[i] != '\'') continue;
    if (i + 1 < text.size() && text[i + 1] == '\'') ++i;
    else return i + 1;
  }
  return std::string_view::npos;
}

/// stringEnd, or text.size() if unterminated.
std::size_t skipString(std::string_view text, std::size_t i) { return std::min(stringEnd(text, i), text.size()); }

/// Index of the ';' ending the instance that starts at `i`, or npos.
std::size_t instanceEnd(std::string_view text, std::size_t i, std::uint64_t& newlines) {
  while (i < text.size()) {
    const char c = text[i];
    if (c == '\'') {
      const std::size_t j = skipString(text, i);
      for (std::size_t k = i; k < j; ++k) newlines += text[k] == '\n';
      i = j;
      continue;
    }
    if (c == ';') return i;
    newlines += c == '\n';
    ++i;
  }
  return std::string_view::npos;
}

/// Parses "#id = TYPE ( args )" in `s` (without ';'); false when it is not that shape.
bool parseInstance(std::string_view s, Entity& e) {
  std::size_t i = 1;
  while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
  if (std::from_chars(s.data() + 1, s.data() + i, e.id).ec != std::errc()) return false;
  const auto eq = s.find('=', i);
  const auto open = s.find('(', i);
  const auto close = s.rfind(')');
  if (eq == std::string_view::npos || open == std::string_view::npos || close == std::string_view::npos ||
      open < eq || close < open)
    return false;
  e.type = trim(s.substr(eq + 1, open - eq - 1));
  e.args = s.substr(open + 1, close - open - 1);
  return true;
}

/// When a string or a comment starts at `i`: the index just past it (its newlines counted into
/// `line`; `whole` cleared when it is left open). Else `i`.
std::size_t pastStringOrComment(std::string_view text, std::size_t i, std::uint64_t& line, bool& whole) {
  std::size_t end = std::string_view::npos;
  if (text[i] == '\'') {
    end = stringEnd(text, i);
  } else if (text.compare(i, 2, "/*") == 0) {
    const auto close = text.find("*/", i + 2);
    if (close != std::string_view::npos) end = close + 2;
  } else {
    return i;
  }
  whole = whole && end != std::string_view::npos;
  end = std::min(end, text.size());
  line += static_cast<std::uint64_t>(std::count(text.begin() + static_cast<std::ptrdiff_t>(i),
                                                text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
  return end;
}

}  // namespace

bool forEachEntity(std::string_view text, const std::function<void(const Entity&)>& visit) {
  std::uint64_t line = 1;
  std::size_t i = 0;
  bool whole = true;
  while (i < text.size()) {
    if (const std::size_t past = pastStringOrComment(text, i, line, whole); past != i) {
      i = past;
      continue;
    }
    if (text[i] != '#') {
      line += text[i++] == '\n';
      continue;
    }
    std::uint64_t newlines = 0;
    const std::size_t semi = instanceEnd(text, i, newlines);
    if (semi == std::string_view::npos) return false;
    Entity e;
    e.begin = i;
    e.end = semi + 1;
    e.line = line;
    if (parseInstance(text.substr(i, semi - i), e)) visit(e);
    else whole = false;
    line += newlines;
    i = semi + 1;
  }
  return whole;
}

std::vector<std::string_view> splitArguments(std::string_view args) {
  std::vector<std::string_view> out;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const char c = args[i];
    if (c == '\'') {
      i = skipString(args, i) - 1;
    } else if (c == '(') {
      ++depth;
    } else if (c == ')') {
      --depth;
    } else if (c == ',' && depth == 0) {
      out.push_back(trim(args.substr(start, i - start)));
      start = i + 1;
    }
  }
  out.push_back(trim(args.substr(start)));
  return out;
}

std::uint64_t reference(std::string_view arg) {
  arg = trim(arg);
  std::uint64_t id = 0;
  if (arg.size() < 2 || arg[0] != '#') return 0;
  const auto r = std::from_chars(arg.data() + 1, arg.data() + arg.size(), id);
  return r.ec == std::errc() && r.ptr == arg.data() + arg.size() ? id : 0;
}

void forEachReference(std::string_view args, const std::function<void(std::uint64_t)>& visit) {
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == '\'') {
      i = skipString(args, i) - 1;
      continue;
    }
    if (args[i] != '#') continue;
    std::uint64_t id = 0;
    const auto r = std::from_chars(args.data() + i + 1, args.data() + args.size(), id);
    if (r.ec == std::errc()) visit(id);
  }
}

}  // namespace plumb::step
