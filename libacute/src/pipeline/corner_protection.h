// Private to the pipeline: protection of narrow input corners before the CVT start.
//
// A corner of the domain whose sector (between two consecutive segments at an input point) is
// narrower than ~60 degrees is covered by one isosceles "fan" triangle: both walls are cut at the
// same distance r from the apex and the chord joining the cuts becomes a constraint. The fan's base
// angles are (180 - sector) / 2, in (60, 90), whatever the sector; its apex angle is the input's own
// (exempt from the min bound when below it). Outside the chord the mesher sees only angles of at
// least 90 degrees at the cuts, which it can split. This is the corner lopping of Delaunay
// refinement (Ruppert, Shewchuk) applied to the domain.
#pragma once

#include <acute/core/domain.h>
#include <acute/mesh/mesh.h>

#include <cstddef>

namespace acute::detail {

struct CornerProtection {
  Domain domain;               ///< the domain with cut points and chords added (segments re-derived)
  std::size_t corners = 0;     ///< input points that got a fan
  std::size_t sectors = 0;     ///< sectors covered by a fan
};

/// Protects the sectors narrower than `max_sector_deg` of the domain whose constrained Delaunay
/// triangulation is `cdt` (build_domain_cdt). `size` is the target edge length (0: none); the fan
/// radius is about size / (2 sin(sector / 2)) (a chord of about the target size), at most 3 size,
/// and always below 0.4 of each wall edge and 0.45 of the distance from the apex to any feature not
/// incident to it, so fans never meet each other or another feature. Returns corners == 0 and the
/// domain unchanged when nothing needs protection (or in convex-hull mode).
CornerProtection protect_narrow_corners(const Domain& domain, const Mesh& cdt, double max_sector_deg, double size);

}  // namespace acute::detail
