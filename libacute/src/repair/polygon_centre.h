// Layer: repair (internal). Points from which a small polygon can be fanned into non-obtuse
// triangles (the "polygon centre" of a region around an obtuse triangle), in doubles: they are
// only candidates; the solver inserts them exactly and checks the result exactly.
#pragma once

#include <utility>
#include <vector>

namespace acute::exact {

using XY = std::pair<double, double>;

/// Samples of { x : for every edge pq of the counter-clockwise polygon, x lies on its inner
/// side, inside the slab between the perpendiculars at p and q, and outside the open disk on
/// diameter pq }: the triangles x p q then have no obtuse corner. Empty when none is found.
std::vector<XY> polygon_centres(const std::vector<XY>& polygon, std::size_t max_points = 6);

}  // namespace acute::exact
