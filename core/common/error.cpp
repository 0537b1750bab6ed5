#include "common/error.hpp"

#include <sstream>

namespace plumb {
namespace {
std::string formatMessage(const std::filesystem::path& file, const std::string& message,
                          const FileLocation& where) {
  std::ostringstream out;
  out << file.string() << ": " << message;
  std::string loc;
  if (!where.element.empty()) loc += where.element;
  if (where.line) loc += (loc.empty() ? "line " : ", line ") + std::to_string(*where.line);
  if (where.byte_offset)
    loc += (loc.empty() ? "byte " : ", byte ") + std::to_string(*where.byte_offset);
  if (!loc.empty()) out << " (at " << loc << ")";
  return out.str();
}
}  // namespace

FileError::FileError(std::filesystem::path file, std::string message, FileLocation where)
    : std::runtime_error(formatMessage(file, message, where)),
      file_(std::move(file)),
      message_(std::move(message)),
      where_(std::move(where)) {}

FileLocation atByte(std::uint64_t offset, std::string element) {
  FileLocation loc;
  loc.byte_offset = offset;
  loc.element = std::move(element);
  return loc;
}

FileLocation atLine(std::uint64_t line, std::string element) {
  FileLocation loc;
  loc.line = line;
  loc.element = std::move(element);
  return loc;
}

}  // namespace plumb
