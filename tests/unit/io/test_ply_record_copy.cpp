// RecordCopier (core/io/ply/record_copy): the fused one-pass kernels and the per-field passes
// must give the same columns as a byte-by-byte copy, for every layout, record stride, field
// placement and block split, and must write nothing outside the block's records.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include "io/ply/record_copy.hpp"

namespace plumb::ply {
namespace {

constexpr unsigned char kSentinel = 0xAB;
constexpr std::size_t kSlack = 16;

struct Case {
  std::vector<std::size_t> bytes;  ///< field sizes, in copy order
  bool fused;                      ///< a fused kernel is expected for this layout
};

const Case kCases[] = {
    {{12}, true},        {{12, 3}, true},       {{12, 4}, true},        {{12, 3, 4}, true},
    {{12, 4, 4}, true},  {{12, 3, 4, 4}, true}, {{12, 12}, true},       {{12, 12, 3}, true},
    {{12, 12, 4}, true}, {{12, 12, 3, 4}, true}, {{3, 4}, false},       {{4}, false},
    {{3}, false},        {{12, 3, 4, 4, 4}, false}, {{4, 12}, false},
};

void PrintTo(const Case& c, std::ostream* os) {
  *os << "field bytes";
  for (std::size_t b : c.bytes) *os << " " << b;
}

class RecordCopyTest : public ::testing::TestWithParam<Case> {};

TEST_P(RecordCopyTest, MatchesByteCopyForEveryStrideAndSplit) {
  const Case& c = GetParam();
  std::mt19937 rng(7);
  const std::size_t payload = std::accumulate(c.bytes.begin(), c.bytes.end(), std::size_t{0});
  for (int trial = 0; trial < 40; ++trial) {
    // A record: the fields in a random order, with random gaps (other properties) between them.
    const std::size_t n = std::uniform_int_distribution<std::size_t>(0, 300)(rng);
    std::vector<std::size_t> order(c.bytes.size());
    std::iota(order.begin(), order.end(), 0);
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<std::size_t> src(c.bytes.size());
    std::size_t stride = 0;
    for (std::size_t j : order) {
      stride += std::uniform_int_distribution<std::size_t>(0, 5)(rng);
      src[j] = stride;
      stride += c.bytes[j];
    }
    stride += std::uniform_int_distribution<std::size_t>(0, 5)(rng);
    ASSERT_GE(stride, payload);
    std::vector<unsigned char> file(n * stride);
    for (auto& b : file) b = static_cast<unsigned char>(rng());

    auto runWith = [&](bool fused, std::vector<std::vector<unsigned char>>& cols) {
      cols.assign(c.bytes.size(), {});
      std::vector<FieldCopy> fields;
      for (std::size_t j = 0; j < c.bytes.size(); ++j) {
        cols[j].assign(n * c.bytes[j] + kSlack, kSentinel);  // slack: catches writes past the end
        fields.push_back({src[j], reinterpret_cast<char*>(cols[j].data()), c.bytes[j]});
      }
      const RecordCopier copier(stride, fields, fused);
      EXPECT_EQ(copier.fused(), fused && c.fused);
      // Blocks of random sizes, in a random order (as threads would take them); after each
      // block, every value outside the blocks done so far must still hold the sentinel.
      std::vector<std::pair<std::size_t, std::size_t>> blocks;
      for (std::size_t i = 0; i < n;) {
        const std::size_t k = std::min(n - i, std::uniform_int_distribution<std::size_t>(1, 40)(rng));
        blocks.emplace_back(i, k);
        i += k;
      }
      std::shuffle(blocks.begin(), blocks.end(), rng);
      std::vector<bool> done(n, false);
      for (const auto& [base, k] : blocks) {
        copier.run(reinterpret_cast<const char*>(file.data()) + base * stride, k, base);
        for (std::size_t i = base; i < base + k; ++i) done[i] = true;
        for (std::size_t j = 0; j < c.bytes.size(); ++j)
          for (std::size_t i = 0; i < n; ++i) {
            if (done[i]) continue;
            for (std::size_t b = 0; b < c.bytes[j]; ++b)
              ASSERT_EQ(cols[j][i * c.bytes[j] + b], kSentinel)
                  << "field " << j << " record " << i << " written by block at " << base;
          }
      }
    };
    std::vector<std::vector<unsigned char>> fused_cols, reference_cols;
    runWith(true, fused_cols);
    runWith(false, reference_cols);
    for (std::size_t j = 0; j < c.bytes.size(); ++j) {
      for (std::size_t i = 0; i < n; ++i)
        for (std::size_t b = 0; b < c.bytes[j]; ++b)
          ASSERT_EQ(fused_cols[j][i * c.bytes[j] + b], file[i * stride + src[j] + b])
              << "field " << j << " record " << i << " byte " << b << " stride " << stride;
      for (std::size_t b = 0; b < kSlack; ++b) ASSERT_EQ(fused_cols[j][n * c.bytes[j] + b], kSentinel) << "written past the column";
      EXPECT_EQ(fused_cols[j], reference_cols[j]);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Layouts, RecordCopyTest, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = "bytes";
                           for (std::size_t b : info.param.bytes) name += "_" + std::to_string(b);
                           return name;
                         });

}  // namespace
}  // namespace plumb::ply
