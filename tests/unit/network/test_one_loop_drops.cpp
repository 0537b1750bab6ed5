// A dropped link judged by one loop alone (one_loop_drops.hpp): a single loop's misclosure says a
// link is wrong, not which; the stations placed through a bridge that the drop left are
// ambiguous. With redundant loops the wrong link is identified and nothing is.
#include <gtest/gtest.h>

#include "registration/network/one_loop_drops.hpp"
#include "support/synthetic_network.hpp"

namespace plumb {
namespace {

/// A chain 0-1-2-3-4-5 of right links and one wrong link (0, 5) closing the only loop; the wrong
/// link weighs like the others (a strong wrong link, as between identical rooms).
test::SyntheticNetwork singleLoop() {
  auto net = test::ringNetwork(6, 5.0, 100, 0.001, 0.005, 3, false);
  net.links.resize(5);  // 0-1 ... 4-5: the ring's closing link 5-0 is replaced below
  AdjustmentLink wrong;
  wrong.a = 0, wrong.b = 5;
  wrong.transform = RigidTransform::fromYaw(0.0, {3.0, 0.0, 0.0}) * net.truth[0].inverse() * net.truth[5];
  wrong.sigma_translation = 0.001, wrong.sigma_rotation_deg = 0.005;
  net.wrong_link = net.links.size();
  net.links.push_back(wrong);
  return net;
}

TEST(OneLoopDrops, ADropInTheOnlyLoopLeavesItsFarSideAmbiguous) {
  const auto net = singleLoop();
  const auto adj = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], test::graphParams());
  ASSERT_EQ(adj.dropped_order.size(), 1u) << "the loop does not close: one link goes";
  const auto ambiguous = decidedByOneLoop(net.truth.size(), net.links, adj, 0);
  // Every kept link is now a bridge: every station but the reference hangs on a choice the one
  // loop could not make (whichever link was dropped).
  EXPECT_EQ(ambiguous, (std::vector<std::size_t>{1, 2, 3, 4, 5}));
}

TEST(OneLoopDrops, RedundantLoopsIdentifyTheWrongLinkAndLeaveNothingAmbiguous) {
  const auto net = test::ringNetwork(12, 10.0, 4, 0.001, 0.005, 11, true);
  const auto adj = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], test::graphParams());
  ASSERT_EQ(adj.dropped_order, (std::vector<std::size_t>{net.wrong_link}));
  EXPECT_TRUE(decidedByOneLoop(net.truth.size(), net.links, adj, 0).empty());
}

TEST(OneLoopDrops, NothingDroppedNothingAmbiguous) {
  const auto net = test::ringNetwork(8, 6.0, 3, 0.001, 0.005, 5, false);
  const auto adj = adjustNetwork(net.truth.size(), net.links, 0, net.truth[0], test::graphParams());
  EXPECT_TRUE(adj.dropped_order.empty());
  EXPECT_TRUE(decidedByOneLoop(net.truth.size(), net.links, adj, 0).empty());
}

}  // namespace
}  // namespace plumb
