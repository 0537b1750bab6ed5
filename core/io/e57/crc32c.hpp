#pragma once
// CRC-32C (Castagnoli), as used for E57 page checksums (docs/E57_FORMAT.md §3): reflected polynomial
// 0x82F63B78, init 0xFFFFFFFF, final XOR 0xFFFFFFFF; check value of "123456789" is 0xE3069283.
// Two implementations that must agree: the SSE4.2 `crc32` instruction (used when the CPU has
// it, detected at run time) and a portable slicing-by-8 table.
#include <cstddef>
#include <cstdint>

namespace plumb::e57 {

/// CRC-32C of `size` bytes with the fastest implementation available on this CPU.
std::uint32_t crc32c(const void* data, std::size_t size);
/// Portable table implementation.
std::uint32_t crc32cTable(const void* data, std::size_t size);
/// True when the CPU supports SSE4.2 (so crc32cHardware may be called).
bool crc32cHardwareAvailable();
/// SSE4.2 implementation. Precondition: crc32cHardwareAvailable().
std::uint32_t crc32cHardware(const void* data, std::size_t size);

}  // namespace plumb::e57
