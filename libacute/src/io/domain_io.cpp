// Domain validation, domain of a mesh, and read_domain dispatch.
#include "io/io_detail.h"

#include <acute/core/errors.h>
#include <acute/io/io.h>
#include <acute/mesh/boundary.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <set>
#include <sstream>
#include <utility>

namespace acute::io {

namespace {

struct Box {
  double xmin, xmax, ymin, ymax;
  int id;
};

Box box_of(const Point2& a, const Point2& b, int id) {
  return {std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()), std::max(a.y(), b.y()), id};
}

// Calls f(id_a, id_b) for every pair of boxes whose closed extents overlap. Sweep along x with an
// active list: near-linear for the segment sets of real domains (long overlapping boxes are rare).
template <class F>
void for_each_overlapping_pair(std::vector<Box> boxes, F&& f) {
  std::sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) {
    return a.xmin < b.xmin || (a.xmin == b.xmin && a.id < b.id);
  });
  std::vector<const Box*> active;
  for (const Box& b : boxes) {
    std::size_t kept = 0;
    for (const Box* a : active) {
      if (a->xmax < b.xmin) continue;  // left behind for good
      active[kept++] = a;
      if (a->ymax >= b.ymin && b.ymax >= a->ymin) f(a->id, b.id);
    }
    active.resize(kept);
    active.push_back(&b);
  }
}

std::string fmt_point(const Point2& p) {
  return "(" + detail::format_double(p.x()) + ", " + detail::format_double(p.y()) + ")";
}

}  // namespace

