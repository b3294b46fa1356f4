// Shared helpers of the libFuzzer targets: input files, the exception policy, and an independent
// verifier of build_cdt's output (exact predicates only, no code from the delaunay layer).
#pragma once

#include <acute/core/domain.h>
#include <acute/core/errors.h>
#include <acute/delaunay/cdt.h>
#include <acute/mesh/check.h>
#include <acute/mesh/mesh.h>
#include <acute/mesh/segments.h>
#include <acute/predicates/predicates.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace acute_fuzz {

using acute::Domain;
using acute::Mesh;
using acute::Point2;
using acute::Sign;
namespace pr = acute::predicates;

/// A finding: print it and abort, so that libFuzzer saves the input as a crash. Findings that
/// contain one of the '|'-separated texts in ACUTE_FUZZ_IGNORE (known, reported bugs) return
/// instead, so that a long run can look past them; the caller then gives up on the input.
/// ACUTE_FUZZ_ONLY=text: only findings containing text count (for -minimize_crash on one bug).
inline void fail(const std::string& what) {
  if (const char* only = std::getenv("ACUTE_FUZZ_ONLY"))
    if (what.find(only) == std::string::npos) return;
  if (const char* ignore = std::getenv("ACUTE_FUZZ_IGNORE")) {
    std::string list = ignore;
    for (std::size_t b = 0; b <= list.size();) {
      std::size_t e = list.find('|', b);
      if (e == std::string::npos) e = list.size();
      if (e > b && what.find(list.substr(b, e - b)) != std::string::npos) return;
      b = e + 1;
    }
  }
  std::fprintf(stderr, "\nFUZZ FINDING: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

/// Writes the input to a per-process file with the given extension and returns its path.
inline std::string write_input(const std::uint8_t* data, std::size_t size, const std::string& ext) {
  static const std::string dir = [] {
    const char* t = std::getenv("TMPDIR");
    std::string d = std::string(t && *t ? t : "/tmp") + "/acute_fuzz_" + std::to_string(getpid());
    std::string cmd = "mkdir -p '" + d + "'";
    if (std::system(cmd.c_str()) != 0) std::abort();
    return d;
  }();
  const std::string path = dir + "/input" + ext;
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f || (size && std::fwrite(data, 1, size, f) != size)) {
    std::perror(path.c_str());
    std::abort();
  }
  std::fclose(f);
  return path;
}

/// The library's error policy: only InvalidInput / IoError may escape a reader or build_cdt on
/// bad input, with one-line messages. Anything else (InternalError, std::out_of_range, a json
/// exception leaking...) is a finding.
template <class F>
bool run_guarded(const char* what, F&& f) {
  try {
    f();
    return true;
  } catch (const acute::InvalidInput& e) {
    if (std::string(e.what()).find('\n') != std::string::npos) fail(std::string(what) + ": multi-line InvalidInput: " + e.what());
  } catch (const acute::IoError& e) {
    if (std::string(e.what()).find('\n') != std::string::npos) fail(std::string(what) + ": multi-line IoError: " + e.what());
  } catch (const acute::Error& e) {
    fail(std::string(what) + ": unexpected acute::Error: " + e.what());
  } catch (const std::exception& e) {
    fail(std::string(what) + ": foreign exception escaped: " + e.what());
  } catch (...) {
    fail(std::string(what) + ": unknown exception escaped");
  }
  return false;
}

inline std::string str(const Point2& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x(), p.y());
  return buf;
}

struct Tri {
  Point2 p[3];
};

/// 0: outside, 1: strictly inside, 2: on the boundary (edge or corner) of the closed triangle.
inline int locate_in_triangle(const Tri& t, const Point2& q) {
  int zeros = 0;
  for (int i = 0; i < 3; ++i) {
    const Sign s = pr::orient2d(t.p[i], t.p[(i + 1) % 3], q);
    if (s == Sign::Negative) return 0;
    zeros += s == Sign::Zero;
  }
  return zeros ? 2 : 1;
}

struct CdtCheckOptions {
  bool convex_hull = false;
  bool delaunay = true;     ///< false for meshes with Steiner points moved off Delaunay (the mesher)
  bool exact_area = false;  ///< integer coordinates: the hull area can be compared exactly
};

