// Layer: mesh. The table of input segments stored inside the mesh (a mesh property), so a mesh is
// self-contained: vertices on a segment can slide along its exact input line, with or without the Domain.
#pragma once

#include <acute/mesh/mesh.h>

#include <array>
#include <vector>

namespace acute {

using SegmentTable = std::vector<std::array<Point2, 2>>;

/// Stores the endpoints of every input segment (indexed by segment id) in the mesh.
void set_segment_table(Mesh& mesh, SegmentTable table);

/// The stored table (empty when none was set).
const SegmentTable& segment_table(const Mesh& mesh);

/// Endpoints of input segment `id`. \pre 0 <= id < segment_table(mesh).size()
const std::array<Point2, 2>& segment_endpoints(const Mesh& mesh, int id);

/// The point of segment `id`'s supporting line nearest to p, as a pair of doubles chosen by
/// snap_to_line (so it stays on the line to far better than a rounded projection on tiny segments).
Point2 project_on_segment(const Mesh& mesh, int id, const Point2& p);

/// The same for a segment given by its endpoints: for hot loops that looked the segment up once
/// (the table lookup goes through a named mesh property). With lo and hi (the neighbours along the
/// segment), only points strictly_between_along them are candidates; when there is none the result
/// is not between them (the caller checks and refuses the split or move).
Point2 project_on_line(const std::array<Point2, 2>& ends, const Point2& p, const Point2* lo = nullptr,
                       const Point2* hi = nullptr);

/// True when p lies strictly between lo and hi in every coordinate in which the segment `ends` is
/// not constant (exact comparisons). This is how the points of a segment chain must be ordered for
/// the chain to be read back as the segment (a referee walks it coordinate by coordinate); on a
/// nearly vertical segment a few ulps wide it bounds the number of Steiner points.
bool strictly_between_along(const std::array<Point2, 2>& ends, const Point2& lo, const Point2& p, const Point2& hi);

/// Distance of p from the line through ends divided by the segment length (exact, rounded once).
double line_deviation(const std::array<Point2, 2>& ends, const Point2& p);

/// A point of doubles at most 2048 ulps (along the dominant axis) from q (q itself when it is already within 2^-42 of
/// the segment length of the line) that minimises line_deviation: rounding a point of a short
/// segment far from the origin (1e-5 long at 1e3) puts it ~1e-9 of the length off the line, which
/// is visible as a gap or overlap; among the nearby doubles some are 100x closer.
/// lo/hi as for project_on_line.
Point2 snap_to_line(const std::array<Point2, 2>& ends, const Point2& q, const Point2* lo = nullptr,
                    const Point2* hi = nullptr);

}  // namespace acute
