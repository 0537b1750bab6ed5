#pragma once
// Decoder of one bytestream of the bit-pack codec (docs/E57_FORMAT.md §9). Integer/ScaledInteger
// values of any width 0..64 bits are packed LSB-first as one continuous bit stream and decode
// to raw + minimum (times scale plus offset for ScaledInteger). Float streams are raw
// little-endian IEEE-754 (4 or 8 bytes). Packets append bytes as they arrive; buffers break
// at arbitrary byte boundaries, so a value may straddle two packets.
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "io/e57/e57_xml.hpp"

namespace plumb::e57 {

class FieldDecoder {
 public:
  explicit FieldDecoder(const FieldSpec& spec);

  /// Appends stream bytes (from one data packet).
  void append(const std::uint8_t* data, std::size_t n);
  /// Number of whole values that can be decoded now (max() for 0-bit fields).
  std::uint64_t available() const {
    if (bits_ == 0) return std::numeric_limits<std::uint64_t>::max();
    return (static_cast<std::uint64_t>(end_) * 8 - bit_pos_) / bits_;
  }
  /// Bytes buffered and not yet consumed.
  std::size_t pendingBytes() const { return end_ - static_cast<std::size_t>(bit_pos_ / 8); }
  /// Decodes `count` values into out. Precondition: count <= available().
  void decode(double* out, std::size_t count);
  unsigned bits() const { return bits_; }

 private:
  void compact();

  FieldType type_;
  unsigned bits_;
  std::int64_t minimum_;
  double scale_, offset_;
  std::vector<std::uint8_t> buffer_;  ///< bytes [0, end_) valid, followed by 16 zero bytes
  std::size_t end_ = 0;
  std::uint64_t bit_pos_ = 0;  ///< next bit to read
};

}  // namespace plumb::e57
