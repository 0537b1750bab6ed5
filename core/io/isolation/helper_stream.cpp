#include "io/isolation/helper_stream.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace plumb::helper_stream {
namespace {

constexpr std::string_view kEnd = "END!";
constexpr std::size_t kChunk = 1 << 20;

}  // namespace

Writer::Writer(int fd) : fd_(fd) { buffer_.reserve(kChunk); }

void Writer::begin(const RecordType& type, std::uint8_t kind) {
  bytes(type.magic.data(), type.magic.size());
  pod(type.version);
  pod(kind);
}

void Writer::bytes(const void* p, std::size_t n) {
  if (n == 0) return;  // an empty table: p may be null
  const auto* c = static_cast<const char*>(p);
  if (n >= kChunk) {  // a block of points: straight from its memory, no copy
    flush();
    send(c, n);
    return;
  }
  const std::size_t k = std::min(n, kChunk - buffer_.size());
  buffer_.append(c, k);
  if (buffer_.size() == kChunk) flush();
  buffer_.append(c + k, n - k);
}

void Writer::str(const std::string& s) {
  pod(static_cast<std::uint32_t>(s.size()));
  bytes(s.data(), s.size());
}

void Writer::failure(const Failure& f) {
  str(f.message);
  pod(static_cast<std::uint8_t>(f.where.line.has_value()));
  pod(static_cast<std::uint64_t>(f.where.line.value_or(0)));
  pod(static_cast<std::uint8_t>(f.where.byte_offset.has_value()));
  pod(static_cast<std::uint64_t>(f.where.byte_offset.value_or(0)));
  str(f.where.element);
}

bool Writer::finish() {
  bytes(kEnd.data(), kEnd.size());
  flush();
  return ok_;
}

void Writer::flush() {
  send(buffer_.data(), buffer_.size());
  buffer_.clear();
}

void Writer::send(const char* p, std::size_t n) {
  std::size_t done = 0;
  while (ok_ && done < n) {
    const ssize_t w = ::write(fd_, p + done, n - done);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) ok_ = false;
    else done += static_cast<std::size_t>(w);
  }
}

std::uint8_t Reader::begin(const RecordType& type) {
  if (view(type.magic.size()) != type.magic)
    throw std::runtime_error("it does not start with " + std::string(type.magic));
  if (pod<std::uint32_t>() != type.version) throw std::runtime_error("its version is not this build's");
  return pod<std::uint8_t>();
}

void Reader::bytes(void* p, std::size_t n) {
  if (n == 0) return;  // an empty table: p may be null
  std::memcpy(p, view(n).data(), n);
}

std::string_view Reader::view(std::size_t n) {
  if (n > b_.size() - at_) throw std::runtime_error("the stream ends early");
  const std::string_view v = b_.substr(at_, n);
  at_ += n;
  return v;
}

std::string Reader::str() { return std::string(view(count(pod<std::uint32_t>(), 1))); }

std::size_t Reader::count(std::uint64_t n, std::size_t size) const {
  if (n > (b_.size() - at_) / size) throw std::runtime_error("a count exceeds the stream");
  return static_cast<std::size_t>(n);
}

Failure Reader::failure() {
  Failure f;
  f.message = str();
  const auto has_line = pod<std::uint8_t>();
  const auto line = pod<std::uint64_t>();
  if (has_line) f.where.line = line;
  const auto has_offset = pod<std::uint8_t>();
  const auto offset = pod<std::uint64_t>();
  if (has_offset) f.where.byte_offset = offset;
  f.where.element = str();
  return f;
}

void Reader::finish() {
  if (b_.size() - at_ < kEnd.size() || b_.substr(at_) != kEnd) throw std::runtime_error("it does not end with END!");
  at_ = b_.size();
}

bool writeFailure(int fd, const RecordType& type, const Failure& failure) {
  Writer w(fd);
  w.begin(type, kFailure);
  w.failure(failure);
  return w.finish();
}

}  // namespace plumb::helper_stream
