#include <acute/cvt/voronoi.h>

#include "cvt/site_delaunay.h"

#include <acute/mesh/geometry.h>

#include <algorithm>
#include <array>
#include <map>
#include <cmath>
#include <limits>

namespace acute {
namespace detail {

/// The Delaunay triangulation of one region's sites, kept for the next call.
struct RegionDelaunay {
  SiteDelaunay delaunay;
  std::vector<int> previous_sites;
};

struct CellScratch {
  /// Full mode, keyed by the region's first and last site (vertex idx): stable under flips, which
  /// renumber faces and so the order regions are found in.
  std::map<std::pair<int, int>, RegionDelaunay> regions;
  RegionDelaunay local;                 ///< local mode (rebuilt every call)
  SiteDelaunay::Seed seed;              ///< a region's faces, to start its sites' triangulation
  SiteDelaunay* delaunay = nullptr;     ///< the current region's
  std::size_t rebuilds = 0, flips = 0;  ///< over every region so far
  std::vector<int> face_region;          ///< per face: region id, -1 not reached
  std::vector<int> region_faces, expanded_faces, flood;
  std::vector<unsigned> face_stamp, vertex_stamp;
  unsigned face_counter = 0, vertex_counter = 0;
  std::vector<int> site_vertex;          ///< the current region's sites (vertex idx)
  std::vector<int> vertex_site;          ///< vertex idx -> site of the current region or -1
  std::vector<Point2> points;            ///< site positions
  std::vector<double> site_rho;
  std::vector<unsigned> stamp;  ///< per site: the triangle that last queued it
  unsigned counter = 0;
  std::vector<int> queue;
  /// A corner of the piece being clipped, relative to its site, with rho there (< 0: not yet
  /// evaluated) and the label of the edge to the next corner (-1: a triangle edge, else the site
  /// whose bisector it lies on).
  struct Corner {
    Point2 y;
    double rho;
    int label;
  };
  std::vector<Corner> poly, next;
  std::vector<double> side;
  std::vector<Point2> centre;     ///< per Delaunay triangle: circumcentre (a Voronoi vertex)
  std::vector<char> centre_ok;    ///< finite (the computed orientation was positive)
  std::vector<double> centre_rho; ///< rho there (< 0: not yet evaluated)
  std::vector<char> whole;        ///< per site: the cell lies inside the vertex's star (integrated whole)
  std::vector<char> calm;         ///< per site: whole, and so are all its Delaunay neighbours
  std::vector<int> fan;           ///< Delaunay triangles around a site, counter-clockwise
};

}  // namespace detail

namespace {

using detail::CellScratch;
using detail::RegionDelaunay;
using Corner = CellScratch::Corner;

/// Keeps the part of `poly` where y.d <= |d|^2 / 2 (the side of the site against the site at
/// offset d). Returns false when nothing was cut.
bool clip(CellScratch& s, const Point2& d, int label) {
  const double half = 0.5 * d.squaredNorm();
  const std::size_t n = s.poly.size();
  s.side.resize(n);
  bool cut = false;
  for (std::size_t k = 0; k < n; ++k) {
    s.side[k] = s.poly[k].y.dot(d) - half;
    cut = cut || s.side[k] > 0;
  }
  if (!cut) return false;
  s.next.clear();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t m = k + 1 == n ? 0 : k + 1;
    const double sk = s.side[k], sm = s.side[m];
    const Corner& a = s.poly[k];
    if (sk <= 0) {
      if (sm > 0) {
        if (sk < 0) {
          s.next.push_back(a);
          const Point2& b = s.poly[m].y;
          s.next.push_back({a.y + (sk / (sk - sm)) * (b - a.y), -1.0, label});  // sk, sm strictly opposite
        } else {
          s.next.push_back({a.y, a.rho, label});  // leaves the half-plane at a itself
        }
      } else {
        s.next.push_back(a);
      }
    } else if (sm < 0) {
      const Point2& b = s.poly[m].y;
      s.next.push_back({a.y + (sk / (sk - sm)) * (b - a.y), -1.0, a.label});
    }
  }
  s.poly.swap(s.next);
  return true;
}

/// Integrals over triangle (q0, q1, q2) (relative to the site) of rho (linear, values r0 r1 r2),
/// rho y and rho |y|^2, added to mass, shift, energy; returns the signed area.
inline double integrate(const Point2& q0, const Point2& q1, const Point2& q2, double r0, double r1, double r2, double& mass,
                        Point2& shift, double& energy) {
  const double area = 0.5 * ((q1 - q0).x() * (q2 - q0).y() - (q1 - q0).y() * (q2 - q0).x());
  const double rs = r0 + r1 + r2;
  const Point2 qs = q0 + q1 + q2;
  mass += area * rs / 3.0;
  shift += (area / 12.0) * (rs * qs + r0 * q0 + r1 * q1 + r2 * q2);
  // With int lambda_m lambda_k lambda_l = A/10 (m = k = l), A/30 (two equal), A/60 (distinct):
  // int rho |y|^2 = A/30 sum_m r_m (Q + q_m.(q_m + qs)), Q = (|qs|^2 + sum_k |q_k|^2) / 2.
  const double Q = 0.5 * (qs.squaredNorm() + q0.squaredNorm() + q1.squaredNorm() + q2.squaredNorm());
  energy += (area / 30.0) * (r0 * (Q + q0.dot(q0 + qs)) + r1 * (Q + q1.dot(q1 + qs)) + r2 * (Q + q2.dot(q2 + qs)));
  return area;
}

/// Whole cells: a site whose Voronoi cell V (the polygon of the circumcentres around it in the
/// Delaunay triangulation) lies within the disk B(x, r) inscribed in its mesh star (r: distance
/// to the star's outer edges; the star is star-shaped from x, so B is inside it) has V inside
/// the domain: it is integrated whole, as a fan from x. Such a cell meets only the triangles of
/// its star, so a triangle whose corners and their Delaunay neighbours all have whole cells holds
/// no other piece and is skipped (in a well-spread mesh, most of the interior).
void integrate_whole_cells(const Mesh& mesh, const SizeField& field, CellScratch& s, CellIntegrals& out, std::vector<int>& hints,
                           double rho_u) {
  const bool uniform = field.is_uniform();
  const auto& tris = s.delaunay->triangles();
  const std::size_t nt = tris.size(), ns = s.site_vertex.size();
  s.centre.resize(nt);
  s.centre_ok.resize(nt);
  s.centre_rho.assign(nt, -1.0);
  for (std::size_t t = 0; t < nt; ++t) {
    if (static_cast<std::size_t>(std::max({tris[t][0], tris[t][1], tris[t][2]})) >= ns) {  // a frame triangle
      s.centre_ok[t] = false;
      s.centre[t] = Point2(0, 0);
      continue;
    }
    const Point2& a = s.points[static_cast<std::size_t>(tris[t][0])];
    const Point2 b = s.points[static_cast<std::size_t>(tris[t][1])] - a, c = s.points[static_cast<std::size_t>(tris[t][2])] - a;
    const double d = 2.0 * (b.x() * c.y() - b.y() * c.x());
    const Point2 u((c.y() * b.squaredNorm() - b.y() * c.squaredNorm()) / d, (b.x() * c.squaredNorm() - c.x() * b.squaredNorm()) / d);
    s.centre_ok[t] = d > 0 && u.allFinite();
    s.centre[t] = s.centre_ok[t] ? Point2(a + u) : a;
  }
  s.whole.assign(ns, 0);
  for (std::size_t i = 0; i < ns; ++i) {
    const VertexHandle vh(s.site_vertex[i]);
    if (mesh.is_boundary(vh)) continue;
    bool on_constraint = false;
    for (auto eh : mesh.ve_range(vh)) on_constraint = on_constraint || is_constrained(mesh, eh);
    if (on_constraint) continue;  // its cell is cut by the segment
    const Point2 x = s.points[i];
    // The Delaunay triangles around i, counter-clockwise; the site is on the hull if the turn breaks.
    s.fan.clear();
    const int t0 = s.delaunay->vertex_triangle(static_cast<int>(i));
    int t = t0;
    double R2 = 0;
    bool closed = false;
    for (std::size_t guard = 0; guard < 4096 && t >= 0; ++guard) {
      if (!s.centre_ok[static_cast<std::size_t>(t)]) break;
      s.fan.push_back(t);
      R2 = std::max(R2, (s.centre[static_cast<std::size_t>(t)] - x).squaredNorm());
      const auto& tv = tris[static_cast<std::size_t>(t)];
      const int k = tv[0] == static_cast<int>(i) ? 0 : (tv[1] == static_cast<int>(i) ? 1 : 2);
      t = s.delaunay->across(t, (k + 1) % 3);  // across the edge from i to the corner after next
      if (t == t0) {
        closed = true;
        break;
      }
    }
    if (!closed || s.fan.size() < 3) continue;
    double r2 = std::numeric_limits<double>::infinity();
    for (auto h : mesh.voh_range(vh)) {
      const auto nh = mesh.next_halfedge_handle(h);
      r2 = std::min(r2, distance2_to_segment(x, point2(mesh, mesh.from_vertex_handle(nh)), point2(mesh, mesh.to_vertex_handle(nh))));
    }
    if (!(R2 < r2 * (1 - 1e-9))) continue;
    s.whole[i] = 1;
    const auto v = static_cast<std::size_t>(s.site_vertex[i]);
    int hint = hints[v];
    double area = 0, mass = 0, energy = 0;
    Point2 shift(0, 0);
    auto rho_at = [&](int tri) {
      double& r = s.centre_rho[static_cast<std::size_t>(tri)];
      if (r < 0) {
        const double h = field.eval(s.centre[static_cast<std::size_t>(tri)], hint);
        r = 1.0 / ((h * h) * (h * h));
      }
      return r;
    };
    for (std::size_t k = 0; k < s.fan.size(); ++k) {
      const int ta = s.fan[k], tb = s.fan[k + 1 == s.fan.size() ? 0 : k + 1];
      area += integrate(Point2(0, 0), s.centre[static_cast<std::size_t>(ta)] - x, s.centre[static_cast<std::size_t>(tb)] - x, s.site_rho[i],
                        uniform ? rho_u : rho_at(ta), uniform ? rho_u : rho_at(tb), mass, shift, energy);
    }
    out.area[v] += area;
    out.mass[v] += mass;
    out.shift[v] += shift;
    out.energy += energy;
    ++out.pieces;
  }
  s.calm.assign(ns, 0);
  for (std::size_t i = 0; i < ns; ++i) {
    if (!s.whole[i]) continue;
    bool calm = true;
    const auto [nb, nb_end] = s.delaunay->neighbours(static_cast<int>(i));
    for (const int* j = nb; j != nb_end && calm; ++j) calm = s.whole[static_cast<std::size_t>(*j)] != 0;
    s.calm[i] = calm;
  }
}

}  // namespace

