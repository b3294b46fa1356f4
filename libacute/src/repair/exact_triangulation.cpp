#include "repair/exact_triangulation.h"

#include <acute/core/errors.h>
#include <acute/mesh/segments.h>

#include <algorithm>
#include <cmath>

namespace acute::exact {

namespace {

constexpr double kEps = 1.2e-16;  // > 2^-53, rounding of one operation
constexpr int kUnnamedSegment = 1 << 30;  // a boundary edge without segment id: still constrained

int sign(const Q& q) { return sgn(q); }

}  // namespace

XPoint::XPoint(Q px, Q py) : x(std::move(px)), y(std::move(py)) {
  dx = x.get_d();
  dy = y.get_d();
  if (Q(dx) == x && Q(dy) == y)
    err = 0;
  else
    err = std::max(std::abs(dx), std::abs(dy)) * 2.3e-16 + 1e-300;
}

int orient(const XPoint& p, const XPoint& q, const XPoint& r) {
  const double ax = q.dx - p.dx, ay = q.dy - p.dy, bx = r.dx - p.dx, by = r.dy - p.dy;
  const double det = ax * by - ay * bx;
  const double ea = p.err + q.err, eb = p.err + r.err;
  const double Eax = ea + kEps * std::abs(ax), Eay = ea + kEps * std::abs(ay);
  const double Ebx = eb + kEps * std::abs(bx), Eby = eb + kEps * std::abs(by);
  const double bound = (std::abs(ax) * Eby + std::abs(by) * Eax + Eax * Eby + std::abs(ay) * Ebx + std::abs(bx) * Eay +
                        Eay * Ebx + 4 * kEps * (std::abs(ax * by) + std::abs(ay * bx))) * 1.01 + 1e-300;
  if (det > bound) return 1;
  if (det < -bound) return -1;
  return sign((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x));
}

int dot_sign(const XPoint& o, const XPoint& p, const XPoint& q) {
  const double ax = p.dx - o.dx, ay = p.dy - o.dy, bx = q.dx - o.dx, by = q.dy - o.dy;
  const double dot = ax * bx + ay * by;
  const double ea = o.err + p.err, eb = o.err + q.err;
  const double Eax = ea + kEps * std::abs(ax), Eay = ea + kEps * std::abs(ay);
  const double Ebx = eb + kEps * std::abs(bx), Eby = eb + kEps * std::abs(by);
  const double bound = (std::abs(ax) * Ebx + std::abs(bx) * Eax + Eax * Ebx + std::abs(ay) * Eby + std::abs(by) * Eay +
                        Eay * Eby + 4 * kEps * (std::abs(ax * bx) + std::abs(ay * by))) * 1.01 + 1e-300;
  if (dot > bound) return 1;
  if (dot < -bound) return -1;
  return sign((p.x - o.x) * (q.x - o.x) + (p.y - o.y) * (q.y - o.y));
}

int incircle(const XPoint& a, const XPoint& b, const XPoint& c, const XPoint& d) {
  const double adx = a.dx - d.dx, ady = a.dy - d.dy, bdx = b.dx - d.dx, bdy = b.dy - d.dy;
  const double cdx = c.dx - d.dx, cdy = c.dy - d.dy;
  const double det = (adx * adx + ady * ady) * (bdx * cdy - bdy * cdx) + (bdx * bdx + bdy * bdy) * (cdx * ady - cdy * adx) +
                     (cdx * cdx + cdy * cdy) * (adx * bdy - ady * bdx);
  const double m = std::max({std::abs(adx), std::abs(ady), std::abs(bdx), std::abs(bdy), std::abs(cdx), std::abs(cdy)});
  const double e = 2 * std::max({a.err, b.err, c.err, d.err}) + kEps * m;
  const double bound = 100 * m * m * m * e + 100 * kEps * m * m * m * m + 1e-300;
  if (e < 0.01 * m) {
    if (det > bound) return 1;
    if (det < -bound) return -1;
  }
  const Q ax = a.x - d.x, ay = a.y - d.y, bx = b.x - d.x, by = b.y - d.y, cx = c.x - d.x, cy = c.y - d.y;
  return sign((ax * ax + ay * ay) * (bx * cy - by * cx) + (bx * bx + by * by) * (cx * ay - cy * ax) +
              (cx * cx + cy * cy) * (ax * by - ay * bx));
}

// --- conversion -------------------------------------------------------------------------------

Triangulation Triangulation::from_mesh(const Mesh& mesh) {
  std::vector<int> slot(mesh.n_vertices());
  std::vector<XPoint> pts;
  pts.reserve(mesh.n_vertices());
  for (auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    slot[static_cast<std::size_t>(vh.idx())] = static_cast<int>(pts.size());
    pts.emplace_back(Q(p[0]), Q(p[1]));
  }
  Triangulation tr;
  const int n = static_cast<int>(pts.size());
  tr.build(mesh, slot, std::move(pts), n);
  return tr;
}

bool Triangulation::from_start(const Mesh& cdt, const Mesh& start, const SegmentTable& table, Triangulation& out) {
  // Required points first, in the CDT's order (to_mesh copies their data from it).
  std::vector<int> cdt_of_input;
  for (auto vh : cdt.vertices()) {
    const int i = cdt.data(vh).input_index;
    if (i < 0) return false;
    if (static_cast<std::size_t>(i) >= cdt_of_input.size()) cdt_of_input.resize(static_cast<std::size_t>(i) + 1, -1);
    cdt_of_input[static_cast<std::size_t>(i)] = vh.idx();
  }
  std::vector<XPoint> pts(cdt.n_vertices());
  for (auto vh : cdt.vertices()) {
    const auto& p = cdt.point(vh);
    pts[static_cast<std::size_t>(vh.idx())] = XPoint(Q(p[0]), Q(p[1]));
  }
  std::vector<int> slot(start.n_vertices(), -1);
  std::vector<char> found(cdt.n_vertices(), 0);
  for (auto vh : start.vertices()) {
    const auto& d = start.data(vh);
    if (d.kind != VertexKind::Input) continue;
    const int i = d.input_index;
    if (i < 0 || static_cast<std::size_t>(i) >= cdt_of_input.size() || cdt_of_input[static_cast<std::size_t>(i)] < 0) return false;
    const int c = cdt_of_input[static_cast<std::size_t>(i)];
    const auto& p = start.point(vh);
    if (p[0] != cdt.point(VertexHandle(c))[0] || p[1] != cdt.point(VertexHandle(c))[1] || found[static_cast<std::size_t>(c)]) return false;
    found[static_cast<std::size_t>(c)] = 1;
    slot[static_cast<std::size_t>(vh.idx())] = c;
  }
  if (std::find(found.begin(), found.end(), 0) != found.end()) return false;
  for (auto vh : start.vertices()) {
    if (slot[static_cast<std::size_t>(vh.idx())] >= 0) continue;
    const auto& p = start.point(vh);
    // The segment it lies on, from its constrained edges (the kinds need not say).
    int seg = -1;
    for (auto h : start.voh_range(vh))
      if (start.data(start.edge_handle(h)).segment >= 0) seg = start.data(start.edge_handle(h)).segment;
    XPoint x{Q(p[0]), Q(p[1])};
    if (seg >= 0 && static_cast<std::size_t>(seg) < table.size()) {
      // Exactly on the segment (the doubles are only near a slanted one): a + t (b - a) with
      // t the rounded parameter of the nearest point, so the rational stays short.
      const Point2 &a = table[static_cast<std::size_t>(seg)][0], &b = table[static_cast<std::size_t>(seg)][1];
      const Point2 ab = b - a;
      if (ab.x() == 0) {
        x = XPoint(Q(a.x()), Q(p[1]));
      } else if (ab.y() == 0) {
        x = XPoint(Q(p[0]), Q(a.y()));
      } else {
        const double t = ((p[0] - a.x()) * ab.x() + (p[1] - a.y()) * ab.y()) / ab.squaredNorm();
        if (!(t > 0 && t < 1)) return false;
        const Q qt(t);
        x = XPoint(Q(a.x()) + qt * Q(ab.x()), Q(a.y()) + qt * Q(ab.y()));
      }
    }
    slot[static_cast<std::size_t>(vh.idx())] = static_cast<int>(pts.size());
    pts.push_back(std::move(x));
  }
  Triangulation tr;
  tr.build(start, slot, std::move(pts), static_cast<int>(cdt.n_vertices()));
  for (const Tri& t : tr.tris_)
    if (orient(tr.point(t.v[0]), tr.point(t.v[1]), tr.point(t.v[2])) <= 0) return false;  // projection folded a triangle
  for (std::size_t v = 0; v < tr.vtri_.size(); ++v)
    if (tr.vtri_[v] < 0) return false;  // a point of the CDT not in the start mesh
  out = std::move(tr);
  return true;
}

void Triangulation::build(const Mesh& mesh, const std::vector<int>& vslot, std::vector<XPoint> pts, int n_required) {
  Triangulation& tr = *this;
  tr.pts_ = std::move(pts);
  tr.alive_.assign(tr.pts_.size(), 1);
  tr.vtri_.assign(tr.pts_.size(), -1);
  tr.n_required_ = n_required;
  tr.n_steiner_ = tr.pts_.size() - static_cast<std::size_t>(n_required);
  std::vector<int> slot(mesh.n_faces(), -1);
  for (auto fh : mesh.faces()) {
    slot[static_cast<std::size_t>(fh.idx())] = static_cast<int>(tr.tris_.size());
    tr.tris_.emplace_back();
  }
  for (auto fh : mesh.faces()) {
    Tri& t = tr.tris_[static_cast<std::size_t>(slot[static_cast<std::size_t>(fh.idx())])];
    auto h = mesh.halfedge_handle(fh);
    std::array<Mesh::HalfedgeHandle, 3> hs{h, mesh.next_halfedge_handle(h), mesh.next_halfedge_handle(mesh.next_halfedge_handle(h))};
    for (int i = 0; i < 3; ++i) t.v[i] = vslot[static_cast<std::size_t>(mesh.from_vertex_handle(hs[i]).idx())];
    // hs[i] runs v[i] -> v[i+1]: the edge opposite v[i+2].
    for (int i = 0; i < 3; ++i) {
      const int k = (i + 2) % 3;
      const auto opp = mesh.opposite_halfedge_handle(hs[i]);
      const auto of = mesh.face_handle(opp);
      t.n[k] = of.is_valid() && !mesh.status(of).deleted() ? slot[static_cast<std::size_t>(of.idx())] : -1;
      const auto eh = mesh.edge_handle(hs[i]);
      int seg = mesh.data(eh).segment;
      if (seg >= 0) {
        if (static_cast<std::size_t>(seg) >= tr.seg_marker_.size()) tr.seg_marker_.resize(static_cast<std::size_t>(seg) + 1, 0);
        tr.seg_marker_[static_cast<std::size_t>(seg)] = mesh.data(eh).marker;
      }
      if (seg < 0 && t.n[k] < 0) seg = kUnnamedSegment;
      t.seg[k] = seg;
    }
    for (int i = 0; i < 3; ++i) tr.vtri_[static_cast<std::size_t>(t.v[i])] = slot[static_cast<std::size_t>(fh.idx())];
  }
  tr.stamp_.assign(tr.tris_.size(), 0);
}

Mesh Triangulation::to_mesh(const Mesh& like, std::vector<std::array<std::string, 2>>* exact) const {
  Mesh out;
  std::vector<int> index(pts_.size(), -1);
  if (exact) exact->clear();
  for (std::size_t v = 0; v < pts_.size(); ++v) {
    if (!alive_[v]) continue;
    const auto vh = out.add_vertex(Mesh::Point(pts_[v].dx, pts_[v].dy, 0.0));
    index[v] = vh.idx();
    if (static_cast<int>(v) < n_required_) {
      const auto src = VertexHandle(static_cast<int>(v));
      out.data(vh) = like.data(src);
    }
    if (exact) exact->push_back({pts_[v].x.get_str(), pts_[v].y.get_str()});
  }
  for (const Tri& t : tris_) {
    if (!t.alive) continue;
    out.add_face(VertexHandle(index[static_cast<std::size_t>(t.v[0])]), VertexHandle(index[static_cast<std::size_t>(t.v[1])]),
                 VertexHandle(index[static_cast<std::size_t>(t.v[2])]));
  }
  for (const Tri& t : tris_) {
    if (!t.alive) continue;
    for (int k = 0; k < 3; ++k) {
      const int seg = t.seg[k];
      if (seg < 0 || seg == kUnnamedSegment) continue;
      const auto a = VertexHandle(index[static_cast<std::size_t>(t.v[(k + 1) % 3])]);
      const auto b = VertexHandle(index[static_cast<std::size_t>(t.v[(k + 2) % 3])]);
      const auto h = out.find_halfedge(a, b);
      if (!h.is_valid()) continue;
      auto& ed = out.data(out.edge_handle(h));
      ed.segment = seg;
      ed.marker = static_cast<std::size_t>(seg) < seg_marker_.size() ? seg_marker_[static_cast<std::size_t>(seg)] : 0;
      for (auto vh : {a, b})
        if (out.data(vh).kind != VertexKind::Input) {
          out.data(vh).kind = VertexKind::OnSegment;
          out.data(vh).segment = seg;
        }
    }
  }
  set_segment_table(out, segment_table(like));
  return out;
}

// --- queries -----------------------------------------------------------------------------------

int Triangulation::obtuse_corner(int t) const {
  const Tri& tri = tris_[static_cast<std::size_t>(t)];
  if (!is_obtuse(tri)) return -1;
  for (int k = 0; k < 3; ++k)
    if (dot_sign(point(tri.v[k]), point(tri.v[(k + 1) % 3]), point(tri.v[(k + 2) % 3])) < 0) return k;
  return -1;
}

namespace {

signed char classify(const Triangulation& tr, const Tri& tri) {
  if (tri.cls < 0) {
    signed char c = 0;
    for (int k = 0; k < 3 && c < 2; ++k) {
      const int s = dot_sign(tr.point(tri.v[k]), tr.point(tri.v[(k + 1) % 3]), tr.point(tri.v[(k + 2) % 3]));
      if (s < 0) c = 2;
      else if (s == 0) c = 1;
    }
    tri.cls = c;
  }
  return tri.cls;
}

}  // namespace

bool Triangulation::is_obtuse(const Tri& tri) const { return classify(*this, tri) == 2; }

bool Triangulation::is_right(const Tri& tri) const { return classify(*this, tri) == 1; }

std::size_t Triangulation::n_obtuse() const {
  std::size_t n = 0;
  for (const Tri& t : tris_) n += t.alive && is_obtuse(t);
  return n;
}

std::size_t Triangulation::n_right() const {
  std::size_t n = 0;
  for (const Tri& t : tris_) n += t.alive && is_right(t);
  return n;
}

std::vector<int> Triangulation::steiner_vertices() const {
  std::vector<int> out;
  for (int v = n_required_; v < static_cast<int>(pts_.size()); ++v)
    if (alive_[static_cast<std::size_t>(v)]) out.push_back(v);
  return out;
}

bool Triangulation::fan(int v, std::vector<int>& out, bool& open) const {
  out.clear();
  open = false;
  const int t0 = vtri_[static_cast<std::size_t>(v)];
  if (t0 < 0) return false;
  auto corner = [&](int t) {
    const Tri& tri = tris_[static_cast<std::size_t>(t)];
    for (int i = 0; i < 3; ++i)
      if (tri.v[i] == v) return i;
    return -1;
  };
  if (!tris_[static_cast<std::size_t>(t0)].alive || corner(t0) < 0) return false;
  // Clockwise to the first triangle (the one after a boundary edge), then counter-clockwise.
  int start = t0;
  for (std::size_t guard = 0; guard < 10000; ++guard) {
    const int i = corner(start);
    const int prev = tris_[static_cast<std::size_t>(start)].n[(i + 2) % 3];  // across (v, v[i+1])
    if (prev < 0) {
      open = true;
      break;
    }
    if (prev == t0) break;
    start = prev;
  }
  int t = start;
  for (std::size_t guard = 0; guard < 10000; ++guard) {
    out.push_back(t);
    const int i = corner(t);
    const int next = tris_[static_cast<std::size_t>(t)].n[(i + 1) % 3];  // across (v, v[i+2])
    if (next < 0 || next == start) return true;
    t = next;
  }
  return false;
}

std::vector<int> Triangulation::fan_of(int v) const {
  std::vector<int> f;
  bool open = false;
  if (!fan(v, f, open)) f.clear();
  return f;
}

std::vector<std::pair<int, int>> Triangulation::spokes(int v) const {
  std::vector<std::pair<int, int>> out;
  for (int t : fan_of(v)) {
    const Tri& tri = tris_[static_cast<std::size_t>(t)];
    int i = 0;
    while (tri.v[i] != v) ++i;
    const int x = tri.v[(i + 1) % 3], y = tri.v[(i + 2) % 3];
    if (std::find_if(out.begin(), out.end(), [&](const auto& e) { return e.first == x; }) == out.end())
      out.emplace_back(x, tri.seg[(i + 2) % 3]);
    if (std::find_if(out.begin(), out.end(), [&](const auto& e) { return e.first == y; }) == out.end())
      out.emplace_back(y, tri.seg[(i + 1) % 3]);
  }
  return out;
}

std::vector<int> Triangulation::neighbours(int v) const {
  std::vector<int> f, out;
  bool open = false;
  if (!fan(v, f, open)) return out;
  for (int t : f) {
    const Tri& tri = tris_[static_cast<std::size_t>(t)];
    for (int i = 0; i < 3; ++i)
      if (tri.v[i] != v && std::find(out.begin(), out.end(), tri.v[i]) == out.end()) out.push_back(tri.v[i]);
  }
  return out;
}

// --- journal -------------------------------------------------------------------------------------

void Triangulation::set_tri(int t, const Tri& value) {
  if (open_) tlog_.emplace_back(t, tris_[static_cast<std::size_t>(t)]);
  tris_[static_cast<std::size_t>(t)] = value;
}

void Triangulation::set_vtri(int v, int t) {
  if (open_) vlog_.emplace_back(v, vtri_[static_cast<std::size_t>(v)]);
  vtri_[static_cast<std::size_t>(v)] = t;
}

void Triangulation::set_alive(int v, char a) {
  if (open_) alog_.emplace_back(v, alive_[static_cast<std::size_t>(v)]);
  alive_[static_cast<std::size_t>(v)] = a;
  if (v >= n_required_) n_steiner_ += a ? 1 : static_cast<std::size_t>(-1);
}

void Triangulation::begin() {
  open_ = true;
  tlog_.clear();
  vlog_.clear();
  alog_.clear();
  begin_ = {0, 0, 0, tris_.size(), pts_.size(), n_steiner_};
  nest_ = begin_;
}

void Triangulation::nest() { nest_ = {tlog_.size(), vlog_.size(), alog_.size(), tris_.size(), pts_.size(), n_steiner_}; }

void Triangulation::unnest() { rollback_to(nest_); }

Triangulation::Mark Triangulation::mark() const { return {tlog_.size(), vlog_.size(), alog_.size(), tris_.size(), pts_.size(), n_steiner_}; }

void Triangulation::rollback_to(const Mark& m) {
  while (tlog_.size() > m.tlog) {
    tris_[static_cast<std::size_t>(tlog_.back().first)] = tlog_.back().second;
    tlog_.pop_back();
  }
  while (vlog_.size() > m.vlog) {
    vtri_[static_cast<std::size_t>(vlog_.back().first)] = vlog_.back().second;
    vlog_.pop_back();
  }
  while (alog_.size() > m.alog) {
    alive_[static_cast<std::size_t>(alog_.back().first)] = alog_.back().second;
    alog_.pop_back();
  }
  tris_.resize(m.ntris);
  pts_.resize(m.npts);
  alive_.resize(m.npts);
  vtri_.resize(m.npts);
  n_steiner_ = m.nsteiner;
}

void Triangulation::commit() {
  last_touched_ = touched();
  open_ = false;
  tlog_.clear();
  vlog_.clear();
  alog_.clear();
}

void Triangulation::rollback() {
  rollback_to(begin_);
  open_ = false;
}

std::vector<int> Triangulation::touched() const { return touched_since(begin_); }

std::vector<int> Triangulation::touched_since(const Mark& m) const {
  if (stamp_.size() < tris_.size()) stamp_.resize(tris_.size(), 0);
  ++epoch_;
  std::vector<int> out;
  for (std::size_t i = m.tlog; i < tlog_.size(); ++i) {
    const int t = tlog_[i].first;
    if (static_cast<std::size_t>(t) >= tris_.size() || stamp_[static_cast<std::size_t>(t)] == epoch_) continue;
    stamp_[static_cast<std::size_t>(t)] = epoch_;
    out.push_back(t);
  }
  for (std::size_t t = m.ntris; t < tris_.size(); ++t)
    if (stamp_[t] != epoch_) {
      stamp_[t] = epoch_;
      out.push_back(static_cast<int>(t));
    }
  return out;
}

std::vector<Tri> Triangulation::touched_originals() const {
  if (stamp_.size() < tris_.size()) stamp_.resize(tris_.size(), 0);
  ++epoch_;
  std::vector<Tri> out;
  for (const auto& [t, old] : tlog_) {
    if (static_cast<std::size_t>(t) >= begin_.ntris || stamp_[static_cast<std::size_t>(t)] == epoch_) continue;
    stamp_[static_cast<std::size_t>(t)] = epoch_;
    out.push_back(old);
  }
  return out;
}

// --- operators -----------------------------------------------------------------------------------

int Triangulation::add_point(const XPoint& p) {
  pts_.push_back(p);
  alive_.push_back(0);
  vtri_.push_back(-1);
  const int v = static_cast<int>(pts_.size()) - 1;
  set_alive(v, 1);
  return v;
}

std::vector<int> Triangulation::replace(const std::vector<int>& old, const std::vector<std::array<int, 3>>& fresh,
                                        const std::vector<std::array<int, 3>>& segs) {
  struct Side {
    int a, b, n, seg;
  };
  std::vector<Side> sides;  // directed edges of the old triangles (a->b with the triangle on the left)
  for (int t : old) {
    const Tri& tri = tris_[static_cast<std::size_t>(t)];
    for (int k = 0; k < 3; ++k) sides.push_back({tri.v[(k + 1) % 3], tri.v[(k + 2) % 3], tri.n[k], tri.seg[k]});
  }
  std::vector<int> slots;
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    if (i < old.size()) {
      slots.push_back(old[i]);
    } else {
      slots.push_back(static_cast<int>(tris_.size()));
      tris_.emplace_back();
      tris_.back().alive = false;
    }
  }
  for (std::size_t i = fresh.size(); i < old.size(); ++i) {
    Tri dead = tris_[static_cast<std::size_t>(old[i])];
    dead.alive = false;
    set_tri(old[i], dead);
  }
  std::vector<Tri> made(fresh.size());
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    Tri& t = made[i];
    t.v = fresh[i];
    t.alive = true;
    t.cls = -1;
    for (int k = 0; k < 3; ++k) {
      const int a = t.v[(k + 1) % 3], b = t.v[(k + 2) % 3];
      int nb = -1, seg = -1;
      bool found = false;
      for (std::size_t j = 0; j < fresh.size() && !found; ++j) {
        if (j == i) continue;
        for (int m = 0; m < 3; ++m)
          if (fresh[j][(m + 1) % 3] == b && fresh[j][(m + 2) % 3] == a) {
            nb = slots[j];
            found = true;
            break;
          }
      }
      if (!found) {
        for (const Side& s : sides)
          if (s.a == a && s.b == b) {
            nb = s.n;
            seg = s.seg;
            found = true;
            // The outer neighbour now faces the new slot.
            if (nb >= 0) {
              Tri o = tris_[static_cast<std::size_t>(nb)];
              for (int m = 0; m < 3; ++m)
                if (o.v[(m + 1) % 3] == b && o.v[(m + 2) % 3] == a) o.n[m] = slots[i];
              set_tri(nb, o);
            }
            break;
          }
      }
      for (const auto& s : segs)
        if ((s[0] == a && s[1] == b) || (s[0] == b && s[1] == a)) seg = s[2];
      t.n[k] = nb;
      t.seg[k] = seg;
    }
  }
  for (std::size_t i = 0; i < fresh.size(); ++i) {
    set_tri(slots[i], made[i]);
    for (int v : fresh[i]) set_vtri(v, slots[i]);
  }
  return slots;
}

