#include "features/planes/polygon_2d.hpp"

#include <cmath>
#include <cstdint>
#include <map>

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
  using Key = std::pair<std::int64_t, std::int64_t>;
  auto key = [cell](const Eigen::Vector2d& p) {
    return Key(std::int64_t(std::floor(p.x() / cell)), std::int64_t(std::floor(p.y() / cell)));
  };
  std::map<Key, int> label;
  for (const auto& p : pts) label.emplace(key(p), -1);
  int n = 0;
  for (auto& [c, l] : label) {
    if (l >= 0) continue;
    l = n;
    std::vector<Key> stack{c};
    while (!stack.empty()) {
      const Key cur = stack.back();
      stack.pop_back();
      for (int di = -1; di <= 1; ++di)
        for (int dj = -1; dj <= 1; ++dj) {
          auto it = label.find({cur.first + di, cur.second + dj});
          if (it != label.end() && it->second < 0) {
            it->second = n;
            stack.push_back(it->first);
          }
        }
    }
    ++n;
  }
  std::vector<std::vector<std::size_t>> out(n);
  for (std::size_t k = 0; k < pts.size(); ++k) out[label[key(pts[k])]].push_back(k);
  return out;
}

}  // namespace plumb
