#pragma once
// Atomic file writes: data goes to a temporary file beside the target, which is renamed over
// the target only when everything was written and flushed. A failed or cancelled export never
// destroys or half-writes an existing file.
// - A symlink target is written through: the file it points to is replaced (the temporary
//   file sits beside that file), the link stays.
// - An existing target keeps its permission bits (a mode-600 file stays 600); a read-only
//   target (no write bit, or not writable by this process) is refused.
// - Durability: the temporary file is fsync'ed before the rename, its directory after it.
// - Live temporary files are registered so that removeTemporaryFilesOnSignals() can delete
//   them when the process is interrupted (SIGINT, SIGTERM, SIGHUP).
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>

namespace plumb {

class AtomicFileWriter {
 public:
  /// Opens a temporary file in the target's directory. Throws FileError if it cannot, or if
  /// the target is read-only or a directory.
  explicit AtomicFileWriter(std::filesystem::path target);
  ~AtomicFileWriter();  ///< removes the temporary file unless commit() succeeded
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  std::ostream& stream() { return out_; }
  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temporaryPath() const { return temp_; }

  /// Flushes, fsyncs, closes and renames over the target (keeping its mode), then fsyncs the
  /// directory. Throws FileError on any write failure.
  void commit();

 private:
  std::filesystem::path target_;    ///< as given (messages)
  std::filesystem::path resolved_;  ///< the file replaced: target_ with symlinks followed
  std::filesystem::path temp_;
  std::unique_ptr<char[]> buffer_;
  std::ofstream out_;
  int slot_ = -1;  ///< registry slot of temp_ (-1: not registered)
  bool committed_ = false;
};

/// Runs write(stream) into a temporary file and renames it over `target` on success.
void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(std::ostream&)>& write);

/// Throws FileError when `target` could not be replaced by AtomicFileWriter (read-only file,
/// directory, missing or unwritable directory), without writing anything.
void checkWritableTarget(const std::filesystem::path& target);

/// Installs handlers for SIGINT, SIGTERM and SIGHUP that delete the live temporary files
/// (async-signal-safe calls only) and then re-raise the signal with its default action.
void removeTemporaryFilesOnSignals();

}  // namespace plumb
