// --pictures PREFIX of `acute mesh` and `acute repair`: the mesh before and after, with bad
// triangles filled, and the angle histograms of both:
//   PREFIX_before.svg  PREFIX_after.svg  PREFIX_before_histogram.svg  PREFIX_after_histogram.svg
// "Before" is the input mesh for `repair`, and the constrained Delaunay triangulation of the
// domain (its points and segments, nothing added) for `mesh` and for domain inputs of `repair`.
#pragma once

#include <acute/io/io.h>
#include <acute/mesh/mesh.h>

#include <string>
#include <vector>

namespace acute::cli {

/// The four paths, in the order above.
std::vector<std::string> picture_paths(const std::string& prefix);

/// Fails early (before a long run) when the folder of PREFIX does not exist or a picture would
/// replace one of `outputs`. \throws IoError / InvalidInput
void check_picture_prefix(const std::string& prefix, const std::vector<std::string>& outputs);

/// Writes the four pictures with the bounds and title of `options`; returns their paths.
std::vector<std::string> write_pictures(const std::string& prefix, const Mesh& before, const Mesh& after,
                                        const io::WriteOptions& options);

/// Marks the boundary edges of a mesh read from a file as constrained, so that pictures of it
/// (the "before" picture, `acute render` without --domain) draw the boundary bold.
void mark_boundary_constrained(Mesh& mesh);

}  // namespace acute::cli
