// Layer: cvt (private). Interior samples on nested equilateral lattices: the vertices of a
// triangular grid refined by halving (each lattice triangle split in four) wherever the size
// field asks for a finer spacing. Where h is uniform the samples are a perfect hexagonal
// arrangement, which is already a centroidal Voronoi tessellation: the optimiser only has to
// settle the boundary rows and the seams between levels, instead of every random sample.
#pragma once

#include <acute/core/types.h>
#include <acute/cvt/size_field.h>

#include <array>
#include <cstdint>
#include <vector>

namespace acute::detail {

class NestedLattice {
 public:
  /// Levels from the top spacing (>= every h of the field, so the coarsest triangles are few)
  /// down to the finest one the field needs; the spacing of the field's largest h is one of them,
  /// so a uniform field gets its exact spacing. `lo`/`hi`: the bounding box to cover. `seed`
  /// shifts the lattice by a fraction of its finest spacing (another seed, other points).
  NestedLattice(const SizeField& field, const Point2& lo, const Point2& hi, unsigned seed);

  /// Appends the lattice points strictly inside triangle (a, b, c) (counter-clockwise): the
  /// vertices of the leaf triangles of the refinement that overlap it, a lattice triangle of
  /// spacing s being split while h at its centre is below s / sqrt(2) (so the spacing is within
  /// a factor sqrt(2) of h). `hint`: the size field's walk hint.
  void points_in_triangle(const Point2& a, const Point2& b, const Point2& c, int& hint, std::vector<Point2>& out);

 private:
  using Key = std::array<std::int64_t, 2>;  ///< lattice coordinates in units of the finest spacing
  struct Cell {
    Key v[3];
    int level;
  };
  Point2 at(const Key& k) const;
  void sort_unique_keys();
  void radix_sort_packed();  ///< packed_ in increasing order, 16 bits a pass

  const SizeField& field_;
  Point2 origin_;
  double fine_ = 1;  ///< spacing of level 0
  int top_ = 0;      ///< the coarsest level
  std::vector<Cell> stack_;
  std::vector<Key> keys_;
  std::vector<std::uint64_t> packed_, scratch_;  ///< radix sort buffers
  std::vector<std::size_t> counts_;
};

}  // namespace acute::detail
