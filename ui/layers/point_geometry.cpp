#include "ui/layers/point_geometry.hpp"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkTypeInt32Array.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace plumb::ui {

static_assert(sizeof(Eigen::Vector3f) == 3 * sizeof(float), "positions must be packed xyz");
static_assert(sizeof(Rgba) == 4, "colours must be packed rgba");

namespace {

/// SplitMix64 finaliser: a well-mixed 64-bit value of a counter (fast, stateless).
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

/// Uniform in [0, range) from the high 32 bits of h (multiply-shift; bias < range / 2^32).
std::size_t bounded(std::uint64_t h, std::size_t range) {
  return static_cast<std::size_t>(((h >> 32) * static_cast<std::uint64_t>(range)) >> 32);
}

/// out[j] = source(order[j]) for the random order of n points and `seed`, without a global
/// shuffle or gather (a cache miss per point: ~0.9 s for 20 M points with std::mt19937): each
/// point draws a random bucket (a hash of its index), points are scattered by bucket in
/// streaming passes, then each bucket (a few thousand points, cache resident) is shuffled
/// (Fisher-Yates). A random bucket and a uniform shuffle within buckets make a uniform random
/// permutation. The draws depend on n and seed only: every call with the same n and seed
/// applies the same order. The passes run in parallel (TBB) over fixed chunks of points and over
/// buckets; the chunking and each bucket's draws do not depend on the threads, so the result
/// is the same as a sequential run.
template <class T, class Source>
void permuteInto(std::size_t n, std::uint32_t seed, Source&& source, T* out) {
  const std::size_t buckets = std::clamp<std::size_t>(n / 4096, 1, 1024);
  const std::uint64_t key = mix(seed);
  auto bucketOf = [&](std::size_t i) { return bounded(mix(key ^ (std::uint64_t{i} << 1)), buckets); };
  constexpr std::size_t kChunk = std::size_t{1} << 16;
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  // cursor[c * buckets + b]: points of chunk c in bucket b, then where chunk c writes them.
  std::vector<std::size_t> cursor(chunks * buckets, 0);
  auto forChunks = [&](const auto& body) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1), [&](const auto& r) {
      for (std::size_t c = r.begin(); c != r.end(); ++c)
        body(c, c * kChunk, std::min(n, (c + 1) * kChunk), &cursor[c * buckets]);
    });
  };
  forChunks([&](std::size_t, std::size_t lo, std::size_t hi, std::size_t* count) {
    for (std::size_t i = lo; i < hi; ++i) ++count[bucketOf(i)];
  });
  // Bucket-major offsets, chunks in order within a bucket: the layout of a sequential scatter.
  std::vector<std::size_t> start(buckets + 1, 0);  // bucket b: [start[b], start[b + 1])
  std::size_t offset = 0;
  for (std::size_t b = 0; b < buckets; ++b) {
    start[b] = offset;
    for (std::size_t c = 0; c < chunks; ++c)
      offset += std::exchange(cursor[c * buckets + b], offset);
  }
  start[buckets] = offset;
  forChunks([&](std::size_t, std::size_t lo, std::size_t hi, std::size_t* next) {
    for (std::size_t i = lo; i < hi; ++i) out[next[bucketOf(i)]++] = source(i);
  });
  // Bucket b's shuffle draws counters first[b], first[b] + 1, ...: one per swap, buckets in
  // order (a single running counter, as a sequential shuffle of the buckets one after another).
  std::vector<std::uint64_t> first(buckets, 0);
  std::uint64_t counter = mix(key + 1);
  for (std::size_t b = 0; b < buckets; ++b) {
    first[b] = counter;
    counter += std::max<std::size_t>(start[b + 1] - start[b], 1) - 1;
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, buckets, 1), [&](const auto& r) {
    for (std::size_t b = r.begin(); b != r.end(); ++b) {
      std::uint64_t draw = first[b];
      for (std::size_t j = start[b + 1]; j > start[b] + 1; --j)
        std::swap(out[j - 1], out[start[b] + bounded(mix(draw++), j - start[b])]);
    }
  });
}

}  // namespace

