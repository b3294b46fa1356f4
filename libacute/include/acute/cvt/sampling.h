// Layer: cvt. The initial vertices of a CVT mesh: input points, the segments divided at the
// target spacing, and the interior seeded on nested equilateral lattices (or at random); built
// into a CDT.
#pragma once

#include <acute/core/domain.h>
#include <acute/cvt/size_field.h>
#include <acute/mesh/mesh.h>
#include <acute/mesh/segments.h>

#include <cstddef>

namespace acute {

/// How interior points are seeded.
enum class InteriorSampling {
  Lattice,  ///< nested equilateral lattices, the spacing within sqrt(2) of h (hexagonal where h is uniform)
  Random,   ///< stratified random, density 2 / (sqrt(3) h^2)
};

struct SamplingParams {
  unsigned seed = 1;          ///< std::mt19937 seed (random sampling): same seed, same points
  bool sample_interior = true;
  InteriorSampling interior = InteriorSampling::Lattice;
};

struct SamplingStats {
  std::size_t boundary_samples = 0;  ///< new points on segments
  std::size_t interior_samples = 0;
  std::size_t small_angle_apices = 0;  ///< input points with a corner below 60 degrees (concentric shells)
  bool inserted_one_by_one = false;    ///< the one CDT build of every sample failed its checks (exact fallback)
};

/// Samples the domain of `input_cdt` (= build_cdt(domain)) and returns the CDT of the samples.
/// Every constrained edge of the input CDT (a piece of an input segment between input points) is
/// divided into n = max(1, round(integral of 1/h)) pieces of equal integral; at input points with a
/// corner below 60 degrees between constrained edges, the first point on every such edge is at the
/// same distance from the apex (isosceles apex triangles). Interior points (Lattice): the vertices
/// of an equilateral grid halved where h asks for it (spacing within sqrt(2) of h, exactly h where
/// h is the field's largest; density 2/(sqrt(3) s^2)); (Random): each triangle of the input CDT
/// is cut recursively into four until it expects <= 1 point (density 2/(sqrt(3) h^2)), each piece
/// then gets a point with that probability, uniformly placed. Points within sqrt(3)/4 h of a
/// constrained edge of their input triangle or its neighbours are dropped (this accounts for the
/// boundary row). All points go into one CDT build (O(n log n)); where rounding puts a point on or
/// across another feature, they are inserted one by one instead, exactly.
/// Result: input points kind Input (input_index as in the domain), segment points OnSegment with
/// data(vh).segment and data(eh).segment = ORIGINAL segment ids, interior points Free, the segment
/// table holding the original segments. Convex-hull domains (domain.convex_hull): unconstrained
/// hull edges of the input CDT become segments numbered domain.num_segments() + k (appended to
/// the table).
Mesh sample_domain(const Domain& domain, const Mesh& input_cdt, const SizeField& field, const SamplingParams& params = {},
                   SamplingStats* stats = nullptr);

/// The segment table of a domain: table[i] = {points[segments[i][0]], points[segments[i][1]]}.
SegmentTable domain_segment_table(const Domain& domain);

}  // namespace acute
