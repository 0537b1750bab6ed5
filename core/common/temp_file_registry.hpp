#pragma once
// Registry of the temporary files being written, for removal by a signal handler. A fixed
// table of slots (no allocation, no locks) so the handler only reads plain memory and calls
// unlink(2), both async-signal-safe. Internal to common (atomic_file.cpp).
namespace plumb::temp_files {

/// Records `path`; returns its slot, or -1 when the table is full (the file is then not
/// removed on a signal, only by the writer's destructor).
int add(const char* path) noexcept;
/// Forgets slot `slot` (no-op for -1).
void remove(int slot) noexcept;
/// Unlinks every registered file. Async-signal-safe.
void unlinkAll() noexcept;

}  // namespace plumb::temp_files
