#include "io/e57/e57_bitpack.hpp"

#include <cstring>

namespace plumb::e57 {
namespace {
constexpr std::size_t kSlack = 16;  // zero bytes after the data so 8-byte loads never overrun

inline std::uint64_t load64(const std::uint8_t* p) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  return v;  // little-endian host
}

// Raw (unsigned, minimum-relative) value of `bits` bits starting at bit `pos`.
inline std::uint64_t extract(const std::uint8_t* base, std::uint64_t pos, unsigned bits) {
  const std::uint8_t* p = base + (pos >> 3);
  const unsigned shift = static_cast<unsigned>(pos & 7);
  std::uint64_t v = load64(p) >> shift;
  if (bits + shift > 64) v |= load64(p + 8) << (64 - shift);  // only for bits > 56
  return bits == 64 ? v : v & ((std::uint64_t{1} << bits) - 1);
}
}  // namespace

FieldDecoder::FieldDecoder(const FieldSpec& spec)
    : type_(spec.type), bits_(spec.bits()), minimum_(spec.minimum), scale_(spec.scale),
      offset_(spec.offset) {
  buffer_.assign(kSlack, 0);
}

void FieldDecoder::compact() {
  const std::size_t consumed = static_cast<std::size_t>(bit_pos_ / 8);
  if (consumed == 0) return;
  std::memmove(buffer_.data(), buffer_.data() + consumed, end_ - consumed);
  end_ -= consumed;
  bit_pos_ -= static_cast<std::uint64_t>(consumed) * 8;
}

void FieldDecoder::append(const std::uint8_t* data, std::size_t n) {
  if (n == 0) return;
  if (bit_pos_ / 8 >= end_ / 2) compact();
  if (buffer_.size() < end_ + n + kSlack) buffer_.resize(end_ + n + kSlack);
  std::memcpy(buffer_.data() + end_, data, n);
  end_ += n;
  std::memset(buffer_.data() + end_, 0, kSlack);
}

void FieldDecoder::decode(double* out, std::size_t count) {
  if (bits_ == 0) {  // min == max: nothing stored, every value is the minimum
    const double v = type_ == FieldType::ScaledInteger
                         ? static_cast<double>(minimum_) * scale_ + offset_
                         : static_cast<double>(minimum_);
    for (std::size_t i = 0; i < count; ++i) out[i] = v;
    return;
  }
  const std::uint8_t* base = buffer_.data();
  std::uint64_t pos = bit_pos_;
  switch (type_) {
    case FieldType::Float:
      if (bits_ == 32) {
        const std::uint8_t* p = base + (pos >> 3);  // Float streams stay byte-aligned
        for (std::size_t i = 0; i < count; ++i) {
          float f;
          std::memcpy(&f, p + 4 * i, 4);
          out[i] = f;
        }
      } else {
        std::memcpy(out, base + (pos >> 3), count * 8);
      }
      pos += static_cast<std::uint64_t>(count) * bits_;
      break;
    case FieldType::Integer:
    case FieldType::ScaledInteger: {
      const double scale = type_ == FieldType::ScaledInteger ? scale_ : 1.0;
      const double offset = type_ == FieldType::ScaledInteger ? offset_ : 0.0;
      const auto minimum = static_cast<std::int64_t>(minimum_);
      if ((bits_ == 8 || bits_ == 16) && (pos & 7) == 0) {  // byte-aligned (colours...)
        const double base_value = static_cast<double>(minimum) * scale + offset;
        const std::uint8_t* p = base + (pos >> 3);
        if (bits_ == 8) {
          for (std::size_t i = 0; i < count; ++i) out[i] = p[i] * scale + base_value;
        } else {
          for (std::size_t i = 0; i < count; ++i) out[i] = (p[2 * i] | (p[2 * i + 1] << 8)) * scale + base_value;
        }
        pos += static_cast<std::uint64_t>(count) * bits_;
      } else if (bits_ <= 56) {  // one unaligned load per value (the common case)
        const std::uint64_t mask = (std::uint64_t{1} << bits_) - 1;
        if (bits_ <= 52 && minimum >= -(std::int64_t{1} << 52) && minimum <= (std::int64_t{1} << 52)) {
          // raw and raw + minimum are exact in double: add in floating point.
          const double dmin = static_cast<double>(minimum);
          for (std::size_t i = 0; i < count; ++i, pos += bits_) {
            const std::uint64_t v = (load64(base + (pos >> 3)) >> (pos & 7)) & mask;
            out[i] = (static_cast<double>(static_cast<std::int64_t>(v)) + dmin) * scale + offset;
          }
        } else {
          for (std::size_t i = 0; i < count; ++i, pos += bits_) {
            const std::uint64_t v = (load64(base + (pos >> 3)) >> (pos & 7)) & mask;
            out[i] = static_cast<double>(static_cast<std::int64_t>(v + static_cast<std::uint64_t>(minimum))) *
                         scale + offset;
          }
        }
      } else {
        for (std::size_t i = 0; i < count; ++i, pos += bits_)
          out[i] = static_cast<double>(static_cast<std::int64_t>(extract(base, pos, bits_) +
                                                                 static_cast<std::uint64_t>(minimum))) *
                       scale + offset;
      }
      break;
    }
  }
  bit_pos_ = pos;
}

}  // namespace plumb::e57
