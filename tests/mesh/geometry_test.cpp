#include <acute/mesh/geometry.h>

#include <gtest/gtest.h>

namespace acute {
namespace {

TEST(DistanceToSegment, measures_to_the_foot_inside_and_to_the_nearer_end_beyond) {
  const Point2 a(1, 1), b(5, 1);
  EXPECT_EQ(nearest_on_segment(Point2(2, 4), a, b), Point2(2, 1));
  EXPECT_DOUBLE_EQ(distance_to_segment(Point2(2, 4), a, b), 3);
  EXPECT_EQ(nearest_on_segment(Point2(-2, 5), a, b), a);
  EXPECT_DOUBLE_EQ(distance_to_segment(Point2(-2, 5), a, b), 5);
  EXPECT_EQ(nearest_on_segment(Point2(8, -3), a, b), b);
  EXPECT_DOUBLE_EQ(distance2_to_segment(Point2(8, -3), a, b), 25);
  EXPECT_DOUBLE_EQ(distance_to_segment(Point2(3, 1), a, b), 0);
}

TEST(DistanceToSegment, a_segment_of_one_point_is_that_point) {
  const Point2 a(2, -1);
  EXPECT_EQ(nearest_on_segment(Point2(5, 3), a, a), a);
  EXPECT_DOUBLE_EQ(distance_to_segment(Point2(5, 3), a, a), 5);
}

}  // namespace
}  // namespace acute
