// Small domains for the cvt tests.
#pragma once

#include <acute/core/domain.h>

namespace acute::test {

/// A polygon domain from its counter-clockwise corners.
inline Domain polygon_domain(std::vector<Point2> corners, std::string name) {
  Domain d;
  d.points = std::move(corners);
  const int n = static_cast<int>(d.points.size());
  for (int i = 0; i < n; ++i) d.segments.push_back({i, (i + 1) % n});
  d.name = std::move(name);
  return d;
}

inline Domain unit_square() { return polygon_domain({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, "unit_square"); }

/// [0,2]^2 minus [1,2]^2: area 3.
inline Domain l_shape() { return polygon_domain({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, "l_shape"); }

/// A 40-degree wedge with an interior constraint and a square hole.
inline Domain wedge_with_hole() {
  Domain d = polygon_domain({{0, 0}, {4, 0}, {4 * 0.766044443118978, 4 * 0.642787609686539}}, "wedge_with_hole");
  const int b = static_cast<int>(d.points.size());
  d.points.insert(d.points.end(), {{2.4, 0.5}, {2.8, 0.5}, {2.8, 0.9}, {2.4, 0.9}});
  for (int i = 0; i < 4; ++i) d.segments.push_back({b + i, b + (i + 1) % 4});
  d.holes.push_back({2.6, 0.7});
  return d;
}

/// The unit square with a slanted interior segment (the domain continues across it).
inline Domain square_with_segment() {
  Domain d = unit_square();
  d.name = "square_with_segment";
  d.points.insert(d.points.end(), {{0.2, 0.3}, {0.7, 0.8}});
  d.segments.push_back({4, 5});
  return d;
}

/// The unit square cut in two by an interior segment from side to side (two regions).
inline Domain split_square() {
  Domain d = polygon_domain({{0, 0}, {1, 0}, {1, 0.4}, {1, 1}, {0, 1}, {0, 0.4}}, "split_square");
  d.segments.push_back({2, 5});
  return d;
}

}  // namespace acute::test