void Triangulation::legalize(const std::vector<int>& start) {
  std::vector<std::pair<int, int>> stack;
  for (int t : start)
    for (int k = 0; k < 3; ++k) stack.emplace_back(t, k);
  std::size_t guard = 0;
  while (!stack.empty() && guard++ < 1'000'000) {
    const auto [t, k] = stack.back();
    stack.pop_back();
    const Tri tri = tris_[static_cast<std::size_t>(t)];
    if (!tri.alive || tri.seg[k] >= 0 || tri.n[k] < 0) continue;
    const int u = tri.n[k];
    const Tri& nt = tris_[static_cast<std::size_t>(u)];
    const int c = tri.v[k], a = tri.v[(k + 1) % 3], b = tri.v[(k + 2) % 3];
    int d = -1;
    for (int m = 0; m < 3; ++m)
      if (nt.v[(m + 1) % 3] == b && nt.v[(m + 2) % 3] == a) d = nt.v[m];
    if (d < 0) continue;
    if (incircle(point(tri.v[0]), point(tri.v[1]), point(tri.v[2]), point(d)) <= 0) continue;
    const auto slots = replace({t, u}, {{{c, a, d}}, {{c, d, b}}}, {});
    for (int s : slots)
      for (int m = 0; m < 3; ++m) stack.emplace_back(s, m);
  }
}

