#include "io/pcd/pcd_records.hpp"

#include <cstring>

#include "common/error.hpp"
#include "io/pcd/lzf_stream.hpp"
#include "io/pcd/positioned_read.hpp"

namespace plumb {
namespace {

/// PCL's datatype code for a header TYPE and SIZE; 0 when ours has none.
std::uint8_t datatypeOf(char type, int size) {
  if (type == 'F') return size == 4 ? pcd_type::kFloat32 : size == 8 ? pcd_type::kFloat64 : 0;
  const bool s = type == 'I';
  switch (size) {
    case 1: return s ? pcd_type::kInt8 : pcd_type::kUint8;
    case 2: return s ? pcd_type::kInt16 : pcd_type::kUint16;
    case 4: return s ? pcd_type::kInt32 : pcd_type::kUint32;
    default: return 0;
  }
}

class BinaryRecords final : public PcdRecordSource {
 public:
  BinaryRecords(int fd, const std::filesystem::path& path, std::uint64_t data_offset, std::uint32_t step)
      : fd_(fd), path_(path), at_(data_offset), step_(step) {}
  void next(std::uint64_t n, std::uint8_t* out) override {
    readFileAt(fd_, path_, at_, out, n * step_, "data");
    at_ += n * step_;
  }

 private:
  int fd_;
  std::filesystem::path path_;
  std::uint64_t at_;
  std::uint32_t step_;
};

/// binary_compressed: field f's values start at points x (bytes of the fields before f) in the
/// uncompressed block; each field's decoder skips there on its first chunk.
class CompressedRecords final : public PcdRecordSource {
 public:
  CompressedRecords(int fd, const std::filesystem::path& path, const PcdHeader& header, const PcdLayout& layout)
      : layout_(layout), path_(path) {
    std::uint32_t sizes[2];
    readFileAt(fd, path, header.data_offset, reinterpret_cast<std::uint8_t*>(sizes), sizeof sizes, "data");
    block_end_ = header.data_offset + 8 + sizes[0];
    std::uint64_t start = 0;  // checkPcdFile checked sizes[1] == points x record size
    for (const auto& f : layout.fields) {
      const std::uint64_t bytes = std::uint64_t{pcd_type::size(f.datatype)} * f.count;
      fields_.push_back({std::make_unique<LzfStream>(fd, path, header.data_offset + 8, sizes[0]), start, bytes});
      start += bytes * layout.points();
    }
  }
  void next(std::uint64_t n, std::uint8_t* out) override {
    for (std::size_t k = 0; k < fields_.size(); ++k) {
      Field& f = fields_[k];
      if (f.decoder->produced() < f.start) f.decoder->read(nullptr, f.start - f.decoder->produced());
      column_.resize(n * f.bytes);
      f.decoder->read(column_.data(), column_.size());
      const std::uint32_t offset = layout_.fields[k].offset;
      for (std::uint64_t i = 0; i < n; ++i)
        std::memcpy(out + i * layout_.point_step + offset, column_.data() + i * f.bytes, f.bytes);
    }
  }
  void finish() override {
    if (!fields_.empty() && !fields_.back().decoder->exhausted())
      throw FileError(path_, "corrupt binary_compressed data: the block decodes to more bytes than its points need",
                      atByte(block_end_, "binary_compressed block"));
  }

 private:
  struct Field {
    std::unique_ptr<LzfStream> decoder;
    std::uint64_t start, bytes;
  };
  PcdLayout layout_;
  std::vector<Field> fields_;
  std::vector<std::uint8_t> column_;
  std::filesystem::path path_;
  std::uint64_t block_end_ = 0;
};

}  // namespace

std::optional<PcdLayout> layoutOfHeader(const PcdHeader& h) {
  PcdLayout l;
  l.width = static_cast<std::uint32_t>(h.width);
  l.height = static_cast<std::uint32_t>(h.height);
  std::uint32_t offset = 0;  // checkPcdFile bounded the record size to 1 MiB
  for (std::size_t i = 0; i < h.fields.size(); ++i) {
    const std::uint8_t type = datatypeOf(h.types[i], h.sizes[i]);
    if (type == 0) return std::nullopt;
    l.fields.push_back({h.fields[i], offset, type, static_cast<std::uint32_t>(h.counts[i])});
    offset += static_cast<std::uint32_t>(h.sizes[i] * h.counts[i]);
  }
  l.point_step = offset;
  l.viewpoint = h.viewpoint;
  return l;
}

bool recordsStream(const PcdHeader& header, const PcdLayout& layout) {
  if (header.data == "binary") return true;
  if (header.data != "binary_compressed") return false;
  for (const auto& f : layout.fields)
    if (f.name == "_") return false;  // PCL leaves padding out of the block: read whole
  return true;
}

std::unique_ptr<PcdRecordSource> openRecordSource(int fd, const std::filesystem::path& path,
                                                  const PcdHeader& header, const PcdLayout& layout) {
  if (!recordsStream(header, layout)) return nullptr;
  if (header.data == "binary") return std::make_unique<BinaryRecords>(fd, path, header.data_offset, layout.point_step);
  return std::make_unique<CompressedRecords>(fd, path, header, layout);
}

}  // namespace plumb
