#pragma once
// A minimal scanner for the DATA section of STEP files (IFC): entity instances "#id=TYPE(args);"
// with their line, and the top-level arguments of one instance. Strings ('...' with '' inside)
// and comments are skipped; nothing is validated beyond what the callers need.
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace plumb::step {

struct Entity {
  std::uint64_t id = 0;
  std::string_view type;  ///< as written, e.g. "IFCCARTESIANPOINT"
  std::string_view args;  ///< between the outer parentheses
  std::size_t begin = 0;  ///< byte offset of '#'
  std::size_t end = 0;    ///< byte offset just past ';'
  std::uint64_t line = 0; ///< 1-based line of '#'
};

/// Calls `visit` for each "#id=TYPE(...);" instance of `text`, in file order. Returns false
/// when the text is damaged so that entities may have been missed: an instance, string or
/// comment left open (the scan stops there), or an instance not of that shape (skipped).
bool forEachEntity(std::string_view text, const std::function<void(const Entity&)>& visit);

/// Top-level arguments of an argument list, split at commas outside strings and parentheses,
/// trimmed: "#3,$,(1.,2.)" -> {"#3", "$", "(1.,2.)"}.
std::vector<std::string_view> splitArguments(std::string_view args);

/// "#123" -> 123; 0 when `arg` is not a reference.
std::uint64_t reference(std::string_view arg);

/// Calls `visit` with every "#id" referenced in `args` (outside strings).
void forEachReference(std::string_view args, const std::function<void(std::uint64_t)>& visit);

}  // namespace plumb::step
