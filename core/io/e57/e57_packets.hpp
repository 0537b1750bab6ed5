#pragma once
// Reads the records of one CompressedVector binary section (docs/E57_FORMAT.md §7-8): validates the
// 32-byte section header, walks the packets (data / index / empty) in the logical stream, and
// feeds every data packet's buffers to one FieldDecoder per prototype field. Memory stays
// bounded: only the bytes not yet decoded are buffered, and the record count is checked
// against the section size before anything is allocated.
#include <cstdint>
#include <string>
#include <vector>

#include "io/e57/e57_bitpack.hpp"
#include "io/e57/e57_pages.hpp"
#include "io/e57/e57_xml.hpp"

namespace plumb::e57 {

class CompressedVectorReader {
 public:
  /// Throws FileError if the section header is invalid or inconsistent with the file.
  CompressedVectorReader(PagedReader& file, const ScanInfo& scan);

  std::uint64_t recordCount() const { return record_count_; }
  std::uint64_t recordsRead() const { return records_read_; }

  /// Decodes up to `max_records` next records: columns[f][i] is field f of record i (columns
  /// are resized to the count). Returns the number decoded, 0 once all were read.
  std::size_t read(std::vector<std::vector<double>>& columns, std::size_t max_records);

 private:
  void readNextPacket();  ///< appends one data packet's buffers (skips index/empty packets)
  /// Type, length and bounds of the packet at logical `at`; counts packets without record bytes.
  void checkPacket(std::uint8_t type, std::size_t length, std::uint64_t at);
  [[noreturn]] void fail(const std::string& message, std::uint64_t logical) const;

  PagedReader& file_;
  std::string path_;
  std::vector<FieldDecoder> decoders_;
  std::uint64_t record_count_ = 0;
  std::uint64_t records_read_ = 0;
  std::uint64_t section_start_ = 0;  ///< logical
  std::uint64_t section_end_ = 0;    ///< logical, exclusive
  std::uint64_t next_packet_ = 0;    ///< logical
  std::vector<std::uint8_t> packet_;
  std::uint32_t barren_packets_ = 0;  ///< packets in a row that delivered no record bytes
};

}  // namespace plumb::e57
