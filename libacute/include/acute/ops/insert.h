// Layer: ops. Point location by walking, and point insertion (in a face, on an edge, on a
// constrained segment) followed by local Delaunay restoration.
#pragma once

#include <acute/mesh/mesh.h>

#include <vector>

namespace acute {

enum class LocationKind {
  InFace,    ///< strictly inside face
  OnEdge,    ///< on the interior of edge
  OnVertex,  ///< equal to vertex
  Blocked    ///< the walk reached a boundary or constrained edge (`edge`) that separates p from the start
};

struct Location {
  LocationKind kind = LocationKind::Blocked;
  FaceHandle face;
  EdgeHandle edge;
  VertexHandle vertex;
};

/// Walks from face `start` towards p with exact orientation tests, never crossing a boundary
/// or constrained edge. \pre start is a valid face
Location locate(const Mesh& mesh, const Point2& p, FaceHandle start);

/// Inserts p where `locate` finds it and restores the constrained Delaunay property around it.
/// On a constrained edge the new vertex is VertexKind::OnSegment (the edge halves keep the
/// segment id). Returns the new vertex (or the existing one when p is a vertex); an invalid
/// handle when blocked (then `blocked_edge` is set if given) or when p falls on an unconstrained
/// boundary edge (a frozen border, e.g. of a region copy), which is never split.
VertexHandle insert_point(Mesh& mesh, const Point2& p, FaceHandle start, EdgeHandle* blocked_edge = nullptr);

/// insert_point walking from each face at `from` in turn until a walk is not blocked (a walk never
/// crosses a constrained edge, so at a vertex on segments the face it starts from matters). Points
/// inserted one after another near each other are located in O(1) from the one before.
VertexHandle insert_point_from(Mesh& mesh, const Point2& p, VertexHandle from);

/// For a run of points inserted one after another: insert_point_from the vertex inserted before
/// (`previous`, skipped when invalid or deleted), then from `anchor` (a vertex on the run's side of
/// every wall, e.g. the apex of a fan) when that walk is blocked.
VertexHandle insert_point_after(Mesh& mesh, const Point2& p, VertexHandle previous, VertexHandle anchor);

/// Splits edge eh at p (which should lie on it, e.g. a midpoint rounded to doubles) and restores
/// the Delaunay property. Constrained edges: the new vertex is OnSegment and p is projected on the
/// input segment line when a segment table is present. \pre p strictly inside the edge's diamond so
/// the four new triangles are counter-clockwise (checked; returns invalid handle otherwise).
VertexHandle split_edge(Mesh& mesh, EdgeHandle eh, const Point2& p);

}  // namespace acute
