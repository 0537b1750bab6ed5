#pragma once
// The pieces every plumb-import result stream is made of (model_stream, pcd_stream): a
// buffered writer to a file descriptor, a reader that checks every size against the bytes
// left, and the failure record the helper sends when the import ended with an error.
//
// A record (native byte order; both ends are the same build): 8-byte magic, u32 version,
// u8 kind, the kind's fields, "END!". Strings are u32 length + bytes; tables u64 count +
// items. The failure record: string message; u8 has line + u64 line; u8 has byte offset +
// u64 byte offset; string element.
#include <cstddef>
#include <cstdint>
#include <string>
#include <stdexcept>
#include <string_view>
#include <variant>
#include <vector>

#include "common/error.hpp"

namespace plumb::helper_stream {

/// An import that ended with an error the helper could describe.
struct Failure {
  std::string message;
  FileLocation where;
};

/// What identifies a record: its magic ("PLUMBMDL") and the version of its layout.
struct RecordType {
  std::string_view magic;  ///< 8 characters
  std::uint32_t version;
};

/// Every stream holds one record: kind 1, the result; kind 2, a failure.
constexpr std::uint8_t kResult = 1, kFailure = 2;

/// Buffered writes to a file descriptor; large blocks go out without being copied.
class Writer {
 public:
  explicit Writer(int fd);
  void begin(const RecordType& type, std::uint8_t kind);
  void bytes(const void* p, std::size_t n);
  template <class T>
  void pod(const T& v) { bytes(&v, sizeof v); }
  void str(const std::string& s);
  template <class T>
  void table(const std::vector<T>& v) {
    pod(static_cast<std::uint64_t>(v.size()));
    bytes(v.data(), v.size() * sizeof(T));
  }
  void failure(const Failure& f);
  /// Writes "END!" and flushes; false if the descriptor refused any byte.
  bool finish();

 private:
  void flush();
  void send(const char* p, std::size_t n);
  int fd_;
  bool ok_ = true;
  std::string buffer_;
};

/// Reads a stream; throws std::runtime_error saying what is wrong with it.
class Reader {
 public:
  explicit Reader(std::string_view bytes) : b_(bytes) {}
  /// Checks magic and version; returns the kind.
  std::uint8_t begin(const RecordType& type);
  void bytes(void* p, std::size_t n);
  /// The next n bytes, in place (no copy).
  std::string_view view(std::size_t n);
  template <class T>
  T pod() {
    T v;
    bytes(&v, sizeof v);
    return v;
  }
  std::string str();
  template <class T>
  void table(std::vector<T>& v) {
    v.resize(count(pod<std::uint64_t>(), sizeof(T)));
    bytes(v.data(), v.size() * sizeof(T));
  }
  /// n items of at least `size` bytes each must fit in what is left.
  std::size_t count(std::uint64_t n, std::size_t size) const;
  Failure failure();
  /// Checks "END!" and that nothing follows it.
  void finish();

 private:
  std::string_view b_;
  std::size_t at_ = 0;
};

/// Writes a whole failure record of `type`.
bool writeFailure(int fd, const RecordType& type, const Failure& failure);

/// Decodes a whole stream of `type`: a result read by `read(Reader&)`, or a failure.
template <class Read>
auto decode(std::string_view bytes, const RecordType& type, Read read)
    -> std::variant<decltype(read(std::declval<Reader&>())), Failure> {
  Reader r(bytes);
  const auto kind = r.begin(type);
  if (kind != kResult && kind != kFailure) throw std::runtime_error("unknown record kind");
  std::variant<decltype(read(r)), Failure> out;
  if (kind == kResult) out = read(r);
  else out = r.failure();
  r.finish();
  return out;
}

}  // namespace plumb::helper_stream
