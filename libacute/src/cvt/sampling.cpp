#include <acute/cvt/sampling.h>

#include "cvt/in_place.h"
#include "delaunay/in_place.h"
#include "cvt/lattice.h"
#include "cvt/narrow_sectors.h"

#include <acute/core/errors.h>
#include <acute/delaunay/cdt.h>
#include <acute/mesh/geometry.h>
#include <acute/mesh/sectors.h>
#include <acute/mesh/segments.h>
#include <acute/ops/insert.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <random>

namespace acute {

SegmentTable domain_segment_table(const Domain& domain) {
  SegmentTable table;
  table.reserve(domain.segments.size());
  for (const auto& s : domain.segments)
    table.push_back({domain.points.at(static_cast<std::size_t>(s[0])), domain.points.at(static_cast<std::size_t>(s[1]))});
  return table;
}

namespace {

constexpr double kPi = 3.14159265358979323846;

/// Uniform double in (0, 1) from 32 random bits (portable, unlike the std distributions).
inline double unit(std::mt19937& rng) { return (static_cast<double>(rng()) + 0.5) * (1.0 / 4294967296.0); }

/// Positions along [0, L] of the interior division points of a piece [s0, s1] of segment a + s u,
/// n = max(min_pieces, round(integral of 1/h)) pieces of equal integral.
void divide(const SizeField& field, const Point2& a, const Point2& u, double s0, double s1, int& hint, std::vector<double>& out,
            int min_pieces = 1) {
  const double len = s1 - s0;
  if (!(len > 0)) return;
  auto inv_h = [&](double s) { return 1.0 / field.eval(a + s * u, hint); };
  auto integrate = [&](int k, std::vector<double>& cum) {
    cum.assign(static_cast<std::size_t>(k) + 1, 0.0);
    double prev = inv_h(s0);
    for (int i = 1; i <= k; ++i) {
      const double cur = inv_h(s0 + len * i / k);
      cum[static_cast<std::size_t>(i)] = cum[static_cast<std::size_t>(i) - 1] + 0.5 * (prev + cur) * len / k;
      prev = cur;
    }
  };
  std::vector<double> cum;
  int k = field.is_uniform() ? 1 : 16;
  integrate(k, cum);
  if (!field.is_uniform()) {
    const int k2 = static_cast<int>(std::min(200000.0, 16.0 + 4.0 * cum.back()));
    if (k2 > k) integrate(k = k2, cum);
  }
  const double total = cum.back();
  // Rounded to nearest: rounding up splits every piece slightly longer than h into two short
  // ones, which measured worse (more obtuse triangles on the classic domains).
  const int n = std::max(min_pieces, static_cast<int>(std::lround(total)));
  std::size_t i = 0;
  for (int j = 1; j < n; ++j) {
    const double target = total * j / n;
    while (i + 1 < cum.size() && cum[i + 1] < target) ++i;
    const double w = cum[i + 1] > cum[i] ? (target - cum[i]) / (cum[i + 1] - cum[i]) : 0.5;
    out.push_back(s0 + len * (static_cast<double>(i) + w) / k);
  }
}

/// Sorts points along a Z-order curve (memory locality of the mesh built from them).
void sort_morton(std::vector<Point2>::iterator first, std::vector<Point2>::iterator last) {
  if (last - first < 2) return;
  double xmin = first->x(), xmax = xmin, ymin = first->y(), ymax = ymin;
  for (auto it = first; it != last; ++it)
    xmin = std::min(xmin, it->x()), xmax = std::max(xmax, it->x()), ymin = std::min(ymin, it->y()), ymax = std::max(ymax, it->y());
  const double scale = 65535.0 / std::max({xmax - xmin, ymax - ymin, std::numeric_limits<double>::min()});
  auto spread = [](std::uint32_t v) {
    v = (v | (v << 8)) & 0x00FF00FFu;
    v = (v | (v << 4)) & 0x0F0F0F0Fu;
    v = (v | (v << 2)) & 0x33333333u;
    v = (v | (v << 1)) & 0x55555555u;
    return v;
  };
  std::vector<std::pair<std::uint32_t, Point2>> keyed;
  keyed.reserve(static_cast<std::size_t>(last - first));
  for (auto it = first; it != last; ++it) {
    const auto qx = static_cast<std::uint32_t>((it->x() - xmin) * scale), qy = static_cast<std::uint32_t>((it->y() - ymin) * scale);
    keyed.emplace_back(spread(qx) | (spread(qy) << 1), *it);
  }
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& k : keyed) *first++ = k.second;
}

/// A copy of the mesh with its faces (hence half-edges) in the order of their smallest vertex
/// index: with Z-ordered vertices, the face loops of the optimiser then walk memory coherently.
Mesh with_coherent_faces(const Mesh& in) {
  std::vector<std::array<int, 4>> faces;  // min vertex, then the three corners from that one
  faces.reserve(in.n_faces());
  for (auto fh : in.faces()) {
    int v[3], k = 0;
    for (auto vh : in.fv_range(fh)) v[k++] = vh.idx();
    const int r = v[0] < v[1] ? (v[0] < v[2] ? 0 : 2) : (v[1] < v[2] ? 1 : 2);
    faces.push_back({v[r], v[(r + 1) % 3], v[(r + 2) % 3], 0});
  }
  std::sort(faces.begin(), faces.end());
  Mesh out;
  out.reserve(in.n_vertices(), in.n_edges(), in.n_faces());
  for (auto vh : in.vertices()) {
    const auto nv = out.add_vertex(in.point(vh));
    out.data(nv) = in.data(vh);
  }
  for (const auto& f : faces) out.add_face(VertexHandle(f[0]), VertexHandle(f[1]), VertexHandle(f[2]));
  for (auto eh : in.edges()) {
    if (in.data(eh).segment < 0) continue;
    const auto h = in.halfedge_handle(eh, 0);
    const auto oh = out.find_halfedge(in.from_vertex_handle(h), in.to_vertex_handle(h));
    ACUTE_ASSERT(oh.is_valid());
    out.data(out.edge_handle(oh)) = in.data(eh);
  }
  return out;
}

/// build_cdt of the samples, true when it kept every point and every segment as one edge (no
/// point merged or found on a segment, no crossing split): the fast path of the sampler.
bool build_keeping_everything(const Domain& bd, Mesh& out) {
  try {
    CdtStats cs;
    detail::build_cdt_into(out, bd, {}, &cs);
    std::size_t constrained = 0;
    for (auto eh : out.edges()) constrained += is_constrained(out, eh) ? 1 : 0;
    return out.n_vertices() == bd.points.size() && constrained == bd.segments.size() && cs.points_on_segments == 0 &&
           cs.merged_duplicates == 0 && cs.crossings_split == 0;
  } catch (const InvalidInput&) {
    return false;
  }
}

/// The boundary mesh with the interior points added: one build_cdt over all the points and the
/// constrained edges (fast), accepted when it keeps every point and every constrained edge as
/// one edge; otherwise the points are inserted one by one (exact, slower).
Mesh with_interior_points(const Mesh& bmesh, const std::vector<Point2>& holes, const std::vector<Point2>& interior, SamplingStats& stats) {
  Domain bd;
  bd.name = "cvt samples";
  bd.holes = holes;
  for (auto vh : bmesh.vertices()) bd.points.push_back(point2(bmesh, vh));
  const std::size_t nb = bd.points.size();
  bd.points.insert(bd.points.end(), interior.begin(), interior.end());
  std::vector<EdgeHandle> seg_edge;
  for (auto eh : bmesh.edges()) {
    if (!is_constrained(bmesh, eh)) continue;
    const auto h = bmesh.halfedge_handle(eh, 0);
    bd.segments.push_back({bmesh.from_vertex_handle(h).idx(), bmesh.to_vertex_handle(h).idx()});
    bd.segment_markers.push_back(0);
    seg_edge.push_back(eh);
  }
  Mesh m;
  if (build_keeping_everything(bd, m)) {
    for (auto vh : m.vertices()) {
      auto& d = m.data(vh);
      const auto i = static_cast<std::size_t>(d.input_index);
      if (i < nb) {
        d = bmesh.data(VertexHandle(static_cast<int>(i)));
      } else {
        d = {};
        d.kind = VertexKind::Free;
      }
    }
    for (auto eh : m.edges()) {
      auto& d = m.data(eh);
      if (d.segment >= 0) d = bmesh.data(seg_edge[static_cast<std::size_t>(d.segment)]);
    }
    stats.interior_samples = interior.size();
    return m;
  }
  m = bmesh;
  FaceHandle start = *m.faces_begin();
  for (const Point2& p : interior) {
    const std::size_t before = m.n_vertices();
    const VertexHandle vh = insert_point(m, p, start);
    if (!vh.is_valid() || m.n_vertices() == before) continue;  // blocked or an existing vertex: dropped
    auto& d = m.data(vh);
    d = {};
    d.kind = VertexKind::Free;
    ++stats.interior_samples;
    for (auto fh : m.vf_range(vh)) {
      start = fh;
      break;
    }
  }
  return m;
}

/// A constrained edge of the input CDT and the points that divide it, in order from a to b.
struct Piece {
  VertexHandle a, b;
  int segment;
  std::vector<Point2> cuts;
};

/// The samples' CDT in one build over every point: the input CDT's vertices, each piece a chain
/// of constrained edges through its cuts, and the interior points. False when that build does not
/// keep every point and every chain edge as one edge (a rounded cut on or across another feature,
/// an interior point on a segment): the caller then inserts the points one by one, exactly.
bool build_at_once(const Mesh& cdt, const std::vector<Point2>& holes, const std::vector<Piece>& pieces, const std::vector<Point2>& interior,
                   const std::function<int(int)>& seg_marker, Mesh& out) {
  Domain bd;
  bd.name = "cvt samples";
  bd.holes = holes;
  const std::size_t ni = cdt.n_vertices();
  bd.points.reserve(ni + interior.size());
  for (auto vh : cdt.vertices()) bd.points.push_back(point2(cdt, vh));
  std::vector<int> chain_piece;  // piece of every chain edge
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const Piece& piece = pieces[k];
    int prev = piece.a.idx();
    for (const Point2& p : piece.cuts) {
      const int v = static_cast<int>(bd.points.size());
      bd.points.push_back(p);
      bd.segments.push_back({prev, v});
      chain_piece.push_back(static_cast<int>(k));
      prev = v;
    }
    bd.segments.push_back({prev, piece.b.idx()});
    chain_piece.push_back(static_cast<int>(k));
  }
  const std::size_t nc = bd.points.size();
  bd.points.insert(bd.points.end(), interior.begin(), interior.end());
  if (!build_keeping_everything(bd, out)) return false;
  // build_cdt keeps the points' order: vertex i is bd.points[i].
  std::vector<int> cut_piece(nc - ni, -1);
  for (std::size_t k = 0; k < bd.segments.size(); ++k)
    if (static_cast<std::size_t>(bd.segments[k][1]) >= ni) cut_piece[static_cast<std::size_t>(bd.segments[k][1]) - ni] = chain_piece[k];
  for (auto vh : out.vertices()) {
    const auto i = static_cast<std::size_t>(vh.idx());
    auto& d = out.data(vh);
    if (i < ni) {
      d = cdt.data(vh);
      d.kind = VertexKind::Input;
    } else if (i < nc) {
      const int s = pieces[static_cast<std::size_t>(cut_piece[i - ni])].segment;
      d = {};
      d.kind = VertexKind::OnSegment;
      d.segment = s;
      d.marker = seg_marker(s);
      d.input_index = -1;
    } else {
      d = {};
      d.kind = VertexKind::Free;
    }
  }
  for (auto eh : out.edges()) {
    auto& d = out.data(eh);
    if (d.segment < 0) continue;
    d.segment = pieces[static_cast<std::size_t>(chain_piece[static_cast<std::size_t>(d.segment)])].segment;
    d.marker = seg_marker(d.segment);
  }
  return true;
}

}  // namespace

