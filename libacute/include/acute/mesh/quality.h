// Layer: mesh. Angle and shape statistics with the same definitions as shared/tools/meshcheck.
// Reporting only (floating point): decisions use the exact predicates instead.
#pragma once

#include <acute/core/domain.h>
#include <acute/mesh/mesh.h>

#include <array>
#include <optional>
#include <vector>

namespace acute {

struct QualityOptions {
  double min_angle_deg = 30.0;  ///< "below min" threshold
  double max_angle_deg = 90.0;  ///< "above max" threshold (an angle >= it is a violation)
  bool histogram = false;
};

/// A sector between consecutive segments around an input point, inside the domain, narrower than
/// the min bound: no mesher can avoid an angle that small there.
struct ForcedCorner {
  int point = -1;       ///< index of the input point
  double angle_deg = 0;
};

struct QualityReport {
  std::size_t n_vertices = 0;   ///< vertices used by triangles
  std::size_t n_triangles = 0;
  std::optional<std::size_t> n_steiner;  ///< with a domain: vertices not at an input point
  double min_angle = 0, max_angle = 0;   ///< degrees
  double min_angle_bound = 30, max_angle_bound = 90;
  std::size_t n_below_min = 0;   ///< triangles with an angle < min bound
  std::size_t n_above_max = 0;   ///< triangles with an angle > max bound (+1e-9)
  std::size_t n_at_max = 0;      ///< triangles whose max angle is within 1e-9 of the max bound
  std::size_t n_max_violations = 0;  ///< triangles with an angle not strictly below the max bound
  std::size_t n_right = 0;       ///< max angle within 1e-9 of 90
  std::size_t n_obtuse = 0;      ///< max angle above 90 + 1e-9
  double mean_min_angle = 0, std_min_angle = 0;
  double mean_max_angle = 0, std_max_angle = 0;
  double q_min = 0, q_mean = 0;  ///< Q = 2*sqrt(3)*S/(p*h)
  std::vector<ForcedCorner> forced_corners;  ///< with a domain
  std::optional<double> free_min_angle;      ///< min angle over triangles not incident on a forced corner
  std::size_t n_free_triangles = 0;
  std::size_t n_below_min_free = 0;
  std::array<std::size_t, 18> histogram{};   ///< 10-degree bins of all 3T angles (right angles excluded)
  std::size_t histogram_right = 0;           ///< angles within 1e-9 of 90
  bool has_histogram = false;

  double pct(std::size_t n) const { return n_triangles ? 100.0 * double(n) / double(n_triangles) : 0.0; }
};

/// The angles of triangle (a, b, c) at a, b, c in degrees, as atan2(|cross|, dot).
std::array<double, 3> triangle_angles_deg(const Point2& a, const Point2& b, const Point2& c);

/// Statistics of a mesh; with a domain also Steiner points and forced corners. Faces are read
/// from their first vertex (the one given first to add_face), as meshcheck reads file order.
/// Forced corners come from the domain alone (first overload below), as meshcheck finds them.
QualityReport measure_quality(const Mesh& mesh, const QualityOptions& options = {}, const Domain* domain = nullptr);

/// Forced corners of a domain: sectors narrower than min_angle_deg (less 1e-9) between consecutive
/// segments around an input point, on the domain side, sorted by angle. The domain is the PSLG as
/// meshcheck models it (repeated points merged, segments split at input points on them, Triangle
/// `-p` faces: bounded faces of the segments minus faces holding a hole seed; convex_hull is
/// ignored). Crossing segments are not supported (validate_domain rejects them).
std::vector<ForcedCorner> forced_corners(const Domain& domain, double min_angle_deg);

/// Same, deciding "on the domain side" with a mesh of the domain instead: a sector is in the
/// domain when some triangle corner at the mesh vertex at that point lies in it. Exact and cheap,
/// but only meaningful for a mesh that conforms to the domain (a point missing from the mesh has
/// no forced corner, and Steiner points rounded off a slanted segment can hide a corner).
std::vector<ForcedCorner> forced_corners(const Domain& domain, double min_angle_deg, const Mesh& mesh);

/// The widest triangle corner that leaves the other two angles summing to at least 2 max_angle, so
/// one of them not below max_angle: pi - 2 max (radians; 0 or less from max 90 degrees on). A corner
/// at a forced vertex (an apex gap) must be wider than this, and a sector this narrow cannot be met.
double narrowest_feasible_corner(double max_angle);

/// Input sectors (as forced_corners models them) where no mesh can meet the bounds, sorted by
/// angle. A triangle's corner a in the sector leaves 180 - a for its other two angles, so only
/// a in (180 - 2 max, 180 - 2 min] can keep them in [min, max). A sector below min is one such
/// corner (its own small angle is allowed): unsatisfiable when it is at most 180 - 2 max (with
/// max 85, any sector under 10 degrees). A wider sector is cut into corners that are also in
/// [min, max): unsatisfiable when no number k of corners from that interval sums to it (only
/// with bounds close together, e.g. 50 and 65 against a 70-degree sector).
std::vector<ForcedCorner> unsatisfiable_sectors(const Domain& domain, double min_angle_deg, double max_angle_deg);

}  // namespace acute
