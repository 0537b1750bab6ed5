#include "io/e57/crc32c.hpp"

#include <array>
#include <cstring>

#if defined(__x86_64__) || defined(__i386__)
#include <nmmintrin.h>
#define PLUMB_E57_HAVE_X86 1
#endif

namespace plumb::e57 {
namespace {

constexpr std::uint32_t kPolynomial = 0x82F63B78u;  // reflected 0x1EDC6F41

// tables[k][b]: CRC of byte b followed by k zero bytes (slicing-by-8).
struct Tables {
  std::array<std::array<std::uint32_t, 256>, 8> t{};
  Tables() {
    for (std::uint32_t b = 0; b < 256; ++b) {
      std::uint32_t c = b;
      for (int k = 0; k < 8; ++k) c = (c >> 1) ^ ((c & 1u) ? kPolynomial : 0u);
      t[0][b] = c;
    }
    for (std::uint32_t b = 0; b < 256; ++b)
      for (int k = 1; k < 8; ++k) t[k][b] = (t[k - 1][b] >> 8) ^ t[0][t[k - 1][b] & 0xFFu];
  }
};
const Tables& tables() {
  static const Tables instance;
  return instance;
}

}  // namespace

std::uint32_t crc32cTable(const void* data, std::size_t size) {
  const auto& t = tables().t;
  const auto* p = static_cast<const std::uint8_t*>(data);
  std::uint32_t crc = 0xFFFFFFFFu;
  while (size >= 8) {
    std::uint32_t lo;
    std::uint32_t hi;
    std::memcpy(&lo, p, 4);  // little-endian host assumed (x86, ARM): E57 is LE anyway
    std::memcpy(&hi, p + 4, 4);
    lo ^= crc;
    crc = t[7][lo & 0xFF] ^ t[6][(lo >> 8) & 0xFF] ^ t[5][(lo >> 16) & 0xFF] ^ t[4][lo >> 24] ^
          t[3][hi & 0xFF] ^ t[2][(hi >> 8) & 0xFF] ^ t[1][(hi >> 16) & 0xFF] ^ t[0][hi >> 24];
    p += 8;
    size -= 8;
  }
  while (size--) crc = (crc >> 8) ^ t[0][(crc ^ *p++) & 0xFFu];
  return crc ^ 0xFFFFFFFFu;
}

#ifdef PLUMB_E57_HAVE_X86
bool crc32cHardwareAvailable() {
  static const bool available = __builtin_cpu_supports("sse4.2");
  return available;
}

__attribute__((target("sse4.2"))) std::uint32_t crc32cHardware(const void* data,
                                                                 std::size_t size) {
  const auto* p = static_cast<const std::uint8_t*>(data);
  std::uint64_t crc = 0xFFFFFFFFu;
#if defined(__x86_64__)
  while (size >= 8) {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    crc = _mm_crc32_u64(crc, v);
    p += 8;
    size -= 8;
  }
#endif
  auto c = static_cast<std::uint32_t>(crc);
  while (size--) c = _mm_crc32_u8(c, *p++);
  return c ^ 0xFFFFFFFFu;
}
#else
bool crc32cHardwareAvailable() { return false; }
std::uint32_t crc32cHardware(const void* data, std::size_t size) {
  return crc32cTable(data, size);
}
#endif

std::uint32_t crc32c(const void* data, std::size_t size) {
  return crc32cHardwareAvailable() ? crc32cHardware(data, size) : crc32cTable(data, size);
}

}  // namespace plumb::e57
