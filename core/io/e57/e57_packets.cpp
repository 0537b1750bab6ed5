#include "io/e57/e57_packets.hpp"

#include <algorithm>
#include <cstring>
#include <sstream>

namespace plumb::e57 {
namespace {
constexpr std::size_t kSectionHeaderSize = 32;
constexpr std::size_t kMaxPacket = 65536;
constexpr std::uint32_t kMaxBarrenPackets = 256;

std::uint16_t u16(const std::uint8_t* p) { return static_cast<std::uint16_t>(p[0] | (p[1] << 8)); }
std::uint64_t u64(const std::uint8_t* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  return v;
}
}  // namespace

void CompressedVectorReader::fail(const std::string& message, std::uint64_t logical) const {
  file_.fail(message, atByte(logicalToPhysical(logical), path_));
}

CompressedVectorReader::CompressedVectorReader(PagedReader& file, const ScanInfo& scan)
    : file_(file), path_(scan.points_path), record_count_(scan.record_count) {
  const std::uint64_t offset = scan.points_offset;
  if (offset >= file.physicalSize() || isInChecksum(offset) ||
      physicalToLogical(offset) + kSectionHeaderSize > file.logicalSize())
    file.fail("CompressedVector fileOffset " + std::to_string(offset) + " is outside the file",
              atByte(offset, path_));
  section_start_ = physicalToLogical(offset);
  std::uint8_t h[kSectionHeaderSize];
  file.readLogical(section_start_, sizeof h, h, "CompressedVector section header");
  if (h[0] != 1) {
    fail("invalid CompressedVector section header: section id " + std::to_string(h[0]) +
             " (expected 1)", section_start_);
  }
  const std::uint64_t length = u64(h + 8);
  const std::uint64_t data_physical = u64(h + 16);
  if (length < kSectionHeaderSize || length > file.logicalSize() - section_start_)
    fail("invalid CompressedVector section length " + std::to_string(length), section_start_ + 8);
  section_end_ = section_start_ + length;

  for (const FieldSpec& f : scan.fields) decoders_.emplace_back(f);
  // A record costs at least one bit of the section per field (fields stored in 0 bits too), so
  // a corrupted count cannot make us allocate unbounded memory.
  const std::uint64_t cost = scan.recordCost();
  const std::uint64_t capacity = (length - kSectionHeaderSize) * 8 / cost;
  if (record_count_ > capacity) {
    std::ostringstream msg;
    msg << "recordCount " << record_count_ << " cannot fit in the " << length
        << "-byte CompressedVector section (at least " << cost << " bits per record)";
    fail(msg.str(), section_start_);
  }
  if (record_count_ > 0) {
    if (decoders_.empty()) fail("CompressedVector prototype has no fields", section_start_);
    if (data_physical >= file.physicalSize() || isInChecksum(data_physical))
      fail("CompressedVector dataPhysicalOffset " + std::to_string(data_physical) +
               " is outside the file", section_start_ + 16);
    next_packet_ = physicalToLogical(data_physical);
    if (next_packet_ < section_start_ + kSectionHeaderSize || next_packet_ >= section_end_)
      fail("CompressedVector dataPhysicalOffset " + std::to_string(data_physical) +
               " is outside its section", section_start_ + 16);
  } else {
    next_packet_ = section_end_;
  }
}

void CompressedVectorReader::readNextPacket() {
  while (true) {
    if (next_packet_ + 4 > section_end_) {
      std::ostringstream msg;
      msg << "CompressedVector data ends after " << records_read_ << " of " << record_count_
          << " records (missing packets or truncated bytestreams)";
      fail(msg.str(), next_packet_);
    }
    const std::uint64_t at = next_packet_;
    std::uint8_t head[4];
    file_.readLogical(at, 4, head, "packet header");
    const std::uint8_t type = head[0];
    const std::size_t length = std::size_t{u16(head + 2)} + 1;
    checkPacket(type, length, at);
    next_packet_ = at + length;
    if (type != 1) continue;  // index and empty packets carry no records
    packet_.resize(kMaxPacket);
    file_.readLogical(at, length, packet_.data(), "data packet");
    const std::size_t count = u16(packet_.data() + 4);
    if (count == 0) continue;  // a packet without bytestreams (libE57Format's 0-record form)
    if (count != decoders_.size()) {
      std::ostringstream msg;
      msg << "data packet has " << count << " bytestreams, the prototype has "
          << decoders_.size() << " fields";
      fail(msg.str(), at);
    }
    std::size_t pos = 6 + 2 * count;
    if (pos > length) fail("data packet too short for its bytestream table", at);
    std::size_t total = pos;
    for (std::size_t i = 0; i < count; ++i) total += u16(packet_.data() + 6 + 2 * i);
    if (total > length) {
      std::ostringstream msg;
      msg << "data packet bytestreams hold " << total << " bytes, more than the packet length "
          << length;
      fail(msg.str(), at);
    }
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t n = u16(packet_.data() + 6 + 2 * i);
      decoders_[i].append(packet_.data() + pos, n);
      pos += n;
    }
    if (total > 6 + 2 * count) {
      barren_packets_ = 0;
      return;
    }
  }
}

void CompressedVectorReader::checkPacket(std::uint8_t type, std::size_t length, std::uint64_t at) {
  if (type > 2) fail("invalid packet type " + std::to_string(type), at);
  // docs/E57_FORMAT.md section 8: lengths are multiples of 4; an index packet has a 16-byte header,
  // a data packet 6 bytes before its buffers. A section of zeros fails here at once instead of
  // being walked as 1-byte packets.
  static const std::size_t kMinLength[3] = {16, 8, 4};
  if (length % 4 != 0 || length < kMinLength[type])
    fail("invalid " + std::string(type == 0 ? "index" : type == 1 ? "data" : "empty") +
             " packet length " + std::to_string(length) + " (packets are multiples of 4 bytes, at least " +
             std::to_string(kMinLength[type]) + ")", at);
  if (at + length > section_end_)
    fail("packet of " + std::to_string(length) + " bytes extends past the end of its section", at);
  // Packets without record bytes cost time but no memory: a run of them longer than any writer
  // produces (libE57Format writes one index packet per section) is a corrupted section.
  if (++barren_packets_ > kMaxBarrenPackets)
    fail(std::to_string(kMaxBarrenPackets) + " packets in a row carry no record bytes", at);
}

std::size_t CompressedVectorReader::read(std::vector<std::vector<double>>& columns,
                                         std::size_t max_records) {
  const std::size_t want =
      static_cast<std::size_t>(std::min<std::uint64_t>(max_records, record_count_ - records_read_));
  columns.resize(decoders_.size());
  if (want == 0) return 0;
  for (std::size_t f = 0; f < decoders_.size(); ++f)
    while (decoders_[f].available() < want) readNextPacket();
  for (std::size_t f = 0; f < decoders_.size(); ++f) {
    columns[f].resize(want);
    decoders_[f].decode(columns[f].data(), want);
  }
  records_read_ += want;
  return want;
}

}  // namespace plumb::e57
