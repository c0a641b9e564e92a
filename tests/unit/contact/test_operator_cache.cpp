// The operator cache of a PatchSolver: hits for the same grid, material and rolling step,
// several entries per kind, least-recently-used eviction that never removes an operator the
// current case holds.

#include <gtest/gtest.h>

#include <memory>

#include "contact/operator_cache.hpp"
#include "elastic/material.hpp"

namespace rollcontact {
namespace {

Grid grid_of(int m, double d) {
  Grid g;
  g.mx = g.my = m;
  g.dx = g.dy = d;
  return g;
}

const CombinedMaterial kSteel = elastic::combine_materials(0.28, 0.28, 8.0e4, 8.0e4);

TEST(OperatorCache, SameKeyIsBuiltOnce) {
  OperatorCache cache({});
  cache.begin_case();
  NormalOperators& a = cache.normal(grid_of(8, 0.5), kSteel);
  NormalOperators& b = cache.normal(grid_of(8, 0.5), kSteel);
  EXPECT_EQ(&a, &b);
  EXPECT_EQ(cache.builds(), 1u);
  cache.normal(grid_of(8, 0.25), kSteel);  // another element size: another operator
  EXPECT_EQ(cache.builds(), 2u);
  EXPECT_EQ(&cache.normal(grid_of(8, 0.5), kSteel), &a);  // both kept
  EXPECT_EQ(cache.builds(), 2u);
}

TEST(OperatorCache, TangentialKeyIncludesKindAndRollingStep) {
  OperatorCache cache({});
  cache.begin_case();
  const Grid g = grid_of(6, 0.5);
  TangentialOperators& steady =
      cache.tangential(g, kSteel, model::TangentialKind::SteadyRolling, 0.5, 0.0);
  EXPECT_FALSE(steady.view().symmetric);
  EXPECT_EQ(&cache.tangential(g, kSteel, model::TangentialKind::SteadyRolling, 0.5, 0.0), &steady);
  cache.tangential(g, kSteel, model::TangentialKind::SteadyRolling, 0.25, 0.0);
  EXPECT_EQ(cache.builds(), 2u);
  // A shift has no rolling step: any step gives the same operator.
  TangentialOperators& shift = cache.tangential(g, kSteel, model::TangentialKind::Shift, 0.5, 0.0);
  EXPECT_TRUE(shift.view().symmetric);
  EXPECT_EQ(&cache.tangential(g, kSteel, model::TangentialKind::Shift, 0.1, 0.2), &shift);
}

TEST(OperatorCache, InfluenceTablesAreComparedByTheirCoefficients) {
  // A C=9 table as every case of a sequence reads it again: equal contents, another object.
  auto table = std::make_shared<model::InfluenceTable>();
  table->mx = table->my = 2;
  table->dx_mm = table->dy_mm = 0.5;
  for (auto& v : table->values) v.assign(9, 0.0);
  table->values[model::InfluenceTable::zz][4] = 1.0;
  table->values[model::InfluenceTable::xx][4] = 0.8;
  table->values[model::InfluenceTable::yy][4] = 0.8;
  CombinedMaterial first = kSteel, again = kSteel, other = kSteel;
  first.table = table;
  again.table = std::make_shared<model::InfluenceTable>(*table);
  auto changed = std::make_shared<model::InfluenceTable>(*table);
  changed->values[model::InfluenceTable::zz][4] = 1.1;
  other.table = changed;
  OperatorCache cache({});
  cache.begin_case();
  NormalOperators& a = cache.normal(grid_of(4, 0.5), first);
  EXPECT_EQ(&cache.normal(grid_of(4, 0.5), again), &a);
  EXPECT_EQ(cache.builds(), 1u);
  EXPECT_NE(&cache.normal(grid_of(4, 0.5), other), &a);
  EXPECT_EQ(cache.builds(), 2u);
  cache.normal(grid_of(4, 0.5), kSteel);  // no table: the closed forms
  EXPECT_EQ(cache.builds(), 3u);
}

TEST(OperatorCache, EvictsTheLeastRecentlyUsedOfEarlierCases) {
  OperatorCacheCapacity capacity;
  capacity.normal = 2;
  OperatorCache cache({}, capacity);
  cache.begin_case();
  cache.normal(grid_of(4, 1.0), kSteel);
  cache.begin_case();
  cache.normal(grid_of(4, 2.0), kSteel);
  cache.begin_case();
  cache.normal(grid_of(4, 1.0), kSteel);  // used again: now the most recent
  cache.normal(grid_of(4, 3.0), kSteel);  // evicts 2.0, the least recent
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(cache.builds(), 3u);
  cache.normal(grid_of(4, 1.0), kSteel);
  EXPECT_EQ(cache.builds(), 3u);  // 1.0 was kept
  cache.normal(grid_of(4, 2.0), kSteel);
  EXPECT_EQ(cache.builds(), 4u);  // 2.0 had gone
}

TEST(OperatorCache, KeepsEverythingTheCurrentCaseHolds) {
  OperatorCacheCapacity capacity;
  capacity.normal = 1;
  OperatorCache cache({}, capacity);
  cache.begin_case();
  NormalOperators& first = cache.normal(grid_of(4, 1.0), kSteel);
  const Grid g1 = first.grid;
  cache.normal(grid_of(4, 2.0), kSteel);  // over capacity, but `first` is in use by this case
  EXPECT_EQ(cache.size(), 2u);
  EXPECT_EQ(first.grid.dx, g1.dx);  // still alive
  cache.begin_case();
  cache.normal(grid_of(4, 3.0), kSteel);  // a new case: the old ones may go
  EXPECT_EQ(cache.size(), 1u);
}

}  // namespace
}  // namespace rollcontact
