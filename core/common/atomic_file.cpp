#include "common/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <string>
#include <system_error>

#include "common/error.hpp"

namespace plumb {
namespace {
std::filesystem::path temporaryFor(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  auto name = "." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
              std::to_string(counter++);
  return target.parent_path() / name;
}
constexpr std::size_t kBufferSize = 1 << 20;
}  // namespace

AtomicFileWriter::AtomicFileWriter(std::filesystem::path target)
    : target_(std::move(target)), temp_(temporaryFor(target_)),
      buffer_(new char[kBufferSize]) {
  if (target_.filename().empty()) throw FileError(target_, "not a file name");
  if (std::filesystem::is_directory(target_))
    throw FileError(target_, "is a directory, cannot write a file there");
  out_.rdbuf()->pubsetbuf(buffer_.get(), kBufferSize);
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_)
    throw FileError(target_, "cannot create a file in directory '" +
                                 (target_.parent_path().empty() ? std::string(".")
                                                                : target_.parent_path().string()) +
                                 "'");
}

AtomicFileWriter::~AtomicFileWriter() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
  }
}

void AtomicFileWriter::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || out_.fail()) throw FileError(target_, "write failed (disk full or I/O error)");
  std::error_code ec;
  std::filesystem::rename(temp_, target_, ec);
  if (ec) throw FileError(target_, "cannot replace the file: " + ec.message());
  committed_ = true;
}

void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(std::ostream&)>& write) {
  AtomicFileWriter writer(target);
  write(writer.stream());
  writer.commit();
}

}  // namespace plumb
