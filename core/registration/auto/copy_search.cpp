#include "registration/auto/copy_search.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <random>
#include <unordered_map>

namespace plumb {

namespace {

using Index3 = Eigen::Array3i;

/// Target occupancy: a cell is set when a target point lies in it or in one of its 26
/// neighbours (the one-cell dilation is the chamfer tolerance).
struct OccupancyGrid {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  double cell = 0.0;
  Index3 dims = Index3::Zero();
  std::vector<std::uint8_t> occupied;

  std::int64_t count() const { return std::int64_t(dims.x()) * dims.y() * dims.z(); }
  std::int64_t linear(const Index3& i) const {
    return (std::int64_t(i.z()) * dims.y() + i.y()) * dims.x() + i.x();
  }
  bool inside(const Index3& i) const { return (i >= 0).all() && (i < dims).all(); }
  Index3 indexOf(const Eigen::Vector3d& p) const {
    return ((p - origin) / cell).array().floor().cast<int>();
  }
  bool at(const Index3& i) const { return inside(i) && occupied[std::size_t(linear(i))] != 0; }
};

/// Grows `cell` until the target's box holds at most `max_cells` cells.
OccupancyGrid emptyGrid(const Bounds& box, double cell, std::int64_t max_cells) {
  OccupancyGrid g;
  g.origin = box.min - Eigen::Vector3d::Constant(cell);
  const Eigen::Vector3d extent = box.size() + Eigen::Vector3d::Constant(2 * cell);
  const double cells = (extent / cell).array().ceil().prod();
  if (cells > double(max_cells)) cell *= std::cbrt(cells / double(max_cells)) * 1.01;
  g.cell = cell;
  g.dims = (extent / cell).array().ceil().cast<int>().max(1);
  g.occupied.assign(std::size_t(g.count()), 0);
  return g;
}

/// One-cell dilation along `axis` (three passes make the 26-neighbourhood).
void dilateAlong(OccupancyGrid& g, int axis) {
  std::vector<std::uint8_t> out = g.occupied;
  Index3 i;
  for (i.z() = 0; i.z() < g.dims.z(); ++i.z())
    for (i.y() = 0; i.y() < g.dims.y(); ++i.y())
      for (i.x() = 0; i.x() < g.dims.x(); ++i.x()) {
        if (!g.occupied[std::size_t(g.linear(i))]) continue;
        for (int s : {-1, 1}) {
          Index3 n = i;
          n[axis] += s;
          if (g.inside(n)) out[std::size_t(g.linear(n))] = 1;
        }
      }
  g.occupied.swap(out);
}

OccupancyGrid buildGrid(const PointCloud& target, double cell, std::int64_t max_cells) {
  OccupancyGrid g = emptyGrid(target.bounds(), cell, max_cells);
  for (std::size_t i = 0; i < target.size(); ++i) {
    const Eigen::Vector3d p = target.world(i);
    if (!p.allFinite()) continue;
    const Index3 c = g.indexOf(p);
    if (g.inside(c)) g.occupied[std::size_t(g.linear(c))] = 1;
  }
  for (int axis = 0; axis < 3; ++axis) dilateAlong(g, axis);
  return g;
}

/// Up to `n` finite source points in world coordinates, in a seeded random order.
std::vector<Eigen::Vector3d> randomPoints(const PointCloud& source, int n, std::uint64_t seed) {
  std::vector<std::size_t> finite;
  for (std::size_t i = 0; i < source.size(); ++i)
    if (source.world(i).allFinite()) finite.push_back(i);
  std::mt19937_64 rng(seed);
  std::shuffle(finite.begin(), finite.end(), rng);
  finite.resize(std::min(finite.size(), std::size_t(std::max(n, 0))));
  std::vector<Eigen::Vector3d> out;
  out.reserve(finite.size());
  for (std::size_t i : finite) out.push_back(source.world(i));
  return out;
}

/// Direction class of each point from the PCA of its neighbours within `radius`: 0 for a
/// horizontal surface (floor, ceiling), 1 + azimuth bin (4 bins of 45 degrees, modulo 180) for
/// a wall, -1 for neither or too few neighbours. Normals are turned by `rotation` first (the
/// classes are then in the target's frame, and a quarter turn keeps floors and walls apart).
std::vector<int> directionClasses(const std::vector<Eigen::Vector3d>& pts, double radius,
                                  const Eigen::Matrix3d& rotation) {
  const auto key = [radius](const Eigen::Vector3d& p) {
    const Eigen::Array3i c = (p / radius).array().floor().cast<int>();
    return (std::int64_t(c.x()) * 73856093) ^ (std::int64_t(c.y()) * 19349663) ^
           (std::int64_t(c.z()) * 83492791);
  };
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells;
  for (std::size_t i = 0; i < pts.size(); ++i) cells[key(pts[i])].push_back(i);
  std::vector<int> out(pts.size(), -1);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int n = 0;
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const auto it = cells.find(key(pts[i] + radius * Eigen::Vector3d(dx, dy, dz)));
          if (it == cells.end()) continue;
          for (std::size_t j : it->second) {
            const Eigen::Vector3d d = pts[j] - pts[i];
            if (d.squaredNorm() > radius * radius) continue;
            sum += d;
            cov += d * d.transpose();
            ++n;
          }
        }
    if (n < 8) continue;
    const Eigen::Vector3d mean = sum / n;
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(cov / n - mean * mean.transpose());
    const Eigen::Vector3d normal = rotation * es.eigenvectors().col(0);
    if (std::abs(normal.z()) > 0.9) {
      out[i] = 0;
    } else if (std::abs(normal.z()) < 0.3) {
      const double az = std::atan2(normal.y(), normal.x());
      const double a = std::fmod(az + 2 * M_PI, M_PI);  // [0, pi)
      out[i] = 1 + std::min(3, int(a / (M_PI / 4)));
    }
  }
  return out;
}

