#include <acute/mesh/segments.h>

#include <OpenMesh/Core/Utils/Property.hh>

namespace acute {
namespace {
const char* const kSegmentTableName = "acute:segment_table";

OpenMesh::MPropHandleT<SegmentTable> table_handle(const Mesh& mesh) {
  OpenMesh::MPropHandleT<SegmentTable> mph;
  mesh.get_property_handle(mph, kSegmentTableName);
  return mph;
}
}  // namespace

void set_segment_table(Mesh& mesh, SegmentTable table) {
  auto mph = table_handle(mesh);
  if (!mph.is_valid()) mesh.add_property(mph, kSegmentTableName);
  mesh.property(mph) = std::move(table);
}

const SegmentTable& segment_table(const Mesh& mesh) {
  static const SegmentTable empty;
  const auto mph = table_handle(mesh);
  return mph.is_valid() ? mesh.property(mph) : empty;
}

const std::array<Point2, 2>& segment_endpoints(const Mesh& mesh, int id) { return segment_table(mesh).at(static_cast<std::size_t>(id)); }

Point2 project_on_segment(const Mesh& mesh, int id, const Point2& p) { return project_on_line(segment_endpoints(mesh, id), p); }

Point2 project_on_line(const std::array<Point2, 2>& ends, const Point2& p) {
  const auto& [a, b] = ends;
  const Point2 d = b - a;
  const double t = (p - a).dot(d) / d.squaredNorm();
  // Interpolate from the nearer endpoint: keeps points near an end accurate.
  return t <= 0.5 ? Point2(a + t * d) : Point2(b - (1.0 - t) * d);
}

}  // namespace acute
