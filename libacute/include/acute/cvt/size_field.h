// Layer: cvt. The target edge length h(x): uniform, or piecewise linear on a background
// triangulation (graded from the local feature size of the input).
#pragma once

#include <acute/core/domain.h>
#include <acute/core/types.h>
#include <acute/mesh/mesh.h>

#include <array>
#include <cstddef>
#include <vector>

namespace acute {

/// A positive size field h(x). Copyable and immutable once built; evaluation is thread-safe
/// (walk hints are owned by the caller).
class SizeField {
 public:
  /// Uniform h = 1.
  SizeField() = default;
  static SizeField uniform(double h);
  /// Piecewise linear on a triangulation of (part of) the plane: `values[i]` at `points[i]`,
  /// triangles counter-clockwise. Points outside it get the value of the nearest triangle reached
  /// by the walk (barycentric coordinates clamped). Visibility walks terminate on Delaunay
  /// triangulations (what from_local_feature_size builds).
  static SizeField piecewise_linear(std::vector<Point2> points, std::vector<std::array<int, 3>> triangles, std::vector<double> values);

  bool is_uniform() const { return triangles_.empty(); }
  /// h(p). `hint`: a background triangle to start the walk from (any value is accepted; updated to
  /// the triangle holding p). Ignored for a uniform field.
  double eval(const Point2& p, int& hint) const;
  double operator()(const Point2& p) const {
    int hint = -1;
    return eval(p, hint);
  }
  /// Multiplies every value by factor (> 0).
  void scale(double factor);
  /// The same background triangulation with other values, one per background point (the
  /// adjacency is shared work: refitting a field costs no triangulation).
  SizeField with_values(std::vector<double> values) const;
  double min_value() const { return min_; }
  double max_value() const { return max_; }

  /// The background triangulation (empty for a uniform field).
  const std::vector<Point2>& background_points() const { return points_; }
  const std::vector<std::array<int, 3>>& background_triangles() const { return triangles_; }
  const std::vector<double>& background_values() const { return values_; }

 private:
  int walk(const Point2& p, int start) const;
  /// h(p) interpolated along the edge of triangle t nearest p (t's rounded area is zero).
  double along_nearest_edge(int t, const Point2& p) const;
  void update_range();

