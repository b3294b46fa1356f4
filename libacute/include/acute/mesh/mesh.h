// Layer: mesh. The mesh type: an OpenMesh TriMesh with double points (z = 0), status attributes,
// and the per-element data the meshing layers need (constraints, input vertices, markers).
#pragma once

#include <acute/core/domain.h>
#include <acute/core/types.h>

#include <OpenMesh/Core/Geometry/VectorT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace acute {

/// What may happen to a vertex.
enum class VertexKind : std::uint8_t {
  Free,       ///< Steiner point in the interior: may move, may be removed
  OnSegment,  ///< Steiner point on an input segment: may slide along it (see segment)
  Input       ///< input point: never moves, never removed
};

struct MeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  VertexAttributes(OpenMesh::Attributes::Status);
  HalfedgeAttributes(OpenMesh::Attributes::Status | OpenMesh::Attributes::PrevHalfedge);
  EdgeAttributes(OpenMesh::Attributes::Status);
  FaceAttributes(OpenMesh::Attributes::Status);

  VertexTraits {
   public:
    VertexKind kind = VertexKind::Free;
    int segment = -1;      ///< input segment id this vertex lies on (OnSegment), else -1
    int input_index = -1;  ///< index in Domain::points for input vertices, else -1
    int marker = 0;        ///< boundary marker (Triangle .poly semantics)
  };

  EdgeTraits {
   public:
    int segment = -1;  ///< id of the input segment this edge is part of; -1 when unconstrained
    int marker = 0;    ///< boundary marker of that segment
    bool frozen = false;  ///< border of a local copy of a mesh region: never split there
  };
};

/// The libacute mesh. Vertices carry z = 0; faces are counter-clockwise in the xy-plane.
using Mesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;
using VertexHandle = Mesh::VertexHandle;
using HalfedgeHandle = Mesh::HalfedgeHandle;
using EdgeHandle = Mesh::EdgeHandle;
using FaceHandle = Mesh::FaceHandle;

/// The 2D position of a vertex.
inline Point2 point2(const Mesh& mesh, VertexHandle vh) {
  const auto& p = mesh.point(vh);
  return Point2(p[0], p[1]);
}
inline void set_point2(Mesh& mesh, VertexHandle vh, const Point2& p) { mesh.set_point(vh, Mesh::Point(p.x(), p.y(), 0.0)); }
inline bool is_constrained(const Mesh& mesh, EdgeHandle eh) { return mesh.data(eh).segment >= 0; }
inline bool is_input(const Mesh& mesh, VertexHandle vh) { return mesh.data(vh).kind == VertexKind::Input; }

/// Relinks the boundary halfedges at every pinch vertex (several fans meeting only there, see
/// mesh/boundary.h) so that each gap between two fans is closed by the boundary halfedges that
/// bound it geometrically (exact angular order), as a mesh carved from a triangulation has them;
/// add_face leaves them in insertion order. Returns the number of pinch vertices.
std::size_t order_pinch_vertices(Mesh& mesh);

/// Builds a mesh from a user's OpenMesh triangle mesh of any traits (float or double points;
/// z is dropped). All vertices become Free; boundary edges are not marked as constraints.
/// Face order and vertex order are kept.
template <class UserMesh>
Mesh from_openmesh(const UserMesh& in) {
  Mesh out;
  out.reserve(in.n_vertices(), in.n_edges(), in.n_faces());
  for (auto vh : in.vertices()) {
    const auto& p = in.point(vh);
    out.add_vertex(Mesh::Point(static_cast<double>(p[0]), static_cast<double>(p[1]), 0.0));
  }
  for (auto fh : in.faces()) {
    VertexHandle tri[3];
    int k = 0;
    for (auto fv : in.fv_range(fh)) {
      if (k < 3) tri[k] = VertexHandle(fv.idx());
      ++k;
    }
    if (k == 3) out.add_face(tri[0], tri[1], tri[2]);
  }
  order_pinch_vertices(out);
  return out;
}

/// Copies a mesh into a user's OpenMesh mesh of any traits (cleared first). Deleted elements
/// are skipped; z = 0. Points are converted with static_cast to the user's scalar.
template <class UserMesh>
void to_openmesh(const Mesh& in, UserMesh& out) {
  using UPoint = typename UserMesh::Point;
  using UScalar = typename UPoint::value_type;
  out.clear();
  std::vector<typename UserMesh::VertexHandle> map(in.n_vertices());
  for (auto vh : in.vertices()) {
    const auto& p = in.point(vh);
    UPoint q;
    q.vectorize(UScalar(0));
    q[0] = static_cast<UScalar>(p[0]);
    q[1] = static_cast<UScalar>(p[1]);
    map[vh.idx()] = out.add_vertex(q);
  }
  for (auto fh : in.faces()) {
    std::vector<typename UserMesh::VertexHandle> f;
    for (auto fv : in.fv_range(fh)) f.push_back(map[fv.idx()]);
    out.add_face(f);
  }
}

/// Marks the mesh's boundary edges as constraints (segment ids 0..k-1 along the boundary) and
/// their vertices as Input, so a repair keeps the region exactly. Returns the number of
/// boundary edges.
int mark_boundary_as_constrained(Mesh& mesh);

/// The seeds and the `rings` rings of vertices around them, each once (seeds first). `seen`:
/// marks indexed by vertex, all zero on entry and on return (grown to the mesh's size if needed),
/// so that callers repeating this keep one buffer instead of allocating one per call.
std::vector<VertexHandle> with_rings(const Mesh& mesh, std::vector<VertexHandle> seeds, int rings, std::vector<char>& seen);

/// The non-input vertices closer than `radius` to `centre`, reached from it through such vertices
/// (a graph search: the movable vertices of a disk without a scan of the mesh).
std::vector<VertexHandle> vertices_near(const Mesh& mesh, VertexHandle centre, double radius);

/// mesh.garbage_collection() when an element is marked deleted (true then); a no-op otherwise.
/// OpenMesh's collection rebuilds every array even when nothing is deleted (0.2 s per million
/// triangles); the check is a scan of the status flags.
bool collect_garbage(Mesh& mesh);

/// A copy without deleted elements (handles renumbered densely). Use instead of calling
/// garbage_collection() while handles are held elsewhere.
Mesh compacted(const Mesh& mesh);

}  // namespace acute