namespace detail {

void remove_duplicate_segments(Domain& domain, DomainSource* source, const WarningSink& warn) {
  const std::size_t n = domain.segments.size();
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  auto key = [&](std::size_t i) {
    const auto& s = domain.segments[i];
    return std::make_pair(std::min(s[0], s[1]), std::max(s[0], s[1]));
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  std::vector<char> drop(n, 0);
  std::size_t dropped = 0, first = n, first_kept = n;
  for (std::size_t k = 1; k < n; ++k) {
    if (key(order[k]) == key(order[k - 1])) {
      drop[order[k]] = 1;
      ++dropped;
      if (order[k] < first) {
        first = order[k];
        // the kept copy is the first one of the run
        std::size_t j = k;
        while (j > 0 && key(order[j - 1]) == key(order[k])) --j;
        first_kept = order[j];
      }
    }
  }
  if (dropped == 0) return;
  if (warn) {
    const int base = source ? source->index_base : 0;
    std::string where = domain.source_path.empty() ? "" : domain.source_path + ": ";
    if (source && !source->segment_lines.empty())
      where = source->segments_file + ":" + std::to_string(source->segment_lines[first]) + ": ";
    warn(where + std::to_string(dropped) + " repeated segment(s) dropped (first: segment " +
         std::to_string(first + base) + " repeats segment " + std::to_string(first_kept + base) + ")");
  }
  std::size_t out = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (drop[i]) continue;
    domain.segments[out] = domain.segments[i];
    if (i < domain.segment_markers.size()) domain.segment_markers[out] = domain.segment_markers[i];
    if (source && i < source->segment_lines.size()) source->segment_lines[out] = source->segment_lines[i];
    ++out;
  }
  domain.segments.resize(out);
  if (domain.segment_markers.size() > out) domain.segment_markers.resize(out);
  if (source && source->segment_lines.size() > out) source->segment_lines.resize(out);
}

void validate_domain(const Domain& d, const DomainSource* src, bool allow_crossings) {
  const int base = src ? src->index_base : 0;
  const std::string plain = d.source_path.empty() ? std::string() : d.source_path + ": ";
  auto at_point = [&](std::size_t i) {
    if (src && i < src->point_lines.size()) return src->points_file + ":" + std::to_string(src->point_lines[i]) + ": ";
    return plain;
  };
  auto at_segment = [&](std::size_t i) {
    if (src && i < src->segment_lines.size())
      return src->segments_file + ":" + std::to_string(src->segment_lines[i]) + ": ";
    return plain;
  };
  auto at_hole = [&](std::size_t i) {
    if (src && i < src->hole_lines.size()) return src->segments_file + ":" + std::to_string(src->hole_lines[i]) + ": ";
    return plain;
  };
  auto pname = [&](std::size_t i) { return "point " + std::to_string(i + base); };
  auto sname = [&](std::size_t i) {
    return "segment " + std::to_string(i + base) + " (points " + std::to_string(d.segments[i][0] + base) + "-" +
           std::to_string(d.segments[i][1] + base) + ")";
  };
  auto bad_coordinate = [](double x) {
    return std::string(std::isfinite(x) ? " is outside the exact range (0 or |x| in [2^-142, 2^201])"
                                        : " is not finite");
  };

  const std::size_t np = d.points.size(), ns = d.segments.size();
  if (!d.point_markers.empty() && d.point_markers.size() != np)
    throw InvalidInput(plain + "point_markers has " + std::to_string(d.point_markers.size()) + " entries for " +
                       std::to_string(np) + " points");
  if (!d.segment_markers.empty() && d.segment_markers.size() != ns)
    throw InvalidInput(plain + "segment_markers has " + std::to_string(d.segment_markers.size()) + " entries for " +
                       std::to_string(ns) + " segments");

  for (std::size_t i = 0; i < np; ++i)
    for (int k = 0; k < 2; ++k)
      if (!predicates::validate_coordinate(d.points[i][k]))
        throw InvalidInput(at_point(i) + pname(i) + ": " + (k ? "y = " : "x = ") + format_double(d.points[i][k]) +
                           bad_coordinate(d.points[i][k]));
  for (std::size_t i = 0; i < d.holes.size(); ++i)
    for (int k = 0; k < 2; ++k)
      if (!predicates::validate_coordinate(d.holes[i][k]))
        throw InvalidInput(at_hole(i) + "hole " + std::to_string(i + base) + ": " + (k ? "y = " : "x = ") +
                           format_double(d.holes[i][k]) + bad_coordinate(d.holes[i][k]));

  for (std::size_t i = 0; i < ns; ++i) {
    for (int k = 0; k < 2; ++k) {
      const int v = d.segments[i][k];
      if (v < 0 || static_cast<std::size_t>(v) >= np)
        throw InvalidInput(at_segment(i) + "segment " + std::to_string(i + base) + " uses point " +
                           std::to_string(v + base) + ", out of range (" + std::to_string(np) + " points)");
    }
    if (d.segments[i][0] == d.segments[i][1])
      throw InvalidInput(at_segment(i) + "segment " + std::to_string(i + base) + " has zero length (both ends at " +
                         pname(d.segments[i][0]) + ")");
  }

  // Duplicate points: exact equality after sorting.
  {
    std::vector<int> order(np);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) {
      const auto &p = d.points[a], &q = d.points[b];
      return p.x() < q.x() || (p.x() == q.x() && (p.y() < q.y() || (p.y() == q.y() && a < b)));
    });
    std::pair<int, int> worst{-1, -1};  // report the pair whose later point comes first
    for (std::size_t k = 1; k < np; ++k) {
      const int a = order[k - 1], b = order[k];
      if (d.points[a] == d.points[b]) {
        int first = a;  // the smallest index of this run
        for (std::size_t j = k - 1; j > 0 && d.points[order[j - 1]] == d.points[b]; --j) first = order[j - 1];
        if (worst.second < 0 || b < worst.second) worst = {first, b};
      }
    }
    if (worst.second >= 0)
      throw InvalidInput(at_point(worst.second) + pname(worst.second) + " duplicates " + pname(worst.first) + " at " +
                         fmt_point(d.points[worst.second]));
  }

  // Repeated, crossing and overlapping segments (exact).
  std::vector<Box> boxes;
  boxes.reserve(ns);
  for (std::size_t i = 0; i < ns; ++i)
    boxes.push_back(box_of(d.points[d.segments[i][0]], d.points[d.segments[i][1]], static_cast<int>(i)));
  struct Conflict {
    int first = -1, second = -1;
    predicates::SegmentIntersection kind{};
    bool repeated = false;
  } worst;
  for_each_overlapping_pair(std::move(boxes), [&](int i, int j) {
    if (i > j) std::swap(i, j);
    if (worst.second >= 0 && (j > worst.second || (j == worst.second && i > worst.first))) return;
    const auto& s = d.segments[i];
    const auto& t = d.segments[j];
    const bool repeated = std::min(s[0], s[1]) == std::min(t[0], t[1]) && std::max(s[0], s[1]) == std::max(t[0], t[1]);
    const auto kind = predicates::intersect_segments(d.points[s[0]], d.points[s[1]], d.points[t[0]], d.points[t[1]]);
    if (repeated || (!allow_crossings && (kind == predicates::SegmentIntersection::Proper ||
                                          kind == predicates::SegmentIntersection::Overlapping)))
      worst = {i, j, kind, repeated};
  });
  if (worst.second >= 0) {
    const std::string what = worst.repeated ? " repeats "
                             : worst.kind == predicates::SegmentIntersection::Proper ? " crosses "
                                                                                      : " overlaps ";
    throw InvalidInput(at_segment(worst.second) + sname(worst.second) + what + sname(worst.first));
  }
}

}  // namespace detail

