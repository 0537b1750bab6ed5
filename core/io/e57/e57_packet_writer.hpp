#pragma once
// Writes one CompressedVector binary section (docs/E57_FORMAT.md §7-9): a 32-byte section header,
// then data packets of at most 64 KiB, each holding the same number R of records (R a multiple
// of 64, so every field's buffer is a whole number of 8-byte words and no value straddles two
// packets). Values are bit-packed LSB-first; the last packet pads each stream with zero bits
// to its word size. No index packet is written (indexPhysicalOffset = 0) and a 0-record
// section is one data packet with one empty buffer per field: both forms are read by
// libE57Format 3.x and by E57RefImpl-based tools (pitfall 8).
#include <cstdint>
#include <functional>
#include <vector>

#include "common/progress.hpp"
#include "io/e57/e57_page_writer.hpp"
#include "io/e57/e57_xml.hpp"

namespace plumb::e57 {

struct OutField {
  FieldSpec spec;  ///< name, type, limits/scale, precision (as written in the prototype)
  /// Integer/ScaledInteger: raw values of records [begin, begin+count), within [min, max].
  std::function<void(std::size_t begin, std::size_t count, std::int64_t* raw)> integers;
  /// Float: values of records [begin, begin+count).
  std::function<void(std::size_t begin, std::size_t count, double* values)> floats;
};

/// Writes the section at the writer's position (4-byte aligned) and returns its physical
/// offset (the XML `fileOffset`).
std::uint64_t writeCompressedVector(PagedWriter& out, const std::vector<OutField>& fields,
                                    std::uint64_t records, Progress* progress);

}  // namespace plumb::e57
