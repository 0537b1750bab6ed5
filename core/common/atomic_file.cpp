#include "common/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <string>
#include <system_error>

#include "common/error.hpp"
#include "common/temp_file_registry.hpp"

namespace plumb {
namespace {

std::filesystem::path temporaryFor(const std::filesystem::path& target) {
  static std::atomic<unsigned> counter{0};
  auto name = "." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) + "-" +
              std::to_string(counter++);
  return target.parent_path() / name;
}
constexpr std::size_t kBufferSize = 1 << 20;

/// `p` with every symlink in its last component followed (a dangling link gives the path it
/// points to, which is then created).
std::filesystem::path followLinks(std::filesystem::path p) {
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(p, ec))) return p;
    const std::filesystem::path to = std::filesystem::read_symlink(p, ec);
    if (ec) return p;
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  throw FileError(p, "too many levels of symbolic links");
}

std::string directoryOf(const std::filesystem::path& p) {
  return p.parent_path().empty() ? std::string(".") : p.parent_path().string();
}

/// Refuses what cannot be replaced; returns the existing file's mode, or -1 for a new file.
int checkReplaceable(const std::filesystem::path& shown, const std::filesystem::path& file) {
  if (shown.filename().empty()) throw FileError(shown, "not a file name");
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return -1;
  if (S_ISDIR(st.st_mode)) throw FileError(shown, "is a directory, cannot write a file there");
  // The write bits decide even for root, who may write anything: a read-only file is meant
  // to stay as it is.
  if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0 || ::access(file.c_str(), W_OK) != 0)
    throw FileError(shown, "is read-only; not replacing it (make it writable or choose another name)");
  return static_cast<int>(st.st_mode & 07777);
}

/// fsync of a path (a written file or a directory); false on failure.
bool syncPath(const std::filesystem::path& p, int flags) {
  const int fd = ::open(p.c_str(), flags | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  ::close(fd);
  return ok;
}

void onSignal(int sig) {
  temp_files::unlinkAll();
  std::signal(sig, SIG_DFL);
  std::raise(sig);  // pending until the handler returns, then the default action
}

}  // namespace

AtomicFileWriter::AtomicFileWriter(std::filesystem::path target)
    : target_(std::move(target)), resolved_(followLinks(target_)), temp_(temporaryFor(resolved_)),
      buffer_(new char[kBufferSize]) {
  checkReplaceable(target_, resolved_);
  out_.rdbuf()->pubsetbuf(buffer_.get(), kBufferSize);
  slot_ = temp_files::add(temp_.c_str());
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    temp_files::remove(slot_);
    throw FileError(target_, "cannot create a file in directory '" + directoryOf(resolved_) + "'");
  }
}

AtomicFileWriter::~AtomicFileWriter() {
  if (!committed_) {
    out_.close();
    std::error_code ec;
    std::filesystem::remove(temp_, ec);
  }
  temp_files::remove(slot_);
}

void AtomicFileWriter::commit() {
  out_.flush();
  const bool ok = static_cast<bool>(out_);
  out_.close();
  if (!ok || out_.fail()) throw FileError(target_, "write failed (disk full or I/O error)");
  const int mode = checkReplaceable(target_, resolved_);
  if (mode >= 0 && ::chmod(temp_.c_str(), static_cast<mode_t>(mode)) != 0)
    throw FileError(target_, "cannot give the new file the permissions of the old one");
  if (!syncPath(temp_, O_RDONLY)) throw FileError(target_, "cannot flush the data to disk (fsync)");
  std::error_code ec;
  std::filesystem::rename(temp_, resolved_, ec);
  if (ec) throw FileError(target_, "cannot replace the file: " + ec.message());
  committed_ = true;
  temp_files::remove(slot_);
  slot_ = -1;
  if (!syncPath(directoryOf(resolved_), O_RDONLY | O_DIRECTORY))
    throw FileError(target_, "written, but its directory could not be flushed to disk (fsync)");
}

void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(std::ostream&)>& write) {
  AtomicFileWriter writer(target);
  write(writer.stream());
  writer.commit();
}

void checkWritableTarget(const std::filesystem::path& target) {
  const std::filesystem::path file = followLinks(target);
  checkReplaceable(target, file);
  const std::string dir = directoryOf(file);
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
    throw FileError(target, "cannot create a file in directory '" + dir + "'");
}

void removeTemporaryFilesOnSignals() {
  struct sigaction sa {};
  sa.sa_handler = onSignal;
  sigemptyset(&sa.sa_mask);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(sig, &sa, nullptr);
}

}  // namespace plumb
