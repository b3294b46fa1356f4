// The exact triangulation's journal: marks inside a transaction undo innermost first, and
// touched_since(mark) names what changed after the mark only (the non-obtuse solver's
// depth-first search of move sequences stands on both).
#include "repair/exact_triangulation.h"

#include <acute/delaunay/cdt.h>

#include <gtest/gtest.h>

#include <algorithm>

namespace acute::exact {
namespace {

/// Live triangles as sorted corner triples: the triangulation's shape, slots aside.
std::vector<std::array<int, 3>> shape(const Triangulation& tr) {
  std::vector<std::array<int, 3>> out;
  for (int t = 0; t < tr.n_tris(); ++t) {
    if (!tr.tri(t).alive) continue;
    auto v = tr.tri(t).v;
    std::sort(v.begin(), v.end());
    out.push_back(v);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(ExactTriangulation, marks_roll_back_innermost_first) {
  Domain d;
  d.points = {Point2(0, 0), Point2(8, 0), Point2(8, 5), Point2(0, 5), Point2(3, 2)};
  d.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  Triangulation tr = Triangulation::from_mesh(build_cdt(d));
  const auto initial = shape(tr);

  tr.begin();
  const auto outer = tr.mark();
  const int a = tr.insert(XPoint(Q(6), Q(1)), 0);
  ASSERT_GE(a, 0);
  const auto after_a = shape(tr);
  const auto inner = tr.mark();
  EXPECT_TRUE(tr.touched_since(inner).empty());
  const int b = tr.insert(XPoint(Q(5, 2), Q(4)), 0);
  ASSERT_GE(b, 0);
  EXPECT_EQ(tr.n_steiner(), 2u);

  // After the inner mark: b's star (and what its flips changed), all of it also since begin().
  const auto since_inner = tr.touched_since(inner), since_begin = tr.touched();
  for (int t : tr.fan_of(b)) EXPECT_NE(std::find(since_inner.begin(), since_inner.end(), t), since_inner.end());
  for (int t : since_inner) EXPECT_NE(std::find(since_begin.begin(), since_begin.end(), t), since_begin.end());
  EXPECT_GT(since_begin.size(), since_inner.size());

  tr.rollback_to(inner);
  EXPECT_EQ(tr.n_steiner(), 1u);
  EXPECT_EQ(shape(tr), after_a);
  tr.rollback_to(outer);
  EXPECT_EQ(tr.n_steiner(), 0u);
  EXPECT_EQ(shape(tr), initial);
  tr.rollback();
  EXPECT_EQ(shape(tr), initial);
}

}  // namespace
}  // namespace acute::exact