int Triangulation::split_edge(int t, int k, const XPoint& p) {
  const Tri tri = tris_[static_cast<std::size_t>(t)];
  if (!tri.alive) return -1;
  const int c = tri.v[k], a = tri.v[(k + 1) % 3], b = tri.v[(k + 2) % 3];
  const XPoint &pa = point(a), &pb = point(b);
  if (orient(pa, pb, p) != 0 || dot_sign(p, pa, pb) >= 0) return -1;  // not strictly inside ab
  const int u = tri.n[k];
  if (u < 0 && tri.seg[k] < 0) return -1;
  const int v = add_point(p);
  std::vector<int> old = {t};
  std::vector<std::array<int, 3>> fresh = {{{c, a, v}}, {{c, v, b}}};
  if (u >= 0) {
    const Tri& nt = tris_[static_cast<std::size_t>(u)];
    int d = -1;
    for (int m = 0; m < 3; ++m)
      if (nt.v[(m + 1) % 3] == b && nt.v[(m + 2) % 3] == a) d = nt.v[m];
    if (d < 0) return -1;
    old.push_back(u);
    fresh.push_back({{d, b, v}});
    fresh.push_back({{d, v, a}});
  }
  std::vector<std::array<int, 3>> segs;
  if (tri.seg[k] >= 0) segs = {{{a, v, tri.seg[k]}}, {{v, b, tri.seg[k]}}};
  legalize(replace(old, fresh, segs));
  return v;
}

