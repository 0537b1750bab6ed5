#pragma once
// Attribute names as tokens of a file header (PLY "property float NAME", the XYZ/CSV column
// line): a name like "my field" or "column 4" would split into two tokens there, and the
// file could not be read back.
#include <string>
#include <string_view>
#include <vector>

namespace plumb {

/// `name` with whitespace, control characters and the characters of `delimiters` replaced by
/// '_'; "field" when empty.
std::string headerToken(std::string name, std::string_view delimiters = "");

/// headerToken of each name, made distinct from each other and from `taken` (the header's
/// fixed columns) by a "_2", "_3"... suffix.
std::vector<std::string> headerTokens(const std::vector<std::string>& names,
                                      std::vector<std::string> taken,
                                      std::string_view delimiters = "");

}  // namespace plumb
