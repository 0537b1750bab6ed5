#pragma once
// Copies fields of fixed-size binary records into columns unchanged: the field's bytes in the
// file are the value's bytes in memory (same type and byte order, consecutive components).
// This is the inner loop of the binary PLY reader (a 10M-point file with x y z float,
// red green blue uchar and intensity float is 30M such copies).
#include <cstddef>
#include <vector>

namespace plumb::ply {

/// Bytes [src, src + bytes) of record i go to dst + i * bytes. bytes is 3, 4 or 12 (RGB,
/// a float, three floats).
struct FieldCopy {
  std::size_t src = 0;
  char* dst = nullptr;
  std::size_t bytes = 0;
};

class RecordCopier {
 public:
  /// `fused` false forces one pass per field (the reference the fused passes are tested
  /// against).
  RecordCopier(std::size_t stride, std::vector<FieldCopy> fields, bool fused = true);

  /// Copies records [0, k) of the block at p into the columns at records [base, base + k).
  /// Reads only the block's k * stride bytes and writes only those records' values, so
  /// threads may copy neighbouring blocks at once.
  void run(const char* p, std::size_t k, std::size_t base) const;

  /// True when one pass per record copies every field (the common layouts: positions, then
  /// optional normals, colours and up to two floats).
  bool fused() const { return kernel_ != nullptr; }

  using Kernel = void (*)(const char* p, std::size_t k, std::size_t stride, const FieldCopy* fields,
                          std::size_t base);

 private:
  std::size_t stride_;
  std::vector<FieldCopy> fields_;
  Kernel kernel_ = nullptr;
};

}  // namespace plumb::ply
