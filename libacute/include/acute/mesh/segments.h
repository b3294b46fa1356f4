// Layer: mesh. The table of input segments stored inside the mesh (a mesh property), so a mesh is
// self-contained: vertices on a segment can slide along its exact input line, with or without the Domain.
#pragma once

#include <acute/mesh/mesh.h>

#include <array>
#include <cstdint>
#include <vector>

namespace acute {

using SegmentTable = std::vector<std::array<Point2, 2>>;

/// Stores the endpoints of every input segment (indexed by segment id) in the mesh.
void set_segment_table(Mesh& mesh, SegmentTable table);

/// Gives `to` the table of `from` without copying it (the two meshes share it).
void share_segment_table(Mesh& to, const Mesh& from);

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

/// Whether the points of a chain along a segment of this direction must advance strictly in `axis`
/// (0: x, 1: y): in x wherever the segment varies in x (a referee walks a segment's chain along x
/// unless its ends share x, and needs every point to advance), in y where it varies in y and y
/// dominates. Elsewhere (y on a segment whose x dominates) consecutive points may share the
/// coordinate: a nearly horizontal wall a few ulps high in y takes as many Steiner points as its
/// length allows, where strict order in y allowed a few (stress seed 32: a 1e-6 notch on a wall
/// 2e-15 out of level kept a 166-degree sliver).
bool advances_strictly(const Point2& direction, int axis);

/// True when p lies between lo and hi in the order of a segment chain (exact comparisons): in
/// each coordinate in which the segment `ends` is not constant, strictly where advances_strictly,
/// else between or equal. This is how the points of a segment chain must be ordered for the chain
/// to be read back as the segment; on a nearly vertical segment a few ulps wide in x it bounds
/// the number of Steiner points.
bool strictly_between_along(const std::array<Point2, 2>& ends, const Point2& lo, const Point2& p, const Point2& hi);

/// How many points a segment chain can hold strictly between a and b (the ends of a segment piece):
/// the doubles strictly between them in each coordinate that must advance strictly
/// (advances_strictly), the fewest of those. Huge but for near-degenerate pieces: a wall 1e-15 out
/// of plumb spans a few doubles in x, so it carries only a few Steiner points however long it is.
std::uint64_t chain_capacity(const Point2& a, const Point2& b);

/// The same for a vertex's two neighbours lo and hi along its segment, the segment's direction
/// given (their difference will do): where they agree p must equal them.
bool in_chain_order(const Point2& direction, const Point2& lo, const Point2& p, const Point2& hi);

/// Distance of p from the line through ends divided by the segment length (exact, rounded once).
double line_deviation(const std::array<Point2, 2>& ends, const Point2& p);

/// The largest line_deviation of a point placed on a segment (2^-34 ~ 5.8e-11, a 1.7x margin under
/// the 1e-10 a referee allows for rounded coordinates). On a segment too short for its distance
/// from the origin (1e-7 long at 1e3: an ulp is 1e-6 of it) only a few doubles come that close;
/// splits and moves elsewhere are refused, so the segment keeps fewer Steiner points.
constexpr double kMaxSegmentDeviation = 0x1p-34;

/// line_deviation(ends, p) <= kMaxSegmentDeviation.
bool close_enough_to_line(const std::array<Point2, 2>& ends, const Point2& p);

/// A point of doubles at most 4096 ulps (along the dominant axis) or 1/64 of the segment from q (q itself when it is already within 2^-42 of
/// the segment length of the line) that minimises line_deviation: rounding a point of a short
/// segment far from the origin (1e-5 long at 1e3) puts it ~1e-9 of the length off the line, which
/// is visible as a gap or overlap; among the nearby doubles some are 100x closer.
/// lo/hi as for project_on_line.
Point2 snap_to_line(const std::array<Point2, 2>& ends, const Point2& q, const Point2* lo = nullptr,
                    const Point2* hi = nullptr);

}  // namespace acute
