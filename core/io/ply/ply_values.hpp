#pragma once
// Typed access to PLY binary values (internal to io/ply).
#include <bit>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "io/ply/ply_header.hpp"

namespace plumb::ply {

template <class T>
inline T byteSwap(T v) {
  if constexpr (sizeof(T) == 1) {
    return v;
  } else {
    using U = std::conditional_t<sizeof(T) == 2, std::uint16_t,
                                 std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>;
    U u;
    std::memcpy(&u, &v, sizeof u);
    if constexpr (sizeof(T) == 2) u = __builtin_bswap16(u);
    else if constexpr (sizeof(T) == 4) u = __builtin_bswap32(u);
    else u = __builtin_bswap64(u);
    std::memcpy(&v, &u, sizeof u);
    return v;
  }
}

template <class T, bool Swap>
inline T load(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  if constexpr (Swap) v = byteSwap(v);
  return v;
}

template <class T, bool Swap>
inline void store(char* p, T v) {
  if constexpr (Swap) v = byteSwap(v);
  std::memcpy(p, &v, sizeof v);
}

/// Calls f(T{}) with the C++ type of a PLY type.
template <class F>
inline decltype(auto) withType(Type t, F&& f) {
  switch (t) {
    case Type::Int8: return f(std::int8_t{});
    case Type::UInt8: return f(std::uint8_t{});
    case Type::Int16: return f(std::int16_t{});
    case Type::UInt16: return f(std::uint16_t{});
    case Type::Int32: return f(std::int32_t{});
    case Type::UInt32: return f(std::uint32_t{});
    case Type::Float32: return f(float{});
    case Type::Float64: break;
  }
  return f(double{});
}

template <bool Swap>
inline double loadAsDouble(Type t, const char* p) {
  return withType(t, [p](auto tag) { return static_cast<double>(load<decltype(tag), Swap>(p)); });
}

}  // namespace plumb::ply
