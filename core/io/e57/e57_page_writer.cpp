#include "io/e57/e57_page_writer.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "common/error.hpp"
#include "io/e57/crc32c.hpp"

namespace plumb::e57 {

PagedWriter::PagedWriter(std::ostream& out, std::filesystem::path file)
    : out_(out), file_(std::move(file)) {}

void PagedWriter::checkStream() const {
  if (!out_) throw FileError(file_, "write failed (disk full or I/O error)", atByte(page_index_ * kPageSize));
}

void PagedWriter::emit(std::uint64_t page, std::array<std::uint8_t, kPageSize>& bytes, bool in_place) {
  const std::uint32_t crc = crc32c(bytes.data(), kPagePayload);
  bytes[kPagePayload + 0] = static_cast<std::uint8_t>(crc >> 24);  // big-endian (pitfall 2)
  bytes[kPagePayload + 1] = static_cast<std::uint8_t>(crc >> 16);
  bytes[kPagePayload + 2] = static_cast<std::uint8_t>(crc >> 8);
  bytes[kPagePayload + 3] = static_cast<std::uint8_t>(crc);
  if (in_place) {
    const auto end = out_.tellp();
    out_.seekp(static_cast<std::streamoff>(page * kPageSize));
    out_.write(reinterpret_cast<const char*>(bytes.data()), kPageSize);
    out_.seekp(end);
  } else {
    out_.write(reinterpret_cast<const char*>(bytes.data()), kPageSize);
  }
  checkStream();
}

void PagedWriter::flushPage() {
  emit(page_index_, page_, false);
  if (auto it = retained_.find(page_index_); it != retained_.end()) it->second = page_;
  ++page_index_;
  fill_ = 0;
  page_.fill(0);
}

void PagedWriter::write(const void* data, std::size_t n) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  while (n > 0) {
    const std::size_t take = std::min<std::size_t>(n, kPagePayload - fill_);
    std::memcpy(page_.data() + fill_, p, take);
    fill_ += take;
    p += take;
    n -= take;
    if (fill_ == kPagePayload) flushPage();
  }
}

void PagedWriter::writeZeros(std::size_t n) {
  static const std::uint8_t zeros[256] = {};
  while (n > 0) {
    const std::size_t take = std::min<std::size_t>(n, sizeof zeros);
    write(zeros, take);
    n -= take;
  }
}

void PagedWriter::retain(std::uint64_t logical, std::size_t n) {
  if (n == 0) return;
  const std::uint64_t first = logical / kPagePayload, last = (logical + n - 1) / kPagePayload;
  // A copy is kept when the page is flushed (a few pages per scan: bounded memory).
  for (std::uint64_t p = first; p <= last; ++p) retained_.try_emplace(p);
}

void PagedWriter::patch(std::uint64_t logical, const void* data, std::size_t n) {
  const auto* src = static_cast<const std::uint8_t*>(data);
  while (n > 0) {
    const std::uint64_t page = logical / kPagePayload;
    const std::size_t at = static_cast<std::size_t>(logical % kPagePayload);
    const std::size_t take = std::min<std::size_t>(n, kPagePayload - at);
    if (page == page_index_) {
      std::memcpy(page_.data() + at, src, take);
    } else {
      auto it = retained_.find(page);
      if (it == retained_.end() || page > page_index_)
        throw std::logic_error("E57 writer: patch of a page that was not retained");
      std::memcpy(it->second.data() + at, src, take);
      emit(page, it->second, true);
    }
    logical += take;
    src += take;
    n -= take;
  }
}

std::uint64_t PagedWriter::finish() {
  if (fill_ > 0) flushPage();
  out_.flush();
  checkStream();
  return page_index_ * kPageSize;
}

}  // namespace plumb::e57