int Triangulation::insert(const XPoint& p, int start) {
  int t = start;
  if (t < 0 || !tris_[static_cast<std::size_t>(t)].alive) return -1;
  for (std::size_t steps = 0; steps < 100000; ++steps) {
    const Tri& tri = tris_[static_cast<std::size_t>(t)];
    int moved = -1, zero = -1, zeros = 0;
    const int r = static_cast<int>(steps % 3);
    for (int i = 0; i < 3; ++i) {
      const int k = (i + r) % 3;
      const int o = orient(point(tri.v[(k + 1) % 3]), point(tri.v[(k + 2) % 3]), p);
      if (o < 0) {
        moved = k;
        break;
      }
      if (o == 0) zero = k, ++zeros;
    }
    if (moved >= 0) {
      if (tri.n[moved] < 0 || tri.seg[moved] >= 0) return -1;  // outside, or behind a segment
      t = tri.n[moved];
      continue;
    }
    if (zeros >= 2) return -1;  // on a vertex
    if (zeros == 1) return split_edge(t, zero, p);
    const int v = add_point(p);
    legalize(replace({t}, {{{tri.v[0], tri.v[1], v}}, {{tri.v[1], tri.v[2], v}}, {{tri.v[2], tri.v[0], v}}}, {}));
    return v;
  }
  return -1;
}

