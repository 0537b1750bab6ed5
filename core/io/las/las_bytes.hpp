#pragma once
// Little-endian loads and stores for LAS records. LAS is little-endian and so are the hosts
// Plumb supports; the static_assert keeps it honest.
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>

namespace plumb::las {

static_assert(std::endian::native == std::endian::little, "LAS I/O assumes a little-endian host");

template <class T>
inline T load(const std::uint8_t* p) {
  T v;
  std::memcpy(&v, p, sizeof(T));
  return v;
}

template <class T>
inline void store(std::uint8_t* p, T v) {
  std::memcpy(p, &v, sizeof(T));
}

/// A fixed char[n] field: NUL-padded, or completely full without terminator.
inline std::string loadText(const std::uint8_t* p, std::size_t n) {
  std::size_t len = 0;
  while (len < n && p[len] != 0) ++len;
  return std::string(reinterpret_cast<const char*>(p), len);
}

inline void storeText(std::uint8_t* p, std::size_t n, const std::string& s) {
  std::memset(p, 0, n);
  std::memcpy(p, s.data(), s.size() < n ? s.size() : n);
}

}  // namespace plumb::las