void validate_domain(const Domain& domain, bool allow_crossings) { detail::validate_domain(domain, nullptr, allow_crossings); }

std::vector<PointOnSegment> find_points_on_segments(const Domain& d) {
  const int ns = static_cast<int>(d.segments.size());
  std::vector<Box> boxes;
  boxes.reserve(d.segments.size() + d.points.size());
  for (int i = 0; i < ns; ++i) boxes.push_back(box_of(d.points[d.segments[i][0]], d.points[d.segments[i][1]], i));
  for (std::size_t p = 0; p < d.points.size(); ++p)
    boxes.push_back(box_of(d.points[p], d.points[p], ns + static_cast<int>(p)));
  std::vector<PointOnSegment> found;
  for_each_overlapping_pair(std::move(boxes), [&](int a, int b) {
    if ((a < ns) == (b < ns)) return;  // want one segment and one point
    const int seg = std::min(a, b), pt = std::max(a, b) - ns;
    const auto& s = d.segments[seg];
    if (s[0] == pt || s[1] == pt) return;
    if (predicates::locate_on_segment(d.points[pt], d.points[s[0]], d.points[s[1]]) ==
        predicates::SegmentLocation::OnInterior)
      found.push_back({pt, seg});
  });
  std::sort(found.begin(), found.end(), [](const PointOnSegment& a, const PointOnSegment& b) {
    return a.segment < b.segment || (a.segment == b.segment && a.point < b.point);
  });
  return found;
}