/// Twice the area of the convex hull of the points (monotone chain, exact orientation).
inline double hull_area2(std::vector<Point2> pts) {
  std::sort(pts.begin(), pts.end(), [](const Point2& a, const Point2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
  if (pts.size() < 3) return 0;
  std::vector<Point2> h(2 * pts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && pr::orient2d(h[k - 2], h[k - 1], pts[i]) != Sign::Positive) --k;
    h[k++] = pts[i];
  }
  for (std::size_t i = pts.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && pr::orient2d(h[k - 2], h[k - 1], pts[i]) != Sign::Positive) --k;
    h[k++] = pts[i];
  }
  h.resize(k - 1);
  double a = 0;
  for (std::size_t i = 1; i + 1 < h.size(); ++i) {  // fan from h[0]: differences stay exact
    const Point2 p = h[i] - h[0], q = h[i + 1] - h[0];
    a += p.x() * q.y() - p.y() * q.x();
  }
  return a;
}

/// Is the vertex on the closed segment ab? Exact for input points; crossing points (input_index
/// -1, rounded) within 1e-12 of the segment's length (+16 ulps of the coordinates) count too.
inline bool on_segment(const Mesh& mesh, acute::VertexHandle vh, const Point2& a, const Point2& b) {
  const Point2 q = acute::point2(mesh, vh);
  if (pr::locate_on_segment(q, a, b) != pr::SegmentLocation::Outside) return true;
  if (mesh.data(vh).input_index != -1) return false;
  const Point2 ab = b - a;
  const double L2 = ab.squaredNorm(), t = (q - a).dot(ab) / L2;
  if (t < 0 || t > 1) return false;
  // Rounding the crossing to doubles moves it by about an ulp of the coordinates' magnitude.
  const double mag = std::max({std::abs(a.x()), std::abs(a.y()), std::abs(b.x()), std::abs(b.y())});
  return (q - a - t * ab).norm() <= 1e-12 * std::sqrt(L2) + 16 * 0x1p-52 * mag;
}

/// A double in full (std::to_string prints 1e-12 as 0.000000).
inline std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

/// How far the mesh area may honestly differ from the domain's (not twice): a Steiner point on a
/// segment may sit off its exact line by acute::kMaxSegmentDeviation times the segment's length
/// (the nearest doubles; the referee allows 1e-10), which moves the boundary by a triangle of at
/// most half that times the length squared; plus 1e-9 relative for summing the areas.
inline double area_slack(const Mesh& mesh, double area) {
  double slack = 1e-9 * std::abs(area);
  const acute::SegmentTable& table = acute::segment_table(mesh);
  for (auto vh : mesh.vertices()) {
    const auto& d = mesh.data(vh);
    if (d.kind != acute::VertexKind::OnSegment || d.segment < 0 || static_cast<std::size_t>(d.segment) >= table.size()) continue;
    const auto& ends = table[static_cast<std::size_t>(d.segment)];
    slack += 0.5 * acute::kMaxSegmentDeviation * (ends[1] - ends[0]).squaredNorm();
  }
  return slack;
}

