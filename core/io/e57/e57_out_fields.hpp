#pragma once
// Building blocks of the writer's point prototype (e57_writer.cpp, e57_extension_fields.cpp):
// field specs and the Integer field of a whole column, its limits taken from the values.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "io/e57/e57_packet_writer.hpp"

namespace plumb::e57 {

/// Integer over [lo, hi], at least one bit per record (keeps counts checkable).
inline FieldSpec integerSpec(std::string name, std::int64_t lo, std::int64_t hi) {
  FieldSpec f;
  f.name = std::move(name);
  f.type = FieldType::Integer;
  f.minimum = lo;
  f.maximum = std::max(hi, lo + 1);
  return f;
}

inline FieldSpec floatSpec(std::string name, bool single) {
  FieldSpec f;
  f.name = std::move(name);
  f.type = FieldType::Float;
  f.single = single;
  return f;
}

/// Smallest and largest get(x) over v; (0, 0) when v is empty.
template <class V, class Get>
std::pair<std::int64_t, std::int64_t> rangeOf(const V& v, Get get) {
  std::int64_t lo = std::numeric_limits<std::int64_t>::max(), hi = std::numeric_limits<std::int64_t>::lowest();
  for (const auto& x : v) {
    const std::int64_t g = get(x);
    lo = std::min(lo, g);
    hi = std::max(hi, g);
  }
  if (v.empty()) lo = hi = 0;
  return {lo, hi};
}

/// The Integer field `name` of an integer column, limits from its values (stored in `range`
/// when given). The field keeps a reference to `values`.
template <class V>
OutField integerColumnField(std::string name, const V& values,
                            std::pair<std::int64_t, std::int64_t>* range = nullptr) {
  const auto r = rangeOf(values, [](auto v) { return static_cast<std::int64_t>(v); });
  if (range) *range = r;
  OutField f{integerSpec(std::move(name), r.first, r.second), {}, {}};
  f.integers = [&values](std::size_t begin, std::size_t count, std::int64_t* out) {
    for (std::size_t i = 0; i < count; ++i) out[i] = static_cast<std::int64_t>(values[begin + i]);
  };
  return f;
}

}  // namespace plumb::e57
