// Layer: io. CG:SHOP 2025 solutions ("Minimum Non-Obtuse Triangulations"): the Steiner points of a
// triangulation of an instance and its edges, with coordinates written exactly.
#pragma once

#include <acute/core/domain.h>
#include <acute/mesh/mesh.h>

#include <array>
#include <string>
#include <vector>

namespace acute::io {

/// The exact value of a finite double as text: an integer ("-12", any size) or "p/q" in lowest
/// terms (q a power of two). \throws InvalidInput for NaN or infinity.
std::string exact_rational(double x);

/// Exact text of a vertex's coordinates. A vertex on an input segment (kind OnSegment, segment
/// table set) whose double position is off the segment's exact line (rounding, on slanted
/// segments) is written as the point a + t (b - a) of the segment, t its double parameter: a
/// dyadic rational exactly on the segment, within about an ulp of the double. Other vertices:
/// exact_rational of their doubles.
std::array<std::string, 2> exact_coordinates(const Mesh& mesh, VertexHandle vh);

/// OFF with exact coordinates (exact_coordinates; "p/q" tokens, as meshcheck and CG:SHOP tools
/// read them; not every OFF reader does). Deleted elements skipped. Atomic. \throws IoError
/// `exact`, when given, holds each vertex's exact coordinates (by index; e.g. from
/// non_obtuse_triangulation) and replaces exact_coordinates.
using ExactCoordinates = std::vector<std::array<std::string, 2>>;
void write_off_exact(const Mesh& mesh, const std::string& path, const ExactCoordinates* exact = nullptr);

struct CgshopSolution {
  std::string instance_uid;
  std::vector<Point2> steiner_points;        ///< mesh vertices that are not domain points, in vertex order
  std::vector<std::array<std::string, 2>> steiner_exact;  ///< their exact coordinates (exact_coordinates)
  std::vector<std::array<int, 2>> edges;     ///< every mesh edge; index < n_points: domain point, else Steiner
  std::size_t n_points = 0;                  ///< domain points (the instance's points)
};

/// The solution a mesh of `domain` represents: a mesh vertex at a domain point (exact) is that
/// point, any other used vertex a Steiner point. \throws InvalidInput when a domain point is not a
/// mesh vertex (the triangulation would not be valid).
CgshopSolution make_cgshop_solution(const Mesh& mesh, const Domain& domain, const ExactCoordinates* exact = nullptr);

/// Writes {"content_type": "CG_SHOP_2025_Solution", "instance_uid", "steiner_points_x",
/// "steiner_points_y", "edges", "meta"}: a coordinate is a JSON integer when it is one (|x| < 2^53),
/// else an exact string "p/q" (or an integer string). Atomic. \throws IoError, InvalidInput.
void write_cgshop_solution(const CgshopSolution& solution, const std::string& path);
void write_cgshop_solution(const Mesh& mesh, const Domain& domain, const std::string& path,
                           const ExactCoordinates* exact = nullptr);

}  // namespace acute::io
