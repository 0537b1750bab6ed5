#pragma once
// Atomic file writes: data goes to a temporary file beside the target, which is renamed over
// the target only when everything was written and flushed. A failed or cancelled export never
// destroys or half-writes an existing file.
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>

namespace plumb {

class AtomicFileWriter {
 public:
  /// Opens a temporary file in the target's directory. Throws FileError if it cannot.
  explicit AtomicFileWriter(std::filesystem::path target);
  ~AtomicFileWriter();  ///< removes the temporary file unless commit() succeeded
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  std::ostream& stream() { return out_; }
  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temporaryPath() const { return temp_; }

  /// Flushes, closes and renames over the target. Throws FileError on any write failure.
  void commit();

 private:
  std::filesystem::path target_;
  std::filesystem::path temp_;
  std::unique_ptr<char[]> buffer_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Runs write(stream) into a temporary file and renames it over `target` on success.
void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(std::ostream&)>& write);

}  // namespace plumb