/// Checks a CDT of `domain` independently; returns the first problem or "".
inline std::string verify_cdt(const Mesh& mesh, const Domain& domain, const CdtCheckOptions& opt) {
  const acute::CheckReport rep = acute::check_mesh(mesh, opt.delaunay ? acute::CheckLevel::Delaunay : acute::CheckLevel::Geometry, 100000);
  if (!rep.ok()) return "check_mesh: " + rep.summary(1);

  std::vector<Tri> tris;
  double area2 = 0;
  for (auto fh : mesh.faces()) {
    Tri t;
    int k = 0;
    for (auto vh : mesh.fv_range(fh)) t.p[k++ % 3] = acute::point2(mesh, vh);
    if (k != 3) return "face " + std::to_string(fh.idx()) + ": not a triangle";
    tris.push_back(t);
    area2 += (t.p[1] - t.p[0]).x() * (t.p[2] - t.p[0]).y() - (t.p[1] - t.p[0]).y() * (t.p[2] - t.p[0]).x();
  }
  std::map<std::pair<double, double>, acute::VertexHandle> at;
  for (auto vh : mesh.vertices()) at[{mesh.point(vh)[0], mesh.point(vh)[1]}] = vh;
  auto vertex_at = [&](const Point2& p) {
    auto it = at.find({p.x(), p.y()});
    return it == at.end() ? acute::VertexHandle() : it->second;
  };
  auto in_closure = [&](const Point2& q) {
    for (const Tri& t : tris)
      if (locate_in_triangle(t, q)) return true;
    return false;
  };

  // Input vertices carry their input index and sit at that point.
  for (auto vh : mesh.vertices()) {
    const auto& d = mesh.data(vh);
    // Crossing points (CrossingSegments::Split) are Input vertices without an input index.
    if (d.kind != acute::VertexKind::Input || d.input_index == -1) continue;
    if (d.input_index < 0 || static_cast<std::size_t>(d.input_index) >= domain.points.size())
      return "vertex " + std::to_string(vh.idx()) + ": input_index " + std::to_string(d.input_index) + " out of range";
    if (acute::point2(mesh, vh) != domain.points[static_cast<std::size_t>(d.input_index)])
      return "vertex " + std::to_string(vh.idx()) + ": not at input point " + std::to_string(d.input_index);
  }
  // Every input point in the closed meshed region is a vertex (convex hull: every point).
  for (std::size_t i = 0; i < domain.points.size(); ++i) {
    const Point2& p = domain.points[i];
    if (vertex_at(p).is_valid()) continue;
    if (opt.convex_hull && domain.holes.empty()) return "input point " + std::to_string(i) + " " + str(p) + " missing (convex hull)";
    if (in_closure(p)) return "input point " + std::to_string(i) + " " + str(p) + " lies in the mesh but is not a vertex";
  }
  // Segments are covered by edges where they run through the mesh: no mesh edge lying on a
  // segment is unconstrained, and no segment crosses a mesh edge (it would run through the inside
  // of a triangle). With CrossingSegments::Split the chains bend through rounded crossing points:
  // a crossing at an edge end that is such a point near the segment is rounding, not a gap; an
  // unconstrained edge with such an end is tolerated along the segment.
  auto near_crossing = [&](acute::VertexHandle vh, const Point2& a, const Point2& b) {
    return mesh.data(vh).input_index == -1 && on_segment(mesh, vh, a, b);
  };
  for (std::size_t s = 0; s < domain.segments.size(); ++s) {
    const Point2 a = domain.points[static_cast<std::size_t>(domain.segments[s][0])];
    const Point2 b = domain.points[static_cast<std::size_t>(domain.segments[s][1])];
    if (a == b) continue;
    for (auto eh : mesh.edges()) {
      const auto h = mesh.halfedge_handle(eh, 0);
      const auto pv = mesh.from_vertex_handle(h), qv = mesh.to_vertex_handle(h);
      const Point2 p = acute::point2(mesh, pv), q = acute::point2(mesh, qv);
      const auto kind = pr::intersect_segments(a, b, p, q);
      if (kind == pr::SegmentIntersection::Proper && !near_crossing(pv, a, b) && !near_crossing(qv, a, b))
        return "segment " + std::to_string(s) + " crosses edge " + str(p) + "-" + str(q);
      // A crossing point may land exactly on another segment's line by rounding, beside its chain.
      if (!acute::is_constrained(mesh, eh) && mesh.data(pv).input_index != -1 && mesh.data(qv).input_index != -1 &&
          pr::locate_on_segment(p, a, b) != pr::SegmentLocation::Outside &&
          pr::locate_on_segment(q, a, b) != pr::SegmentLocation::Outside)
        return "segment " + std::to_string(s) + ": edge " + str(p) + "-" + str(q) + " on it not constrained";
    }
  }
  for (auto eh : mesh.edges()) {
    const auto h = mesh.halfedge_handle(eh, 0);
    const Point2 u = acute::point2(mesh, mesh.from_vertex_handle(h)), v = acute::point2(mesh, mesh.to_vertex_handle(h));
    const int s = mesh.data(eh).segment;
    if (s < 0) {
      if (mesh.is_boundary(eh) && !opt.convex_hull)
        return "edge " + str(u) + "-" + str(v) + ": mesh boundary but not constrained";
      continue;
    }
    Point2 a, b;
    if (static_cast<std::size_t>(s) < domain.segments.size()) {
      a = domain.points[static_cast<std::size_t>(domain.segments[static_cast<std::size_t>(s)][0])];
      b = domain.points[static_cast<std::size_t>(domain.segments[static_cast<std::size_t>(s)][1])];
    } else if (opt.convex_hull && static_cast<std::size_t>(s) < acute::segment_table(mesh).size() && mesh.is_boundary(eh)) {
      // The mesher gives the hull edges of a -c domain their own segment ids (the segment table).
      a = acute::segment_table(mesh)[static_cast<std::size_t>(s)][0];
      b = acute::segment_table(mesh)[static_cast<std::size_t>(s)][1];
    } else {
      return "edge " + str(u) + "-" + str(v) + ": segment id out of range";
    }
    if (!on_segment(mesh, mesh.from_vertex_handle(h), a, b) || !on_segment(mesh, mesh.to_vertex_handle(h), a, b))
      return "edge " + str(u) + "-" + str(v) + ": labelled segment " + std::to_string(s) + " but not on it";
  }
  // Hole seeds are not inside the mesh (on a constrained edge or a vertex is ambiguous).
  for (std::size_t i = 0; i < domain.holes.size(); ++i) {
    const Point2& q = domain.holes[i];
    for (const Tri& t : tris)
      if (locate_in_triangle(t, q) == 1) return "hole " + std::to_string(i) + " " + str(q) + " strictly inside a triangle";
    for (auto eh : mesh.edges()) {
      if (acute::is_constrained(mesh, eh) || mesh.is_boundary(eh)) continue;
      const auto h = mesh.halfedge_handle(eh, 0);
      const Point2 u = acute::point2(mesh, mesh.from_vertex_handle(h)), v = acute::point2(mesh, mesh.to_vertex_handle(h));
      if (pr::locate_on_segment(q, u, v) == pr::SegmentLocation::OnInterior)
        return "hole " + std::to_string(i) + " " + str(q) + " on an unconstrained interior edge";
    }
  }
  if (opt.convex_hull && domain.holes.empty()) {
    const double want = hull_area2(domain.points);
    const bool equal = opt.exact_area ? area2 == want : std::abs(area2 - want) <= 2.0 * area_slack(mesh, 0.5 * want);
    if (!equal) return "mesh area*2 " + num(area2) + " != convex hull area*2 " + num(want) + " (allowed difference " + num(2.0 * area_slack(mesh, 0.5 * want)) + ")";
  }
  return {};
}