CellWorkspace::CellWorkspace() : scratch(std::make_unique<detail::CellScratch>()) {}
CellWorkspace::~CellWorkspace() = default;
CellWorkspace::CellWorkspace(CellWorkspace&&) noexcept = default;
CellWorkspace& CellWorkspace::operator=(CellWorkspace&&) noexcept = default;
std::size_t CellWorkspace::delaunay_rebuilds() const { return scratch ? scratch->rebuilds : 0; }
std::size_t CellWorkspace::delaunay_flips() const { return scratch ? scratch->flips : 0; }

namespace {

bool crossable(const Mesh& mesh, HalfedgeHandle h) {
  return !mesh.is_boundary(mesh.edge_handle(h)) && !is_constrained(mesh, mesh.edge_handle(h));
}

/// Flood fill from face f0 across unconstrained edges among the faces allowed (face_stamp ==
/// allowed, or every face when allowed == 0); appends to s.region_faces and labels face_region.
void flood_region(const Mesh& mesh, int f0, int region, CellScratch& s, unsigned allowed) {
  s.region_faces.clear();
  s.flood.assign(1, f0);
  s.face_region[static_cast<std::size_t>(f0)] = region;
  while (!s.flood.empty()) {
    const int f = s.flood.back();
    s.flood.pop_back();
    s.region_faces.push_back(f);
    for (auto h : mesh.fh_range(FaceHandle(f))) {
      if (!crossable(mesh, h)) continue;
      const int g = mesh.face_handle(mesh.opposite_halfedge_handle(h)).idx();
      if (g < 0 || s.face_region[static_cast<std::size_t>(g)] != -1) continue;
      if (allowed && s.face_stamp[static_cast<std::size_t>(g)] != allowed) continue;
      s.face_region[static_cast<std::size_t>(g)] = region;
      s.flood.push_back(g);
    }
  }
}

unsigned next_stamp(std::vector<unsigned>& stamps, unsigned& counter, std::size_t size) {
  stamps.resize(size, 0);
  if (++counter == 0) {
    std::fill(stamps.begin(), stamps.end(), 0u);
    counter = 1;
  }
  return counter;
}

/// Cells of one region: sites = the vertices of `site_faces`, pieces over s.region_faces.
void region_cells(const Mesh& mesh, const SizeField& field, CellIntegrals& out, CellWorkspace& ws, const std::vector<int>& site_faces,
                  bool persistent, double rho_u) {
  const bool whole_cells = persistent;
  CellScratch& s = *ws.scratch;
  const unsigned vs = next_stamp(s.vertex_stamp, s.vertex_counter, mesh.n_vertices());
  s.site_vertex.clear();
  for (int f : site_faces)
    for (auto vh : mesh.fv_range(FaceHandle(f))) {
      auto& st = s.vertex_stamp[static_cast<std::size_t>(vh.idx())];
      if (st == vs) continue;
      st = vs;
      s.site_vertex.push_back(vh.idx());
    }
  // In vertex order, so that the same region gives the same list after flips (and its Delaunay
  // triangulation is repaired, not rebuilt).
  if (s.site_vertex.size() * 4 > mesh.n_vertices()) {
    s.site_vertex.clear();
    for (std::size_t v = 0; v < mesh.n_vertices(); ++v)
      if (s.vertex_stamp[v] == vs) s.site_vertex.push_back(static_cast<int>(v));
  } else {
    std::sort(s.site_vertex.begin(), s.site_vertex.end());
  }
  const std::size_t ns = s.site_vertex.size();
  if (ns < 3) return;
  s.points.resize(ns);
  s.site_rho.resize(ns);
  for (std::size_t i = 0; i < ns; ++i) {
    const auto v = static_cast<std::size_t>(s.site_vertex[i]);
    s.points[i] = point2(mesh, VertexHandle(s.site_vertex[i]));
    s.site_rho[i] = ws.vertex_rho[v];
    s.vertex_site[v] = static_cast<int>(i);
  }
  RegionDelaunay& rd = persistent ? s.regions[{s.site_vertex.front(), s.site_vertex.back()}] : s.local;
  const std::size_t r0 = rd.delaunay.rebuilds(), f0 = rd.delaunay.flips();
  const bool same_sites = persistent && s.site_vertex == rd.previous_sites;
  detail::SiteDelaunay::Seed* seed = nullptr;
  if (persistent && !same_sites) {
    // The region's own faces seed the sites' triangulation: it only has to be completed beyond
    // the region's border and flipped Delaunay near its constraints.
    seed = &s.seed;
    seed->triangles.clear();
    seed->border.clear();
    const int region = s.face_region[static_cast<std::size_t>(site_faces.front())];
    for (int f : site_faces) {
      std::array<int, 3> t{};
      int k = 0;
      for (auto h : mesh.fh_range(FaceHandle(f))) {
        const int from = s.vertex_site[static_cast<std::size_t>(mesh.from_vertex_handle(h).idx())];
        t[static_cast<std::size_t>(k++)] = from;
        const int g = mesh.face_handle(mesh.opposite_halfedge_handle(h)).idx();
        if (g < 0 || s.face_region[static_cast<std::size_t>(g)] != region)
          seed->border.push_back({from, s.vertex_site[static_cast<std::size_t>(mesh.to_vertex_handle(h).idx())]});
      }
      seed->triangles.push_back(t);
    }
  }
  rd.delaunay.update(s.points, same_sites, seed);
  s.rebuilds += rd.delaunay.rebuilds() - r0;
  s.flips += rd.delaunay.flips() - f0;
  if (persistent) rd.previous_sites = s.site_vertex;
  s.delaunay = &rd.delaunay;
  const bool uniform = field.is_uniform();
  if (whole_cells) {
    integrate_whole_cells(mesh, field, s, out, ws.vertex_hint, rho_u);
  } else {
    s.whole.assign(ns, 0);
    s.calm.assign(ns, 0);
  }
  auto rho_of_h = [](double h) { return 1.0 / ((h * h) * (h * h)); };
  s.stamp.resize(ns, 0);
  for (int f : s.region_faces) {
    int site[3];
    Point2 p[3];
    {
      auto h = mesh.halfedge_handle(FaceHandle(f));
      for (int k = 0; k < 3; ++k, h = mesh.next_halfedge_handle(h)) {
        const VertexHandle vh = mesh.to_vertex_handle(h);
        site[k] = s.vertex_site[static_cast<std::size_t>(vh.idx())];
        p[k] = point2(mesh, vh);
      }
    }
    out.total_area += 0.5 * signed_area2(p[0], p[1], p[2]);
    if (s.calm[static_cast<std::size_t>(site[0])] && s.calm[static_cast<std::size_t>(site[1])] && s.calm[static_cast<std::size_t>(site[2])]) continue;
    if (++s.counter == 0) {
      std::fill(s.stamp.begin(), s.stamp.end(), 0u);
      s.counter = 1;
    }
    s.queue.clear();
    for (int k : site) {
      s.stamp[static_cast<std::size_t>(k)] = s.counter;
      s.queue.push_back(k);
    }
    int hint = uniform ? -1 : ws.vertex_hint[static_cast<std::size_t>(s.site_vertex[static_cast<std::size_t>(site[0])])];
    // The sites whose bisector bounds the piece just clipped (their cells meet the triangle too).
    auto push_neighbours = [&]() {
      for (const auto& c : s.poly) {
        if (c.label < 0) continue;
        auto& st = s.stamp[static_cast<std::size_t>(c.label)];
        if (st == s.counter) continue;
        st = s.counter;
        s.queue.push_back(c.label);
      }
    };
    while (!s.queue.empty()) {
      const int i = s.queue.back();
      s.queue.pop_back();
      const Point2 x = s.points[static_cast<std::size_t>(i)];
      s.poly.clear();
      for (int k = 0; k < 3; ++k) s.poly.push_back({p[k] - x, s.site_rho[static_cast<std::size_t>(site[k])], -1});
      const auto [nb, nb_end] = s.delaunay->neighbours(i);
      for (const int* j = nb; j != nb_end && s.poly.size() >= 3; ++j) clip(s, s.points[static_cast<std::size_t>(*j)] - x, *j);
      if (s.poly.size() < 3) continue;
      if (s.whole[static_cast<std::size_t>(i)]) {  // integrated already: only its neighbours matter
        push_neighbours();
        continue;
      }
      for (auto& c : s.poly)
        if (c.rho < 0) c.rho = uniform ? rho_u : rho_of_h(field.eval(x + c.y, hint));
      const auto v = static_cast<std::size_t>(s.site_vertex[static_cast<std::size_t>(i)]);
      double area = 0, mass = 0, energy = 0;
      Point2 shift(0, 0);
      for (std::size_t k = 1; k + 1 < s.poly.size(); ++k)
        area += integrate(s.poly[0].y, s.poly[k].y, s.poly[k + 1].y, s.poly[0].rho, s.poly[k].rho, s.poly[k + 1].rho, mass, shift, energy);
      if (!(area > 0)) continue;  // a sliver of rounding: nothing behind it
      out.area[v] += area;
      out.mass[v] += mass;
      out.shift[v] += shift;
      out.energy += energy;
      ++out.pieces;
      push_neighbours();
    }
  }
  for (int v : s.site_vertex) s.vertex_site[static_cast<std::size_t>(v)] = -1;
}

}  // namespace

