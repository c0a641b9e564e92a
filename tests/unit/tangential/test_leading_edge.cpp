// The elements of a transient rolling step that began outside the contact (physics.md §9.4).

#include <gtest/gtest.h>

#include <numbers>
#include <vector>

#include "tangential/leading_edge.hpp"

namespace rollcontact::tangential {
namespace {

/// A 16 × 2 grid with δx = 0.5 mm; row 0 in contact at ix = 3..10, row 1 at ix = 3..14.
struct TwoRows {
  Grid grid{16, 2, 0.0, 0.0, 0.5, 1.0};
  std::vector<char> contact = std::vector<char>(32, 0);
  TwoRows() {
    for (int ix = 3; ix <= 10; ++ix) contact[grid.index(ix, 0)] = 1;
    for (int ix = 3; ix <= 14; ++ix) contact[grid.index(ix, 1)] = 1;
  }
};

TEST(LeadingEdge, StepOfTwoAndAHalfElementsForwards) {
  const TwoRows r;
  // χ = 0: the edge of row 0 is the centre of ix = 11; the particles at ix = 10 and 9 were
  // 1 and 2 elements from it, 0.4 and 0.8 of the step of 1.25 mm. Row 1 has only one element of
  // the grid beyond its contact: left alone.
  const auto e = leading_edge_entries(r.grid, r.contact, 0.0, 1.25);
  ASSERT_EQ(e.size(), 2U);
  EXPECT_EQ(e[0].element, r.grid.index(10, 0));
  EXPECT_EQ(e[0].edge, r.grid.index(11, 0));
  EXPECT_DOUBLE_EQ(e[0].factor, 0.4);
  EXPECT_EQ(e[1].element, r.grid.index(9, 0));
  EXPECT_EQ(e[1].edge, r.grid.index(11, 0));
  EXPECT_DOUBLE_EQ(e[1].factor, 0.8);
}

TEST(LeadingEdge, RollingBackwardsHasItsEdgeAtLowIx) {
  const TwoRows r;
  const auto e = leading_edge_entries(r.grid, r.contact, std::numbers::pi, 1.25);
  ASSERT_EQ(e.size(), 4U);  // both rows: ix = 3 and 4, with the edge at ix = 2
  for (int row = 0; row < 2; ++row) {
    EXPECT_EQ(e[2 * row].element, r.grid.index(3, row));
    EXPECT_EQ(e[2 * row].edge, r.grid.index(2, row));
    EXPECT_DOUBLE_EQ(e[2 * row].factor, 0.4);
    EXPECT_EQ(e[2 * row + 1].element, r.grid.index(4, row));
    EXPECT_DOUBLE_EQ(e[2 * row + 1].factor, 0.8);
  }
}

TEST(LeadingEdge, NothingForStepsUpToOneElementOrOffTheRows) {
  const TwoRows r;
  EXPECT_TRUE(leading_edge_entries(r.grid, r.contact, 0.0, 0.5).empty());
  EXPECT_TRUE(leading_edge_entries(r.grid, r.contact, 0.0, 0.2).empty());
  EXPECT_TRUE(leading_edge_entries(r.grid, r.contact, 0.5 * std::numbers::pi, 1.25).empty());
  // Within CONTACT's 0.01 rad of χ = 0 the rows still are the rolling direction.
  EXPECT_EQ(leading_edge_entries(r.grid, r.contact, 0.005, 1.25).size(), 2U);
}

TEST(LeadingEdge, HolesInARowAreSkipped) {
  TwoRows r;
  r.contact[r.grid.index(9, 0)] = 0;
  const auto e = leading_edge_entries(r.grid, r.contact, 0.0, 1.25);
  ASSERT_EQ(e.size(), 1U);
  EXPECT_EQ(e[0].element, r.grid.index(10, 0));
}

}  // namespace
}  // namespace rollcontact::tangential