/// Up to `n` source points drawn evenly from each direction class (directionClasses), so that
/// the floor and ceiling, which fit at any horizontal shift, do not outvote the walls; then in
/// a seeded random order (so that a shift that cannot reach the threshold is given up after a
/// few points).
std::vector<Eigen::Vector3d> samplePoints(const PointCloud& source, const RigidTransform& chosen,
                                          const CopySearchParams& p) {
  const std::vector<Eigen::Vector3d> pool = randomPoints(source, p.class_pool, p.seed);
  const std::vector<int> cls = directionClasses(pool, p.normal_radius, chosen.rotation());
  std::array<std::vector<std::size_t>, 5> buckets;
  for (std::size_t i = 0; i < pool.size(); ++i)
    if (cls[i] >= 0) buckets[std::size_t(cls[i])].push_back(i);
  std::vector<Eigen::Vector3d> out;
  for (std::size_t k = 0; int(out.size()) < p.sample_points; ++k) {
    bool any = false;
    for (const auto& b : buckets) {
      if (k >= b.size() || int(out.size()) >= p.sample_points) continue;
      out.push_back(pool[b[k]]);
      any = true;
    }
    if (!any) break;
  }
  std::mt19937_64 rng(p.seed + 1);
  std::shuffle(out.begin(), out.end(), rng);
  return out;
}

bool upsideDown(int turn) { return turn >= 4; }

/// Turn `t`: 0-3 the turn by t x 90 degrees about the vertical through `centre`; 4-7 the same
/// after turning upside down (180 degrees about the X axis through `centre`).
RigidTransform turnAbout(int t, const Eigen::Vector3d& centre) {
  Eigen::Matrix3d r =
      Eigen::AngleAxisd((t % 4) * M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  if (upsideDown(t)) r = r * Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()).toRotationMatrix();
  return RigidTransform(r, centre - r * centre);
}

int turnCount(const CopySearchParams& p) { return p.upside_down ? 8 : 4; }

/// The placed sample's cells, for one turn.
struct PlacedSample {
  int turn = 0;  ///< turnAbout index: 0-3 upright, 4-7 upside down
  std::vector<Index3> cells;
  Index3 centre = Index3::Zero();  ///< the cell of the sample's box centre
};

PlacedSample placeSample(const std::vector<Eigen::Vector3d>& sample, const RigidTransform& placed,
                         const OccupancyGrid& g, int turn) {
  PlacedSample s;
  s.turn = turn;
  Bounds box;
  for (const auto& p : sample) {
    const Eigen::Vector3d q = placed.apply(p);
    s.cells.push_back(g.indexOf(q));
    box.extend(q);
  }
  s.centre = g.indexOf(box.center());
  return s;
}

/// Sample points in occupied cells under `shift`, or -1 once more than `allowed_misses` missed.
int scoreShift(const PlacedSample& s, const Index3& shift, const OccupancyGrid& g,
               int allowed_misses) {
  int misses = 0;
  for (const Index3& c : s.cells) {
    if (g.at(c + shift)) continue;
    if (++misses > allowed_misses) return -1;
  }
  return int(s.cells.size()) - misses;
}

struct ShiftScore {
  int turn = 0;
  Index3 shift = Index3::Zero();
  int score = 0;
};

