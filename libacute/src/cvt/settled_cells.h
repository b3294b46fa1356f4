// Layer: cvt (private). Cells a lattice start has settled already, read off the mesh.
#pragma once

#include <acute/cvt/size_field.h>
#include <acute/mesh/mesh.h>

#include <vector>

namespace acute::detail {

/// Per vertex index, the spacing s of a vertex whose Voronoi cell is by construction a regular
/// hexagon in a density too even to move it by more than `max_move` * h, 0 for every other
/// vertex. Such a vertex is a free interior vertex whose six neighbours lie at one distance s and
/// 60 degrees apart (a lattice point whose star the CDT kept: in a Delaunay mesh its cell is then
/// the hexagon of its six triangles' centres), with no constrained edge around it, and a size
/// field whose slope over the star, fitted to h at the seven points, moves the hexagon's centroid
/// by at most half of `max_move` * h. (The centroid of a regular hexagon of spacing s under a
/// density rho = h^-4 shifts by (5 s^2 / 72) |grad rho| / rho = (5 s^2 / 18) |grad h| / h.)
/// `h` receives h at every vertex; both vectors are sized to the mesh.
std::vector<double> settled_cells(const Mesh& mesh, const SizeField& field, double max_move, std::vector<double>& h);

/// The energy, the integral of rho |x - v|^2 over the cell, of a settled vertex of spacing s and
/// size h: (5 sqrt(3) / 72) s^4 / h^4.
double settled_cell_energy(double s, double h);

}  // namespace acute::detail