  double uniform_ = 1.0;
  double min_ = 1.0, max_ = 1.0;
  std::vector<Point2> points_;
  std::vector<std::array<int, 3>> triangles_;
  std::vector<std::array<int, 3>> neighbours_;  ///< across the edge opposite corner i; -1 on the hull
  std::vector<double> values_;
};

/// The graded field's smallest size, relative to the domain's diameter: features down to this scale
/// are resolved (a coordinate still has some 10^7 representable values per such spacing), and the
/// vertex-count caps keep their cost bounded.
constexpr double kMinSizeRatio = 1e-9;
/// With a vertex count, the features alone may ask for this many times the count before their
/// sizes are coarsened (SizeFieldParams::hold_count).
constexpr double kMaxFeatureExcess = 16.0;
/// The coarsest feature-bound size, relative to the local feature size, when the features decide
/// the count. A strip of width w takes one row of acute triangles across at edges of up to 1.15 w,
/// but its square ends want an interior vertex (a 1 x 0.001 rectangle at 10 vertices: met in 1.1 s
/// at 1.0, not in 150 repair iterations at 1.15 or 1.3); debug2's 9-degree wedge at 1.0: 62k
/// vertices in 26 s against 110k in 55 s at the acute start's 0.7 (both with L-BFGS steps).
constexpr double kCoarsestLfsFactor = 1.0;
/// The graded field's default largest size, relative to the domain's diameter.
constexpr double kDefaultMaxSizeRatio = 1.0 / 25.0;

struct SizeFieldParams {
  double size = 0;                ///< > 0: field of this edge length (uniform, or at most it: graded)
  std::size_t target_vertices = 0;  ///< > 0 (and size == 0): field giving about this many vertices
  /// With target_vertices: the graded field scaled to the count (else uniform); with size: size
  /// where the features allow it, the graded field of the local feature size where they need finer
  bool graded = false;
  double gradation = 1.3;         ///< graded field: |grad h| <= gradation - 1
  double lfs_factor = 1.0;        ///< graded field: h = lfs_factor * local feature size at input points
  double hmin = 0;                ///< graded field clamp; 0: kMinSizeRatio * diameter
  double hmax = 0;                ///< graded field clamp; 0: kDefaultMaxSizeRatio * diameter
  /// Every size of the field, as the rules above give it, times this (a restart's finer start).
  /// Applied before the last step, the raise beside walls that can carry only a few Steiner
  /// points (LfsSamples::tight_walls): those need their size whatever the scale.
  double scale = 1.0;
  /// > 0: with target_vertices, the field predicts at most this many vertices (coarsening the
  /// feature-bound sizes when the features alone would need more)
  std::size_t max_vertices = 0;
  /// With target_vertices, when the features alone (the lfs-bound field) ask for more than
  /// kMaxFeatureExcess times the count, their sizes are coarsened by a common factor: false (the
  /// default) stops at kCoarsestLfsFactor times the local feature size, and the features decide
  /// the count (a strip still takes a row of acute triangles across); true goes on, when the count
  /// there is over max(kMaxFeatureExcess times the count, held_count_at_least), until the field
  /// predicts that many (near the request, but thin strips are then too coarse for the angle
  /// bounds: for a run under a time limit, which could not mesh them at their density anyway)
  bool hold_count = false;
  /// With hold_count: the count is held to no fewer vertices than this (what a run's time limit
  /// can mesh at the features' density).
  double held_count_at_least = 0;
  /// > 0: the count calibration stops after this many seconds with a field predicting at most the
  /// count (the coarsening of an over-fine feature-bound field always runs: it bounds the samples)
  double time_limit_s = 0;
  /// > 0: once this many seconds have passed (checked after the lfs samples, which are the first
  /// cost on a huge boundary), a uniform field is returned at once: the caller is past its own
  /// deadline and gives the start up (cvt_mesh: CvtResult::abandoned)
  double abandon_after_s = 0;
};

/// Area, boundary length and diameter (bounding-box diagonal) of a meshed domain.
struct DomainMeasures {
  double area = 0;
  double boundary_length = 0;
  double diameter = 0;
};
DomainMeasures measure_domain(const Mesh& mesh);

/// The uniform h for which a CVT of the domain has about n vertices: solves
/// n = 2A/(sqrt(3) h^2) + P/(2h) + 1 (equilateral triangles; V = T/2 + B/2 + 1).
double size_for_vertex_count(const DomainMeasures& measures, std::size_t n);

/// Predicted vertex count of a CVT with field h: integral of 2/(sqrt(3) h^2) over the mesh
/// (faces cut into four until they are small against h, centroid rule) + boundary length / (2 h)
/// along mesh boundary edges + 1.
double predicted_vertex_count(const Mesh& mesh, const SizeField& field);

/// Local feature size samples of the input CDT. Features: the vertices and the constrained (or
/// boundary) edges. At every vertex v: the distance to the nearest feature not incident to v.
/// (also put at the nearest point of that feature). Along every constrained edge ab, at spacing
/// about min(lfs, spacing_cap) (at least length / 16): the distance to the
/// nearest feature sharing no endpoint with ab (so two walls of a narrow channel see each other
/// all along, not only at their endpoints). Exact nearest-feature search over a bucket grid:
/// features across the whole domain count, not only CDT neighbours. Every point appears once,
/// with the smallest value any sample had there.
struct LfsSamples {
  std::vector<Point2> points;
  std::vector<double> lfs;
  /// Input vertices with a sector of at least kWideCornerDeg between their segments: one
  /// triangle cannot cover it within the angle bounds, so its sizes are never coarsened beyond the
  /// lfs factor asked for (the split needs a vertex inside the corner: at a strip's square end,
  /// an edge as long as the strip is wide leaves no room for one).
  std::vector<Point2> wide_corners;
  /// Segment pieces that can carry only a few Steiner points (chain_capacity: a wall 1e-15 out of
  /// plumb spans a few doubles in x) and the edge length they force, length / (capacity + 1): the
  /// field is at least that near them, less the gradation slope with the distance, so the mesh
  /// beside such a wall is as coarse as its edges (finer, every triangle on it was a sliver).
  struct TightWall {
    Point2 a, b;
    double edge = 0;
  };
  std::vector<TightWall> tight_walls;
};
/// The sector angle from which an input corner counts as wide (LfsSamples::wide_corners): 80
/// degrees, below the default max bound so that bounds down to 80 degrees are covered.
constexpr double kWideCornerDeg = 80.0;
LfsSamples local_feature_size_samples(const Mesh& input_cdt, double spacing_cap);

/// The graded field of the input: h = lfs_factor * lfs at the local_feature_size_samples (spacing
/// cap hmax), plus a coarse grid at hmax; clamped to [hmin, hmax] and gradation-limited along the
/// edges of the Delaunay triangulation of those points (Dijkstra), which is the background mesh.
/// *abandoned (when given) is set true where params.abandon_after_s gave the field up (a uniform
/// field at hmax comes back then).
SizeField local_feature_size_field(const Mesh& input_cdt, const SizeFieldParams& params, bool* abandoned = nullptr);

/// Chooses the field from params: for size, uniform(size), or (graded) the field of
/// local_feature_size_field capped at size (uniform when nothing needs finer; past
/// kMaxFeatureExcess times the uniform size's count at kCoarsestLfsFactor * lfs, the features then
/// deciding); for target_vertices uniform, or (graded) the graded
/// field with hmax >= the uniform size h_N for N vertices, hmax chosen so the predicted count is
/// within 2% of N. The field never exceeds lfs_factor * lfs: when the features alone need more
/// than N vertices, the count exceeds the target (hmax then the diameter), up to
/// kMaxFeatureExcess * N; beyond that the lfs-bound sizes are coarsened by a common factor, up to
/// kCoarsestLfsFactor * lfs (the features then decide the count, within max_vertices), or with
/// hold_count to about kMaxFeatureExcess * N (pathological inputs such as thousands of
/// needle-thin spikes). Else the graded field.
/// *abandoned (when given) says whether params.abandon_after_s gave the field up: then a uniform
/// field comes back and the caller gives its start up too (also when the abandon time is only
/// predicted to pass: a grading round that would outlast it is not started).
/// *features_decide (when given) says whether the field stopped at kCoarsestLfsFactor * lfs;
/// *held (when given) whether hold_count coarsened it past that.
SizeField make_size_field(const Mesh& input_cdt, const SizeFieldParams& params, bool* abandoned = nullptr,
                          bool* features_decide = nullptr, bool* held = nullptr);

}  // namespace acute