/// Every whole-cell shift keeping the placed sample's centre inside the grid that reaches
/// `threshold` sample points.
void scanShifts(const PlacedSample& s, const OccupancyGrid& g, int threshold,
                std::vector<ShiftScore>& out) {
  const int allowed = int(s.cells.size()) - threshold;
  const Index3 lo = -s.centre, hi = g.dims - 1 - s.centre;
  Index3 d;
  for (d.z() = lo.z(); d.z() <= hi.z(); ++d.z())
    for (d.y() = lo.y(); d.y() <= hi.y(); ++d.y())
      for (d.x() = lo.x(); d.x() <= hi.x(); ++d.x()) {
        const int score = scoreShift(s, d, g, allowed);
        if (score >= threshold) out.push_back({s.turn, d, score});
      }
}

/// A candidate in metres: its turn, its shift and its score.
struct Copy {
  int turn = 0;
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();
  int score = 0;
};

/// Best first, one per `separation` metres and turn, at most `max_kept`, without the chosen
/// placement itself (turn 0, no shift).
std::vector<Copy> suppressNonMaxima(std::vector<Copy> all, double separation, int max_kept) {
  std::stable_sort(all.begin(), all.end(),
                   [](const Copy& a, const Copy& b) { return a.score > b.score; });
  std::vector<Copy> kept{{0, Eigen::Vector3d::Zero(), 0}};  // the chosen placement
  for (const Copy& c : all) {
    if (int(kept.size()) > max_kept) break;
    const bool near = std::any_of(kept.begin(), kept.end(), [&](const Copy& k) {
      return k.turn == c.turn && (k.shift - c.shift).norm() < separation;
    });
    if (!near) kept.push_back(c);
  }
  kept.erase(kept.begin());
  return kept;
}

std::vector<Copy> inMetres(const std::vector<ShiftScore>& shifts, double cell) {
  std::vector<Copy> out;
  for (const ShiftScore& s : shifts)
    out.push_back({s.turn, s.shift.cast<double>().matrix() * cell, s.score});
  return out;
}

/// The best fine score of `coarse` within one coarse cell of its shift horizontally, and half
/// the separation vertically (fine grid `g`).
Copy refineOnFineGrid(const Copy& coarse, const PlacedSample& placed, const OccupancyGrid& g,
                      double coarse_cell, double separation, int threshold) {
  const Index3 centre = (coarse.shift / g.cell).array().round().cast<int>();
  const int r = int(std::ceil(0.5 * coarse_cell / g.cell)) + 1;
  // Vertically as far as the non-maximum suppression reaches: a shift half a storey off can
  // outscore the right one on the dilated coarse grid (a corridor's walls fit at any height)
  // and suppress it; the fine grid, which the floors and ceilings must fit, tells them apart.
  const int rz = std::max(r, int(std::ceil(0.5 * separation / g.cell)) + 1);
  Copy best = coarse;
  best.score = -1;
  const int allowed = int(placed.cells.size()) - threshold;
  Index3 d;
  for (d.z() = -rz; d.z() <= rz; ++d.z())
    for (d.y() = -r; d.y() <= r; ++d.y())
      for (d.x() = -r; d.x() <= r; ++d.x()) {
        const Index3 shift = centre + d;
        const int score = scoreShift(placed, shift, g, std::min(allowed, int(placed.cells.size()) - best.score - 1));
        if (score > best.score) best = {coarse.turn, shift.cast<double>().matrix() * g.cell, score};
      }
  return best;
}

Hypothesis copyHypothesis(const Copy& c, const RigidTransform& chosen,
                          const Eigen::Vector3d& centre, std::size_t n) {
  const RigidTransform t = RigidTransform(Eigen::Matrix3d::Identity(), c.shift) *
                           turnAbout(c.turn, centre) * chosen;
  char label[160];
  std::snprintf(label, sizeof label, "copy: turned %d deg%s, shifted (%.2f, %.2f, %.2f) m",
                90 * (c.turn % 4), upsideDown(c.turn) ? " upside down" : "", c.shift.x(),
                c.shift.y(), c.shift.z());
  return Hypothesis{t, double(c.score) / double(n), label};
}

/// The placed sample on grid `g` for each turn (turnAbout).
std::vector<PlacedSample> placeTurns(const std::vector<Eigen::Vector3d>& sample,
                                     const RigidTransform& chosen, const Eigen::Vector3d& centre,
                                     const OccupancyGrid& g, int turns) {
  std::vector<PlacedSample> out;
  for (int t = 0; t < turns; ++t)
    out.push_back(placeSample(sample, turnAbout(t, centre) * chosen, g, t));
  return out;
}

