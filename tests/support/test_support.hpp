#pragma once
// Shared helpers for tests: where the shared real data lives, and scratch directories.
#include <filesystem>
#include <string>

namespace plumb::test {

/// ../shared/data/<relative> (the real public files described in its README).
std::filesystem::path sharedData(const std::string& relative);
/// A fresh, empty directory under <build>/test-artifacts/<name>, kept after the run so
/// outputs (written files, screenshots) can be inspected.
std::filesystem::path scratchDir(const std::string& name);
/// Reads a whole file.
std::string readAll(const std::filesystem::path& path);
/// Writes bytes to a file (non-atomic, test use only).
void writeAll(const std::filesystem::path& path, const std::string& bytes);

}  // namespace plumb::test
