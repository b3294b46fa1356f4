#pragma once
// Layer: cvt (private). The CVT start built in the caller's mesh: see delaunay/in_place.h for why.

#include <acute/cvt/cvt.h>
#include <acute/cvt/sampling.h>

namespace acute::detail {

/// sample_domain, built in `mesh` (whatever it held is replaced).
void sample_domain_into(Mesh& mesh, const Domain& domain, const Mesh& input_cdt, const SizeField& field, const SamplingParams& params,
                        SamplingStats* stats);

/// cvt_mesh with its mesh built in `mesh` instead of `out.mesh`; every other field of `out` as
/// cvt_mesh sets it.
void cvt_mesh_into(Mesh& mesh, CvtResult& out, const Domain& domain, const CvtParams& params);

}  // namespace acute::detail
