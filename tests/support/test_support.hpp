#pragma once
// Shared helpers for tests: where the shared real data lives, and scratch directories.
#include <filesystem>
#include <string>

namespace plumb::test {

/// ../shared/data/<relative> (the real public files described in its README).
std::filesystem::path sharedData(const std::string& relative);
/// A fresh, empty directory under <build>/test-artifacts/<name>, kept after the run so
/// outputs (written files, screenshots) can be inspected. Inside a GoogleTest case it is
/// <name>/<Suite.Case>: CTest runs the cases of one executable as parallel processes, and
/// two cases wiping one shared folder would delete each other's files.
std::filesystem::path scratchDir(const std::string& name);
/// The per-case part of scratchDir's path ("" outside a test case); set by the test main.
void setScratchCase(const std::string& test_case);
/// Reads a whole file.
std::string readAll(const std::filesystem::path& path);
/// Writes bytes to a file (non-atomic, test use only).
void writeAll(const std::filesystem::path& path, const std::string& bytes);

}  // namespace plumb::test