/// The fuzz input as a byte stream; missing bytes read as 0.
struct Reader {
  const std::uint8_t* data;
  std::size_t size;
  std::size_t pos = 0;
  std::uint8_t next() { return pos < size ? data[pos++] : 0; }
};

/// Coordinates of the PSLG targets: points on an integer grid (4, 16, 64 or 256 per side, flags
/// bits 2-3) with a power-of-two scale and offset (bits 4-6), so the geometry stays exact in doubles.
struct GridCoordinates {
  int grid;
  double scale, offset;
  explicit GridCoordinates(std::uint8_t flags) : grid(4 << (2 * ((flags >> 2) & 3))) {
    static const double scales[8] = {1, 1, 0x1p-30, 0x1p30, 0x1p-60, 0x1p60, 1, 0x1p-20};
    static const double offsets[8] = {0, -8, 0, 0, 0, 0, 0x1p40, 0x1p-10};
    const int mode = (flags >> 4) & 7;
    scale = scales[mode];
    offset = offsets[mode];
  }
  double point(std::uint8_t b) const { return offset + scale * static_cast<double>(b % grid); }
  /// Hole seeds sit at cell centres, never on a grid point.
  double hole(std::uint8_t b) const { return offset + scale * (b % grid + 0.5); }
};

}  // namespace acute_fuzz