void compute_cells(const Mesh& mesh, const SizeField& field, CellIntegrals& out, CellWorkspace& ws, const std::vector<FaceHandle>* faces) {
  const std::size_t nv = mesh.n_vertices(), nf = mesh.n_faces();
  out.area.assign(nv, 0.0);
  out.mass.assign(nv, 0.0);
  out.moment.assign(nv, Point2(0, 0));
  out.shift.assign(nv, Point2(0, 0));
  out.energy = 0;
  out.total_area = 0;
  out.pieces = 0;
  if (!ws.scratch) ws.scratch = std::make_unique<detail::CellScratch>();
  CellScratch& s = *ws.scratch;

  // rho at the vertices.
  const bool uniform = field.is_uniform();
  auto rho_of_h = [](double h) { return 1.0 / ((h * h) * (h * h)); };
  const double rho_u = rho_of_h(field.max_value());
  if (ws.vertex_hint.size() != nv) ws.vertex_hint.assign(nv, -1);
  ws.vertex_rho.resize(nv);
  int last_hint = -1;  // a vertex without a hint yet starts its walk where the previous one ended (vertices are Z-ordered)
  auto set_rho = [&](VertexHandle vh) {
    const auto i = static_cast<std::size_t>(vh.idx());
    if (uniform) {
      ws.vertex_rho[i] = rho_u;
      return;
    }
    int& hint = ws.vertex_hint[i];
    if (hint < 0) hint = last_hint;
    ws.vertex_rho[i] = rho_of_h(field.eval(point2(mesh, vh), hint));
    last_hint = hint;
  };
  s.vertex_site.assign(nv, -1);
  s.face_region.assign(nf, -1);

  if (!faces) {
    for (auto vh : mesh.vertices())
      if (!mesh.status(vh).deleted()) set_rho(vh);
    int region = 0;
    for (auto fh : mesh.faces()) {
      if (mesh.status(fh).deleted() || s.face_region[static_cast<std::size_t>(fh.idx())] != -1) continue;
      flood_region(mesh, fh.idx(), region, s, 0);
      region_cells(mesh, field, out, ws, s.region_faces, true, rho_u);
      ++region;
    }
  } else {
    unsigned allowed = next_stamp(s.face_stamp, s.face_counter, nf);
    for (FaceHandle fh : *faces) s.face_stamp[static_cast<std::size_t>(fh.idx())] = allowed;
    for (FaceHandle fh : *faces)
      for (auto vh : mesh.fv_range(fh)) set_rho(vh);
    int region = 0;
    for (FaceHandle fh : *faces) {
      if (s.face_region[static_cast<std::size_t>(fh.idx())] != -1) continue;
      flood_region(mesh, fh.idx(), region++, s, allowed);
      // The sites: the region's vertices and those of the faces up to four steps further on
      // its side of the constraints.
      const unsigned seen = next_stamp(s.face_stamp, s.face_counter, nf);
      s.expanded_faces = s.region_faces;
      for (int f : s.expanded_faces) s.face_stamp[static_cast<std::size_t>(f)] = seen;
      std::size_t begin = 0;
      for (int depth = 0; depth < 4; ++depth) {
        const std::size_t end = s.expanded_faces.size();
        for (std::size_t k = begin; k < end; ++k)
          for (auto h : mesh.fh_range(FaceHandle(s.expanded_faces[k]))) {
            if (!crossable(mesh, h)) continue;
            const int g = mesh.face_handle(mesh.opposite_halfedge_handle(h)).idx();
            if (g < 0 || s.face_stamp[static_cast<std::size_t>(g)] == seen) continue;
            s.face_stamp[static_cast<std::size_t>(g)] = seen;
            s.expanded_faces.push_back(g);
          }
        begin = end;
      }
      for (int f : s.expanded_faces)
        for (auto vh : mesh.fv_range(FaceHandle(f))) set_rho(vh);
      // face_stamp was reused for the expansion: mark the given faces again for the next flood.
      const unsigned again = next_stamp(s.face_stamp, s.face_counter, nf);
      for (FaceHandle g : *faces) s.face_stamp[static_cast<std::size_t>(g.idx())] = again;
      region_cells(mesh, field, out, ws, s.expanded_faces, false, rho_u);
      allowed = again;
    }
  }
  for (auto vh : mesh.vertices()) {
    const auto v = static_cast<std::size_t>(vh.idx());
    out.moment[v] = out.shift[v] + out.mass[v] * point2(mesh, vh);
  }
}

}  // namespace acute
