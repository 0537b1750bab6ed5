#include "support/degenerate_scenes.hpp"

#include <random>

namespace plumb::test {

PointCloud noisyRectangles(const std::vector<Rectangle>& rects, int per_rect, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> n(0.0, 0.003);
  PointCloud c;
  for (const auto& r : rects)
    for (int i = 0; i < per_rect; ++i) {
      const Eigen::Vector3d p = r[0] + u(rng) * r[1] + u(rng) * r[2];
      c.positions.push_back((p + Eigen::Vector3d(n(rng), n(rng), n(rng))).cast<float>());
    }
  return c;
}

std::vector<DegenerateScene> degenerateScenes() {
  using V = Eigen::Vector3d;
  const V x(10, 0, 0), y(0, 10, 0);
  return {
      {"single plane", {{V(0, 0, 0), x, y}}, 3},
      {"two parallel planes", {{V(0, 0, 0), x, y}, {V(0, 0, 3), x, y}}, 3},
      {"corridor without openings",
       {{V(0, 0, 0), V(30, 0, 0), V(0, 2, 0)}, {V(0, 0, 3), V(30, 0, 0), V(0, 2, 0)},
        {V(0, 0, 0), V(30, 0, 0), V(0, 0, 3)}, {V(0, 2, 0), V(30, 0, 0), V(0, 0, 3)}},
       1},
      // A line: a 10 m pole 6 mm thick (two thin strips).
      {"single line", {{V(0, 0, 0), x, V(0, 0.006, 0)}, {V(0, 0, 0), x, V(0, 0, 0.006)}}, 2},
  };
}

}  // namespace plumb::test
