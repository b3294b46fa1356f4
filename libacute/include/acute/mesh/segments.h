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

/// The point of segment `id`'s supporting line nearest to p (rounded to doubles).
Point2 project_on_segment(const Mesh& mesh, int id, const Point2& p);

/// The same for a segment given by its endpoints: for hot loops that looked the segment up once
/// (the table lookup goes through a named mesh property).
Point2 project_on_line(const std::array<Point2, 2>& ends, const Point2& p);

}  // namespace acute