Mesh sample_domain(const Domain& domain, const Mesh& cdt, const SizeField& field, const SamplingParams& params, SamplingStats* stats_out) {
  Mesh mesh;
  detail::sample_domain_into(mesh, domain, cdt, field, params, stats_out);
  return mesh;
}

void detail::sample_domain_into(Mesh& mesh, const Domain& domain, const Mesh& cdt, const SizeField& field, const SamplingParams& params,
                                SamplingStats* stats_out) {
  if (mesh.n_vertices() > 0) mesh = Mesh();
  SamplingStats stats;
  SegmentTable table = domain_segment_table(domain);
  // Segment id of every edge of the input CDT (hull edges of -c domains get new ids).
  std::vector<int> edge_seg(cdt.n_edges(), -1);
  for (auto eh : cdt.edges()) {
    int s = cdt.data(eh).segment;
    if (s < 0 && cdt.is_boundary(eh)) {
      const auto h = cdt.halfedge_handle(eh, 0);
      s = static_cast<int>(table.size());
      table.push_back({point2(cdt, cdt.from_vertex_handle(h)), point2(cdt, cdt.to_vertex_handle(h))});
    }
    edge_seg[static_cast<std::size_t>(eh.idx())] = s;
  }
  auto seg_of = [&](HalfedgeHandle h) { return edge_seg[static_cast<std::size_t>(cdt.edge_handle(h).idx())]; };
  auto seg_marker = [&](int s) {
    return static_cast<std::size_t>(s) < domain.segment_markers.size() ? domain.segment_markers[static_cast<std::size_t>(s)] : 0;
  };

  // Concentric shells: the first point on every constrained edge at a corner below 60 degrees is at
  // the same distance from the apex.
  std::vector<double> shell(cdt.n_vertices(), 0.0), strip_shell(cdt.n_vertices(), 0.0);
  // Vertices with a sector from kWideCornerDeg to 180 degrees: it needs two triangles, so a vertex
  // inside it or on its walls (a right-angled corner).
  std::vector<char> wide(cdt.n_vertices(), 0);
  const WallTest is_wall = [&](HalfedgeHandle h) { return seg_of(h) >= 0; };
  int hint = -1;
  for (auto vh : cdt.vertices()) {
    const Point2 v = point2(cdt, vh);
    bool sharp = false;
    double shortest = std::numeric_limits<double>::infinity();
    for (auto h : cdt.voh_range(vh)) {
      if (seg_of(h) < 0) continue;
      shortest = std::min(shortest, (point2(cdt, cdt.to_vertex_handle(h)) - v).norm());
      // The sector counter-clockwise from h through the faces up to the next constrained edge.
      if (cdt.is_boundary(h)) continue;
      const double radians = sweep_sector(cdt, h, is_wall, 100000).radians;
      if (radians < kPi / 3.0) sharp = true;
      if (radians >= kWideCornerDeg * kPi / 180.0 && radians < kPi) wide[static_cast<std::size_t>(vh.idx())] = 1;
    }
    if (sharp) {
      ++stats.small_angle_apices;
      shell[static_cast<std::size_t>(vh.idx())] = std::min(field.eval(v, hint), shortest / 3.0);
      const detail::StripApex apex = detail::strip_apex(cdt, vh);
      if (apex.narrowest > 0) strip_shell[static_cast<std::size_t>(vh.idx())] = apex.triangle_radius(field.eval(v, hint));
    }
  }
  // The first cut from `out`'s vertex: on the walls of a strip sector at the apex triangle's radius
  // (the size field's strip samples start there), elsewhere at the shell.
  auto first_cut = [&](HalfedgeHandle out) {
    const auto i = static_cast<std::size_t>(cdt.from_vertex_handle(out).idx());
    return strip_shell[i] > 0 && detail::bounds_strip_sector(cdt, out) ? strip_shell[i] : shell[i];
  };

  // Divide every constrained edge of the input CDT. Each cut is put on its segment's line as
  // split_edge would put it, and dropped (the piece left longer) where rounding leaves no double
  // strictly between its neighbours near enough the line.
  std::vector<Piece> pieces;
  std::vector<double> cuts;
  for (auto eh : cdt.edges()) {
    const int s = edge_seg[static_cast<std::size_t>(eh.idx())];
    if (s < 0) continue;
    const auto h = cdt.halfedge_handle(eh, 0);
    const auto va = cdt.from_vertex_handle(h), vb = cdt.to_vertex_handle(h);
    const Point2 a = point2(cdt, va), b = point2(cdt, vb);
    const double len = (b - a).norm();
    const Point2 u = (b - a) / len;
    const double ra = first_cut(h), rb = first_cut(cdt.opposite_halfedge_handle(h));
    cuts.clear();
    if (ra > 0) cuts.push_back(ra);
    // A piece between two right-angled (wide) corners is cut at least once: left whole, its
    // corners' triangles must share one interior vertex over it, and a cell of such pieces (a grid
    // of interior segments 1.4 spacings apart) was left with right angles the repair could not
    // undo (98 bad triangles after 60 s; cut in two, it meets the bounds in about a second).
    const bool between_wide = ra == 0 && rb == 0 && wide[static_cast<std::size_t>(va.idx())] && wide[static_cast<std::size_t>(vb.idx())];
    divide(field, a, u, ra, len - rb, hint, cuts, between_wide ? 2 : 1);
    if (rb > 0) cuts.push_back(len - rb);
    Piece piece{va, vb, s, {}};
    const auto& ends = table[static_cast<std::size_t>(s)];
    Point2 prev = a;
    for (double c : cuts) {
      // Interpolate from the nearer end for accuracy.
      const Point2 raw = c <= 0.5 * len ? Point2(a + c * u) : Point2(b - (len - c) * u);
      const Point2 p = project_on_line(ends, raw, &prev, &b);
      if (!strictly_between_along(ends, prev, p, b) || !close_enough_to_line(ends, p)) continue;
      piece.cuts.push_back(p);
      prev = p;
    }
    pieces.push_back(std::move(piece));
  }

  // Interior points, over the faces of the input CDT (whose few large triangles the lattice walks
  // in time linear in its points), away from the constrained edges of each face and its neighbours.
  std::vector<Point2> interior;
  if (params.sample_interior) {
    std::mt19937 rng(params.seed);
    const double density = 2.0 / std::sqrt(3.0);
    const double margin = std::sqrt(3.0) / 4.0;
    struct Tri {
      Point2 a, b, c;
      int depth;
    };
    std::vector<Tri> stack;
    std::vector<std::pair<Point2, Point2>> near_segments;
    std::vector<Point2> candidates;
    std::optional<detail::NestedLattice> lattice;
    if (params.interior == InteriorSampling::Lattice) {
      Point2 lo = point2(cdt, *cdt.vertices_begin()), hi = lo;
      for (auto vh : cdt.vertices()) lo = lo.cwiseMin(point2(cdt, vh)), hi = hi.cwiseMax(point2(cdt, vh));
      lattice.emplace(field, lo, hi, params.seed);
    }
    for (auto fh : cdt.faces()) {
      const auto fp = face_points(cdt, fh);
      near_segments.clear();
      for (auto h : cdt.fh_range(fh)) {
        const auto pushc = [&](HalfedgeHandle g) {
          if (seg_of(g) >= 0) near_segments.emplace_back(point2(cdt, cdt.from_vertex_handle(g)), point2(cdt, cdt.to_vertex_handle(g)));
        };
        pushc(h);
        const auto o = cdt.opposite_halfedge_handle(h);
        if (!cdt.is_boundary(o)) {
          pushc(cdt.next_halfedge_handle(o));
          pushc(cdt.prev_halfedge_handle(o));
        }
      }
      candidates.clear();
      if (lattice) {
        lattice->points_in_triangle(fp[0], fp[1], fp[2], hint, candidates);
      } else {
        // Stratified: the triangle cut in four until each piece expects <= 1 point.
        stack.clear();
        stack.push_back({fp[0], fp[1], fp[2], 0});
        while (!stack.empty()) {
          const Tri t = stack.back();
          stack.pop_back();
          const double area = 0.5 * signed_area2(t.a, t.b, t.c);
          const double h = field.eval((t.a + t.b + t.c) / 3.0, hint);
          const double expected = area * density / (h * h);
          if (expected > 1.0 && t.depth < 40) {
            const Point2 ab = 0.5 * (t.a + t.b), bc = 0.5 * (t.b + t.c), ca = 0.5 * (t.c + t.a);
            stack.push_back({ca, bc, t.c, t.depth + 1});
            stack.push_back({ab, t.b, bc, t.depth + 1});
            stack.push_back({ab, bc, ca, t.depth + 1});
            stack.push_back({t.a, ab, ca, t.depth + 1});
            continue;
          }
          const double draw = unit(rng);
          double r1 = unit(rng), r2 = unit(rng);
          if (draw >= expected) continue;
          if (r1 + r2 > 1.0) r1 = 1.0 - r1, r2 = 1.0 - r2;
          const Point2 p = t.a + r1 * (t.b - t.a) + r2 * (t.c - t.a);
          if (predicates::orient2d(fp[0], fp[1], p) != Sign::Positive || predicates::orient2d(fp[1], fp[2], p) != Sign::Positive ||
              predicates::orient2d(fp[2], fp[0], p) != Sign::Positive)
            continue;
          candidates.push_back(p);
        }
      }
      for (const Point2& p : candidates) {
        const double hp = field.eval(p, hint);
        bool keep = true;
        for (const auto& [sa, sb] : near_segments)
          if (distance_to_segment(p, sa, sb) < margin * hp) {
            keep = false;
            break;
          }
        if (keep) interior.push_back(p);
      }
    }
    sort_morton(interior.begin(), interior.end());
  }
  for (const Piece& piece : pieces) stats.boundary_samples += piece.cuts.size();

  if (build_at_once(cdt, domain.holes, pieces, interior, seg_marker, mesh)) {
    stats.interior_samples = interior.size();
  } else {
    // One by one: the input CDT with its constrained edges split in place (split_edge checks every
    // new triangle exactly, so no point can land on the wrong side of a nearby feature), then the
    // interior points.
    stats.inserted_one_by_one = true;
    stats.boundary_samples = 0;
    mesh = cdt;
    for (auto eh : cdt.edges())
      if (cdt.data(eh).segment < 0 && edge_seg[static_cast<std::size_t>(eh.idx())] >= 0) {
        mesh.data(eh).segment = edge_seg[static_cast<std::size_t>(eh.idx())];
        mesh.data(eh).marker = 0;
      }
    set_segment_table(mesh, table);
    for (auto vh : mesh.vertices()) mesh.data(vh).kind = VertexKind::Input;
    for (const Piece& piece : pieces) {
      VertexHandle prev = piece.a;
      for (const Point2& p : piece.cuts) {
        const auto h = mesh.find_halfedge(prev, piece.b);
        ACUTE_ASSERT(h.is_valid());
        const VertexHandle vh = split_edge(mesh, mesh.edge_handle(h), p);
        if (!vh.is_valid()) continue;  // would make a flat or inverted triangle: leave the piece longer
        auto& d = mesh.data(vh);
        d.kind = VertexKind::OnSegment;
        d.segment = piece.segment;
        d.marker = seg_marker(piece.segment);
        d.input_index = -1;
        prev = vh;
        ++stats.boundary_samples;
      }
    }
    if (!interior.empty()) mesh = with_interior_points(mesh, domain.holes, interior, stats);
    mesh = with_coherent_faces(mesh);
  }
  set_segment_table(mesh, std::move(table));
  if (stats_out) *stats_out = stats;
}

}  // namespace acute
