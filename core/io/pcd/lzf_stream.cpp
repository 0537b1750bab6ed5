#include "io/pcd/lzf_stream.hpp"

#include <algorithm>
#include <string>

#include "common/error.hpp"
#include "io/pcd/positioned_read.hpp"

namespace plumb {

LzfStream::LzfStream(int fd, std::filesystem::path path, std::uint64_t begin, std::uint64_t size)
    : fd_(fd), path_(std::move(path)), begin_(begin), size_(size), in_(std::size_t{1} << 16) {}

void LzfStream::corrupt(const char* what) const {
  throw FileError(path_, std::string("corrupt binary_compressed data: ") + what,
                  atByte(begin_ + op_start_, "LZF block byte " + std::to_string(op_start_)));
}

std::uint8_t LzfStream::nextInput() {
  if (in_pos_ == in_len_) {
    in_len_ = static_cast<std::size_t>(std::min<std::uint64_t>(in_.size(), size_ - consumed_));
    readFileAt(fd_, path_, begin_ + consumed_, in_.data(), in_len_, "binary_compressed block");
    in_pos_ = 0;
  }
  ++consumed_;
  return in_[in_pos_++];
}

void LzfStream::startOperation() {
  op_start_ = consumed_;
  const std::uint32_t c = nextInput();
  if (c < 32) {
    literal_left_ = c + 1;
    if (size_ - consumed_ < literal_left_) corrupt("a literal run goes past the end of the block");
    return;
  }
  std::uint32_t length = c >> 5;
  if (!inputLeft()) corrupt("a back reference is cut by the end of the block");
  if (length == 7) {
    length += nextInput();
    if (!inputLeft()) corrupt("a back reference is cut by the end of the block");
  }
  match_distance_ = (((c & 31u) << 8) | nextInput()) + 1;
  if (match_distance_ > produced_) corrupt("a back reference points before the start of the output");
  match_left_ = length + 2;
}

void LzfStream::read(std::uint8_t* out, std::uint64_t n) {
  while (n > 0) {
    if (literal_left_ == 0 && match_left_ == 0) {
      if (!inputLeft())
        throw FileError(path_, "corrupt binary_compressed data: the block decodes to " + std::to_string(produced_) +
                                   " bytes, fewer than its points need",
                        atByte(begin_ + size_, "binary_compressed block"));
      startOperation();
    }
    std::uint8_t b;
    if (literal_left_ > 0) {
      b = nextInput();
      --literal_left_;
    } else {
      b = history_[(produced_ - match_distance_) % kWindow];
      --match_left_;
    }
    history_[produced_ % kWindow] = b;
    ++produced_;
    if (out) *out++ = b;
    --n;
  }
}

bool LzfStream::exhausted() const { return !inputLeft() && literal_left_ == 0 && match_left_ == 0; }

}  // namespace plumb
