#include "io/e57/e57_packet_writer.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace plumb::e57 {
namespace {

constexpr std::size_t kPacketTarget = 60000;  // bytes, below the 64 KiB limit

void put16(std::uint8_t* p, std::size_t v) {
  p[0] = static_cast<std::uint8_t>(v);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
void put64(std::uint8_t* p, std::uint64_t v) { std::memcpy(p, &v, 8); }

// Bytes of the smallest 8/16/32/64-bit word holding `bits` (the codec's word size).
std::size_t wordBytes(unsigned bits) {
  return bits <= 8 ? 1 : bits <= 16 ? 2 : bits <= 32 ? 4 : 8;
}

// Packs `count` values of `bits` bits LSB-first into dst; returns bytes written (whole bytes,
// last byte zero-padded).
std::size_t packBits(const std::uint64_t* values, std::size_t count, unsigned bits, std::uint8_t* dst) {
  std::uint8_t* p = dst;
  std::uint64_t acc = 0;
  unsigned nacc = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint64_t v = values[i];
    acc |= v << nacc;
    const unsigned total = nacc + bits;
    if (total >= 64) {
      std::memcpy(p, &acc, 8);
      p += 8;
      acc = nacc ? v >> (64 - nacc) : 0;
      nacc = total - 64;
    } else {
      nacc = total;
    }
  }
  const std::size_t tail = (nacc + 7) / 8;
  std::memcpy(p, &acc, tail);
  return static_cast<std::size_t>(p - dst) + tail;
}

/// Records per data packet and the packet header's size for a prototype.
struct PacketPlan {
  std::size_t header = 0;      ///< bytes: 6 + 2 per bytestream length
  std::size_t per_packet = 0;  ///< records, a multiple of 64
};

PacketPlan planPackets(const std::vector<OutField>& fields) {
  const std::size_t nf = fields.size();
  std::size_t bits_per_record = 0;
  for (const auto& f : fields) bits_per_record += f.spec.bits();
  PacketPlan plan;
  plan.header = 6 + 2 * nf;
  std::size_t per_packet = bits_per_record == 0
                               ? 65536
                               : (kPacketTarget - plan.header - 8 * nf) * 8 / bits_per_record;
  per_packet = std::max<std::size_t>(64, per_packet / 64 * 64);
  if (plan.header + per_packet * bits_per_record / 8 + 8 * nf > 65536)
    throw std::logic_error("E57 writer: too many bits per record for one packet");
  plan.per_packet = per_packet;
  return plan;
}

/// The packet being assembled and the per-field value buffers of one packet's records.
struct PacketBuffers {
  explicit PacketBuffers(std::size_t per_packet)
      : packet(65536 + 64), raw(per_packet), rel(per_packet), values(per_packet) {}
  std::vector<std::uint8_t> packet;
  std::vector<std::int64_t> raw;
  std::vector<std::uint64_t> rel;
  std::vector<double> values;
};

/// Writes the bytestream of `field` for records [done, done + n) at dst; returns its length.
/// In the `last` packet an Integer stream is padded with zero bits to its word size.
std::size_t fieldBytestream(const OutField& field, std::uint64_t done, std::size_t n, bool last,
                            PacketBuffers& b, std::uint8_t* dst) {
  const FieldSpec& s = field.spec;
  const unsigned bits = s.bits();
  if (n == 0 || bits == 0) return 0;
  if (s.type == FieldType::Float) {
    field.floats(static_cast<std::size_t>(done), n, b.values.data());
    if (s.single) {
      for (std::size_t i = 0; i < n; ++i) {
        const auto v = static_cast<float>(b.values[i]);
        std::memcpy(dst + 4 * i, &v, 4);
      }
      return 4 * n;
    }
    std::memcpy(dst, b.values.data(), 8 * n);
    return 8 * n;
  }
  field.integers(static_cast<std::size_t>(done), n, b.raw.data());
  const auto minimum = static_cast<std::uint64_t>(s.minimum);
  for (std::size_t i = 0; i < n; ++i) b.rel[i] = static_cast<std::uint64_t>(b.raw[i]) - minimum;
  std::size_t len = packBits(b.rel.data(), n, bits, dst);
  if (last) {  // fill the stream's last word with zero bits
    const std::size_t w = wordBytes(bits);
    const std::size_t padded = (len + w - 1) / w * w;
    std::memset(dst + len, 0, padded - len);
    len = padded;
  }
  return len;
}

/// Assembles in b.packet the data packet of records [done, done + n); returns its size,
/// padded to 4 bytes.
std::size_t dataPacket(const std::vector<OutField>& fields, std::size_t header, std::uint64_t done,
                       std::size_t n, bool last, PacketBuffers& b) {
  const std::size_t nf = fields.size();
  std::uint8_t* packet = b.packet.data();
  std::size_t pos = header;
  packet[0] = 1;  // data packet
  packet[1] = 0;
  put16(packet + 4, nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::size_t len = fieldBytestream(fields[f], done, n, last, b, packet + pos);
    put16(packet + 6 + 2 * f, len);
    pos += len;
  }
  const std::size_t padded = (pos + 3) / 4 * 4;
  std::memset(packet + pos, 0, padded - pos);
  put16(packet + 2, padded - 1);
  return padded;
}

}  // namespace

std::uint64_t writeCompressedVector(PagedWriter& out, const std::vector<OutField>& fields,
                                    std::uint64_t records, Progress* progress) {
  if (fields.empty()) throw std::logic_error("E57 writer: empty prototype");
  const std::uint64_t section_logical = out.logicalPosition();
  const std::uint64_t section_physical = out.physicalPosition();
  out.retain(section_logical, 32);
  out.writeZeros(32);  // patched below

  const PacketPlan plan = planPackets(fields);
  PacketBuffers buffers(plan.per_packet);
  const std::uint64_t data_physical = out.physicalPosition();

  std::uint64_t done = 0;
  do {
    checkCanceled(progress);
    const auto n = static_cast<std::size_t>(std::min<std::uint64_t>(plan.per_packet, records - done));
    const bool last = done + n == records;
    const std::size_t size = dataPacket(fields, plan.header, done, n, last, buffers);
    out.write(buffers.packet.data(), size);
    done += n;
    if (records) reportProgress(progress, static_cast<double>(done) / records, "writing E57 points");
  } while (done < records);

  std::uint8_t h[32] = {};
  h[0] = 1;  // CompressedVector section
  put64(h + 8, out.logicalPosition() - section_logical);
  put64(h + 16, data_physical);
  put64(h + 24, 0);  // no index packet (pitfall 8)
  out.patch(section_logical, h, sizeof h);
  return section_physical;
}

}  // namespace plumb::e57
