#include "features/planes/polygon_2d.hpp"

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <unordered_map>

namespace plumb {

double ringSignedArea(const std::vector<Eigen::Vector2d>& r) {
  double a = 0;
  for (std::size_t i = 0, n = r.size(); i < n; ++i) {
    const auto& p = r[i];
    const auto& q = r[(i + 1) % n];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

bool ringContains(const std::vector<Eigen::Vector2d>& r, const Eigen::Vector2d& p) {
  bool in = false;
  if (r.empty()) return false;
  for (std::size_t i = 0, j = r.size() - 1; i < r.size(); j = i++)
    if ((r[i].y() > p.y()) != (r[j].y() > p.y()) &&
        p.x() < (r[j].x() - r[i].x()) * (p.y() - r[i].y()) / (r[j].y() - r[i].y()) + r[i].x())
      in = !in;
  return in;
}

std::vector<std::vector<std::size_t>> gridComponents(const std::vector<Eigen::Vector2d>& pts,
                                                     double cell) {
  // Cells as packed keys, sorted (deterministic order), looked up through a hash map.
  auto pack = [](std::int64_t i, std::int64_t j) {
    return (static_cast<std::uint64_t>(i + (std::int64_t(1) << 31)) << 32) |
           static_cast<std::uint64_t>(j + (std::int64_t(1) << 31));
  };
  std::vector<std::uint64_t> key(pts.size());
  for (std::size_t k = 0; k < pts.size(); ++k)
    key[k] = pack(std::int64_t(std::floor(pts[k].x() / cell)), std::int64_t(std::floor(pts[k].y() / cell)));
  std::vector<std::uint64_t> cells = key;
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  std::unordered_map<std::uint64_t, int> index;
  index.reserve(cells.size() * 2);
  for (std::size_t c = 0; c < cells.size(); ++c) index.emplace(cells[c], static_cast<int>(c));
  std::vector<int> label(cells.size(), -1);
  int n = 0;
  std::vector<int> stack;
  for (std::size_t c0 = 0; c0 < cells.size(); ++c0) {
    if (label[c0] >= 0) continue;
    label[c0] = n;
    stack.assign(1, static_cast<int>(c0));
    while (!stack.empty()) {
      const std::uint64_t k = cells[stack.back()];
      stack.pop_back();
      const std::int64_t i = std::int64_t(k >> 32) - (std::int64_t(1) << 31);
      const std::int64_t j = std::int64_t(k & 0xffffffffu) - (std::int64_t(1) << 31);
      for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
          auto it = index.find(pack(i + di, j + dj));
          if (it != index.end() && label[it->second] < 0) {
            label[it->second] = n;
            stack.push_back(it->second);
          }
        }
    }
    ++n;
  }
  std::vector<std::vector<std::size_t>> out(n);
  for (std::size_t k = 0; k < pts.size(); ++k) out[label[index.at(key[k])]].push_back(k);
  return out;
}

}  // namespace plumb
