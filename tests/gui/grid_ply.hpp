#pragma once
// Test input shared by the GUI tests: a flat, single-colour grid of points as an ASCII PLY.
#include <filesystem>
#include <fstream>

namespace plumb::test {

/// An ASCII PLY of `n` x `n` points on a 0.2 m grid in the plane z = 0, one RGB colour,
/// starting at x = `x0`.
inline std::filesystem::path writeGridPly(const std::filesystem::path& path, int n, int r, int g,
                                          int b, double x0 = 0.0) {
  std::ofstream out(path);
  out << "ply\nformat ascii 1.0\nelement vertex " << n * n
      << "\nproperty float x\nproperty float y\nproperty float z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      out << x0 + i * 0.2 << " " << j * 0.2 << " 0 " << r << " " << g << " " << b << "\n";
  return path;
}

}  // namespace plumb::test