/// Steps 1-3: the coarse shifts reaching `min_fraction` of the chosen placement's score.
std::vector<Copy> coarseCandidates(const std::vector<Eigen::Vector3d>& sample,
                                   const RigidTransform& chosen, const Eigen::Vector3d& centre,
                                   const OccupancyGrid& g, const CopySearchParams& p) {
  const auto placed = placeTurns(sample, chosen, centre, g, turnCount(p));
  const int own = scoreShift(placed[0], Index3::Zero(), g, int(sample.size()));
  const int threshold = std::max(1, int(std::ceil(p.min_fraction * own)));
  std::vector<ShiftScore> passing;
  for (const PlacedSample& s : placed) scanShifts(s, g, threshold, passing);
  return suppressNonMaxima(inMetres(passing, g.cell), p.separation, p.max_coarse);
}

/// Steps 4-5: the coarse candidates scored on the fine grid, the copies kept.
std::vector<Copy> fineCopies(const std::vector<Copy>& coarse,
                             const std::vector<Eigen::Vector3d>& sample,
                             const RigidTransform& chosen, const Eigen::Vector3d& centre,
                             const OccupancyGrid& fine, double coarse_cell,
                             const CopySearchParams& p, int& own_score) {
  const auto placed = placeTurns(sample, chosen, centre, fine, turnCount(p));
  own_score = scoreShift(placed[0], Index3::Zero(), fine, int(sample.size()));
  const int threshold = std::max(1, int(std::ceil(p.min_fraction * own_score)));
  std::vector<Copy> scored;
  for (const Copy& c : coarse) {
    const Copy f = refineOnFineGrid(c, placed[std::size_t(c.turn)], fine, coarse_cell, p.separation, threshold);
    if (f.score >= threshold) scored.push_back(f);
  }
  // Upright and upside-down copies kept apart, each up to max_copies: on a grid, an upside-down
  // room fits about as well as an upright one, and must not push the upright copies out.
  std::vector<Copy> upright, upside_down;
  for (const Copy& c : scored) (upsideDown(c.turn) ? upside_down : upright).push_back(c);
  std::vector<Copy> kept = suppressNonMaxima(upright, p.separation, p.max_copies);
  for (const Copy& c : suppressNonMaxima(upside_down, p.separation, p.max_copies)) kept.push_back(c);
  return kept;
}

}  // namespace

CopySearchResult findCopies(const PointCloud& source, const PointCloud& target,
                            const RigidTransform& chosen, const CopySearchParams& p) {
  CopySearchResult r;
  const std::vector<Eigen::Vector3d> sample = samplePoints(source, chosen, p);
  if (sample.empty() || target.empty()) {
    r.message = "copy search: no points";
    return r;
  }
  const OccupancyGrid coarse = buildGrid(target, p.cell, p.max_cells);
  r.cell = coarse.cell;
  if (turnCount(p) * coarse.count() > p.max_shifts) {
    r.skipped = true;
    r.message = "copy search skipped: the target is too large for a whole-cell search";
    return r;
  }
  const PlacedSample own = placeSample(sample, chosen, coarse, 0);
  r.chosen_fraction =
      double(scoreShift(own, Index3::Zero(), coarse, int(sample.size()))) / double(sample.size());
  if (r.chosen_fraction < p.min_explained) {
    r.skipped = true;
    r.message = "copy search skipped: the chosen placement explains too little of the source";
    return r;
  }
  const Eigen::Vector3d centre = target.bounds().center();
  const std::vector<Copy> candidates = coarseCandidates(sample, chosen, centre, coarse, p);
  r.coarse_candidates = candidates.size();
  int own_fine = 0;
  if (!candidates.empty()) {
    const OccupancyGrid fine = buildGrid(target, p.fine_cell, p.max_cells);
    r.fine_cell = fine.cell;
    for (const Copy& c : fineCopies(candidates, sample, chosen, centre, fine, coarse.cell, p, own_fine))
      r.copies.push_back(copyHypothesis(c, chosen, centre, sample.size()));
  }
  char msg[240];
  std::snprintf(msg, sizeof msg,
                "copy search (%.2f / %.2f m cells): the chosen placement explains %.2f of %zu "
                "source points (%.2f on the fine grid); %zu coarse candidates, %zu copies reach "
                "%.2f of it",
                coarse.cell, r.fine_cell, r.chosen_fraction, sample.size(),
                double(own_fine) / double(sample.size()), r.coarse_candidates, r.copies.size(),
                p.min_fraction);
  r.message = msg;
  return r;
}

}  // namespace plumb