bool Triangulation::remove_vertex(int v) {
  if (is_required(v) || !alive_point(v)) return false;
  std::vector<int> f;
  bool open = false;
  if (!fan(v, f, open) || f.size() < 2) return false;
  // Link vertices x_j (counter-clockwise) and which spokes (v, x_j) are constrained.
  std::vector<int> link;
  std::vector<int> spoke_seg;
  for (int t : f) {
    const Tri& tri = tris_[static_cast<std::size_t>(t)];
    int i = 0;
    while (tri.v[i] != v) ++i;
    link.push_back(tri.v[(i + 1) % 3]);
    spoke_seg.push_back(tri.seg[(i + 2) % 3]);  // edge (v, v[i+1])
  }
  if (open) {
    const Tri& last = tris_[static_cast<std::size_t>(f.back())];
    int i = 0;
    while (last.v[i] != v) ++i;
    link.push_back(last.v[(i + 2) % 3]);
    spoke_seg.push_back(last.seg[(i + 1) % 3]);
  }
  std::vector<std::size_t> constrained;
  for (std::size_t j = 0; j < spoke_seg.size(); ++j)
    if (spoke_seg[j] >= 0) constrained.push_back(j);
  std::vector<std::vector<int>> polygons;
  std::vector<std::array<int, 3>> segs;
  if (open) {
    if (constrained.size() != 2 || constrained[0] != 0 || constrained[1] != link.size() - 1) return false;
    if (spoke_seg.front() != spoke_seg.back()) return false;
    if (orient(point(link.front()), point(v), point(link.back())) != 0) return false;
    polygons.push_back(link);
    segs.push_back({{link.back(), link.front(), spoke_seg.front()}});
  } else if (constrained.empty()) {
    polygons.push_back(link);
  } else if (constrained.size() == 2) {
    const std::size_t j1 = constrained[0], j2 = constrained[1];
    if (spoke_seg[j1] != spoke_seg[j2]) return false;
    if (orient(point(link[j1]), point(v), point(link[j2])) != 0) return false;
    std::vector<int> p1, p2;
    for (std::size_t j = j1; j <= j2; ++j) p1.push_back(link[j]);
    for (std::size_t j = j2; j != j1; j = (j + 1) % link.size()) p2.push_back(link[j]);
    p2.push_back(link[j1]);
    polygons.push_back(p1);
    polygons.push_back(p2);
    segs.push_back({{link[j1], link[j2], spoke_seg[j1]}});
  } else {
    return false;
  }
  std::vector<std::array<int, 3>> fresh;
  for (auto poly : polygons) {
    if (poly.size() < 3) return false;
    while (poly.size() > 3) {
      bool clipped = false;
      const std::size_t n = poly.size();
      for (std::size_t i = 0; i < n && !clipped; ++i) {
        const int a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
        const XPoint &pa = point(a), &pb = point(b), &pc = point(c);
        if (orient(pa, pb, pc) <= 0) continue;
        bool empty = true;
        for (std::size_t j = 0; j < n && empty; ++j) {
          const int q = poly[j];
          if (q == a || q == b || q == c) continue;
          const XPoint& pq = point(q);
          if (orient(pa, pb, pq) >= 0 && orient(pb, pc, pq) >= 0 && orient(pc, pa, pq) >= 0) empty = false;
        }
        if (!empty) continue;
        fresh.push_back({{a, b, c}});
        poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
        clipped = true;
      }
      if (!clipped) return false;
    }
    if (orient(point(poly[0]), point(poly[1]), point(poly[2])) <= 0) return false;
    fresh.push_back({{poly[0], poly[1], poly[2]}});
  }
  set_alive(v, 0);
  legalize(replace(f, fresh, segs));
  return true;
}

}  // namespace acute::exact
