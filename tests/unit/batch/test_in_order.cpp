#include <gtest/gtest.h>

#include <atomic>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "batch/in_order.hpp"

namespace rollcontact::batch {
namespace {

TEST(InOrder, ItemsWaitOnlyForAnEarlierOne) {
  std::vector<int> seen;
  InOrder<int> order([&](std::size_t k, int& v) {
    EXPECT_EQ(static_cast<int>(k) * 10, v);
    seen.push_back(v);
  });
  order.add(2, 20);  // finish order 2, 1, 0, 3
  EXPECT_EQ(order.handed_on(), 0u);
  EXPECT_EQ(order.waiting(), 1u);
  order.add(1, 10);
  EXPECT_EQ(order.waiting(), 2u);
  order.add(0, 0);
  EXPECT_EQ(order.handed_on(), 3u);
  EXPECT_EQ(order.waiting(), 0u);
  EXPECT_THROW(order.add(1, 10), std::logic_error);
  order.add(3, 30);
  EXPECT_EQ(seen, (std::vector<int>{0, 10, 20, 30}));
}

TEST(InOrder, ItemsAreMovedNotCopied) {
  std::vector<int> seen;
  InOrder<std::unique_ptr<int>> order(
      [&](std::size_t, std::unique_ptr<int>& v) { seen.push_back(*v); });
  order.add(1, std::make_unique<int>(1));
  order.add(0, std::make_unique<int>(0));
  EXPECT_EQ(seen, (std::vector<int>{0, 1}));
}

TEST(InOrder, TwoThreadsInterleavedGiveTheOrder) {
  constexpr std::size_t n = 2000;
  std::vector<std::size_t> seen;
  InOrder<std::size_t> order([&](std::size_t k, std::size_t& v) {
    EXPECT_EQ(k, v);
    seen.push_back(v);
  });
  {
    std::jthread odd([&] {
      for (std::size_t k = 1; k < n; k += 2) order.add(k, k);
    });
    for (std::size_t k = 0; k < n; k += 2) order.add(k, k);
  }
  ASSERT_EQ(seen.size(), n);
  for (std::size_t k = 0; k < n; ++k) EXPECT_EQ(seen[k], k);
}

}  // namespace
}  // namespace rollcontact::batch
