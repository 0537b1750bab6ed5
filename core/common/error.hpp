#pragma once
// Errors raised by the core. Every message a user may see names the file, what is wrong and
// where (byte offset, line, element) when that is known.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace plumb {

/// Where in a file a problem was found. Any combination may be set.
struct FileLocation {
  std::optional<std::uint64_t> byte_offset;
  std::optional<std::uint64_t> line;  ///< 1-based
  std::string element;                ///< e.g. "vertex 12", "page 3", "/data3D/0/pose"
};

/// A file could not be read or written. what() is one line: "FILE: MESSAGE (at LOCATION)".
class FileError : public std::runtime_error {
 public:
  FileError(std::filesystem::path file, std::string message, FileLocation where = {});
  const std::filesystem::path& file() const noexcept { return file_; }
  const std::string& message() const noexcept { return message_; }
  const FileLocation& where() const noexcept { return where_; }

 private:
  std::filesystem::path file_;
  std::string message_;
  FileLocation where_;
};

/// Helpers to build locations tersely.
FileLocation atByte(std::uint64_t offset, std::string element = {});
FileLocation atLine(std::uint64_t line, std::string element = {});

/// Invalid input that is not a file (bad parameters, too few features...).
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Thrown by long operations when their Progress was cancelled.
class Canceled : public std::runtime_error {
 public:
  Canceled() : std::runtime_error("operation cancelled") {}
};

}  // namespace plumb
