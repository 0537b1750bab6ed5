#pragma once
// A streaming decoder of LZF (the compression of PCD's binary_compressed data; format of
// Marc Lehmann's liblzf, which PCL embeds as pcl::lzfDecompress). PCL and liblzf decode a
// whole block into a whole buffer; this decoder hands out the output in pieces, holding only
// its last 8 KiB (the farthest an LZF back reference reaches) and a 64 KiB read window, so a
// PCD of any size is read in bounded memory (pcd_records.hpp). Written here because no
// packaged library decodes LZF incrementally.
//
// The format: a control byte c < 32 is followed by c + 1 literal bytes; otherwise it is a back
// reference of length (c >> 5) + 2 (with c >> 5 == 7, the next byte is added to the length)
// to the output ((c & 31) << 8 | next byte) + 1 bytes back.
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace plumb {

class LzfStream {
 public:
  /// Decodes the `size` compressed bytes at `begin` in the open file `fd` (`path`: for errors).
  LzfStream(int fd, std::filesystem::path path, std::uint64_t begin, std::uint64_t size);

  /// The next `n` output bytes into `out` (nullptr: decoded and dropped). Throws FileError
  /// (file, byte offset of the control byte) when the data ends first or is corrupt.
  void read(std::uint8_t* out, std::uint64_t n);

  /// Bytes handed out so far.
  std::uint64_t produced() const { return produced_; }
  /// True when every compressed byte was decoded and nothing is pending (PCL requires the
  /// whole block to decode to exactly the declared size).
  bool exhausted() const;

 private:
  static constexpr std::uint32_t kWindow = 8192;
  std::uint8_t nextInput();
  bool inputLeft() const { return consumed_ < size_; }
  void startOperation();
  [[noreturn]] void corrupt(const char* what) const;

  int fd_;
  std::filesystem::path path_;
  std::uint64_t begin_, size_;
  std::uint64_t consumed_ = 0;   ///< compressed bytes taken
  std::uint64_t op_start_ = 0;   ///< compressed offset of the current control byte
  std::vector<std::uint8_t> in_;
  std::size_t in_pos_ = 0, in_len_ = 0;
  std::array<std::uint8_t, kWindow> history_{};
  std::uint64_t produced_ = 0;
  std::uint32_t literal_left_ = 0, match_left_ = 0, match_distance_ = 0;
};

}  // namespace plumb