namespace {

/// domain_of_mesh, and the domain point of each mesh vertex (-1: none).
Domain domain_of_mesh(const Mesh& mesh, std::vector<int>& index) {
  Domain d;
  index.assign(mesh.n_vertices(), -1);
  std::vector<VertexHandle> boundary_vertices;
  for (auto vh : mesh.vertices()) {  // skips deleted ones
    if (!mesh.is_boundary(vh) || mesh.is_isolated(vh)) continue;
    index[vh.idx()] = static_cast<int>(d.points.size());
    d.points.push_back(point2(mesh, vh));
    d.point_markers.push_back(mesh.data(vh).marker);
    boundary_vertices.push_back(vh);
  }
  // Simple loops (split at pinch vertices), so that the lowest corner of each is strictly convex.
  for (const auto& vloop : simple_boundary_loops(mesh)) {
    std::vector<int> loop;
    for (std::size_t k = 0; k < vloop.size(); ++k) {
      const VertexHandle u = vloop[k], w = vloop[(k + 1) % vloop.size()];
      loop.push_back(index[u.idx()]);
      d.segments.push_back({index[u.idx()], index[w.idx()]});
      d.segment_markers.push_back(mesh.data(mesh.edge_handle(mesh.find_halfedge(u, w))).marker);
    }
    // Orientation at the lowest-leftmost vertex (strictly convex there): boundary halfedges run
    // clockwise around the domain, so a counter-clockwise loop bounds a hole.
    const std::size_t n = loop.size();
    if (n < 3) continue;
    std::size_t low = 0;
    for (std::size_t k = 1; k < n; ++k) {
      const Point2 &p = d.points[loop[k]], &q = d.points[loop[low]];
      if (p.y() < q.y() || (p.y() == q.y() && p.x() < q.x())) low = k;
    }
    const Point2& u = d.points[loop[(low + n - 1) % n]];
    const Point2& v = d.points[loop[low]];
    const Point2& w = d.points[loop[(low + 1) % n]];
    if (predicates::orient2d(u, v, w) != Sign::Positive) continue;
    // Seed strictly inside the hole: in the ear (u, v, w) at the convex corner v, halfway from v
    // to the boundary vertex inside the ear nearest to v (perpendicular to uw), if any.
    const Point2* nearest = nullptr;
    double best = 0;
    for (std::size_t k = 0; k < d.points.size(); ++k) {
      const Point2& p = d.points[k];
      if (p == u || p == v || p == w) continue;
      if (predicates::orient2d(u, v, p) == Sign::Negative || predicates::orient2d(v, w, p) == Sign::Negative ||
          predicates::orient2d(w, u, p) == Sign::Negative)
        continue;
      const double dist = -predicates::detail::orient2d_naive(u, w, p);  // grows towards v
      if (!nearest || dist > best) {
        nearest = &p;
        best = dist;
      }
    }
    d.holes.push_back(nearest ? Point2(0.5 * (v + *nearest)) : Point2((u + v + w) / 3.0));
  }
  return d;
}

/// The edges the mesh file tags (OBJ polylines) become segments of its domain, their vertices
/// points; a tagged boundary edge is a segment already.
void add_tagged_segments(const std::string& path, const Mesh& mesh, std::vector<int> index, Domain& d) {
  std::set<std::pair<int, int>> have;
  for (const auto& s : d.segments) have.insert(std::minmax(s[0], s[1]));
  auto point_of = [&](int v) {
    if (static_cast<std::size_t>(v) >= index.size()) throw InvalidInput(path + ": polyline vertex " + std::to_string(v + 1) + " is not a mesh vertex");
    if (index[v] < 0) {
      index[v] = static_cast<int>(d.points.size());
      d.points.push_back(point2(mesh, VertexHandle(v)));
      d.point_markers.push_back(mesh.data(VertexHandle(v)).marker);
    }
    return index[v];
  };
  for (const TaggedEdge& t : read_tagged_edges(path)) {
    const int a = point_of(t.vertices[0]), b = point_of(t.vertices[1]);
    if (!have.insert(std::minmax(a, b)).second) continue;
    d.segments.push_back({a, b});
    d.segment_markers.push_back(0);
  }
}

}  // namespace

Domain domain_of_mesh(const Mesh& mesh) {
  std::vector<int> index;
  return domain_of_mesh(mesh, index);
}

Domain read_domain(const std::string& path, const WarningSink& warn, const ReadOptions& options) {
  const std::string ext = detail::extension_of(path);
  if (ext == ".poly") return read_poly(path, warn, options);
  if (ext == ".json") return read_cgshop(path, warn, options);
  if (ext == ".node" && !std::ifstream(detail::with_extension(path, ".ele"))) {
    // A point set: Triangle meshes its convex hull.
    detail::NodeList nodes = detail::read_node_file(path, warn);
    Domain d;
    d.points = std::move(nodes.points);
    d.point_markers = std::move(nodes.markers);
    d.convex_hull = true;
    d.name = detail::stem_of(path);
    d.source_path = path;
    detail::DomainSource source;
    source.points_file = path;
    source.point_lines = std::move(nodes.lines);
    source.index_base = nodes.base;
    detail::validate_domain(d, &source);
    return d;
  }
  if (is_mesh_path(path)) {
    const Mesh mesh = read_mesh(path, warn);
    std::vector<int> point_of_vertex;
    Domain d = domain_of_mesh(mesh, point_of_vertex);
    add_tagged_segments(path, mesh, std::move(point_of_vertex), d);
    d.name = detail::stem_of(path);
    d.source_path = path;
    validate_domain(d);
    return d;
  }
  throw IoError(path + ": unknown domain format '" + ext + "' (expected .poly, .json, .off, .obj, .ply, .node, .ele)");
}

bool is_mesh_path(const std::string& path) {
  const std::string ext = detail::extension_of(path);
  return ext == ".off" || ext == ".obj" || ext == ".ply" || ext == ".node" || ext == ".ele";
}

}  // namespace acute::io