std::vector<std::uint32_t> randomOrder(std::size_t n, std::uint32_t seed) {
  std::vector<std::uint32_t> order(n);
  permuteInto(n, seed, [](std::size_t i) { return static_cast<std::uint32_t>(i); }, order.data());
  return order;
}

PermutedPoints::PermutedPoints(const PointCloud& cloud, std::uint32_t seed) : seed_(seed) {
  const std::size_t n = cloud.size();
  // Vertex ids are 32-bit (connectivity and original indices).
  if (n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
    throw std::length_error("point cloud too large to draw (more than 2^31 - 1 points)");
  positions_.resize(n);
  permuteInto(n, seed_, [&cloud](std::size_t i) { return cloud.positions[i]; }, positions_.data());
  colors_.assign(n, Rgba{255, 255, 255, 255});
  iota_.resize(n);
  std::iota(iota_.begin(), iota_.end(), 0);
}

std::vector<Rgba> permuteColors(std::span<const Rgb> cloud_order, std::uint32_t seed) {
  std::vector<Rgba> out(cloud_order.size());
  permuteInto(
      out.size(), seed,
      [cloud_order](std::size_t i) {
        const Rgb& c = cloud_order[i];
        return Rgba{c[0], c[1], c[2], 255};
      },
      out.data());
  return out;
}

bool PermutedPoints::setColors(std::vector<Rgba> permuted) {
  if (permuted.size() != size()) return false;
  colors_.swap(permuted);
  return true;
}

void PermutedPoints::bindColors(vtkPolyData* poly) const {
  if (!poly) return;
  auto* colors = vtkUnsignedCharArray::SafeDownCast(poly->GetPointData()->GetScalars());
  if (!colors) return;
  const vtkIdType k = std::min<vtkIdType>(colors->GetNumberOfTuples(), static_cast<vtkIdType>(size()));
  // Same array object (the mapper re-uploads only the colours), new buffer.
  colors->SetArray(k ? const_cast<std::uint8_t*>(colors_[0].data()) : nullptr, 4 * k, 1);
  colors->Modified();
  poly->Modified();
}

vtkSmartPointer<vtkPolyData> PermutedPoints::prefix(std::size_t k) const {
  k = std::min(k, size());
  const auto kid = static_cast<vtkIdType>(k);
  // save = 1 everywhere: VTK never frees (or reallocates) these buffers.
  vtkNew<vtkFloatArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetArray(k ? const_cast<float*>(positions_[0].data()) : nullptr, 3 * kid, 1);
  vtkNew<vtkPoints> points;
  points->SetData(xyz);
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName("colors");
  colors->SetNumberOfComponents(4);
  colors->SetArray(k ? const_cast<std::uint8_t*>(colors_[0].data()) : nullptr, 4 * kid, 1);
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->GetPointData()->SetScalars(colors);
  if (k > 0) {
    // One poly-vertex cell over points 0..k-1: 32-bit offsets and the shared iota prefix.
    vtkNew<vtkTypeInt32Array> offsets;
    offsets->SetNumberOfValues(2);
    offsets->SetValue(0, 0);
    offsets->SetValue(1, static_cast<std::int32_t>(k));
    vtkNew<vtkTypeInt32Array> connectivity;
    connectivity->SetArray(const_cast<std::int32_t*>(iota_.data()), kid, 1);
    vtkNew<vtkCellArray> cells;
    cells->SetData(offsets, connectivity);
    poly->SetVerts(cells);
  }
  return poly;
}

vtkSmartPointer<vtkUnsignedCharArray> makeColorArray(std::size_t n) {
  auto colors = vtkSmartPointer<vtkUnsignedCharArray>::New();
  colors->SetName("colors");
  colors->SetNumberOfComponents(3);
  colors->SetNumberOfTuples(static_cast<vtkIdType>(n));
  return colors;
}

void setupPointActor(vtkActor* actor, vtkPolyDataMapper* mapper, vtkPolyData* poly) {
  if (poly) mapper->SetInputData(poly);
  mapper->SetScalarModeToUsePointData();
  mapper->SetColorModeToDirectScalars();
  mapper->ScalarVisibilityOn();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetRepresentationToPoints();
  actor->GetProperty()->LightingOff();
  actor->PickableOff();
}

}  // namespace plumb::ui
