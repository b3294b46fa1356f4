#include <acute/cvt/voronoi.h>

#include <acute/mesh/geometry.h>

#include <cmath>

namespace acute {
namespace {

/// Integrals over triangle (s, p1, p2) of rho (linear, values r0 r1 r2), rho x and rho |x - s|^2,
/// added to mass, moment, energy; returns the signed area.
inline double integrate(const Point2& s, const Point2& p1, const Point2& p2, double r0, double r1, double r2, double& mass,
                        Point2& moment, double& energy) {
  const Point2 q1 = p1 - s, q2 = p2 - s;
  const double area = 0.5 * (q1.x() * q2.y() - q1.y() * q2.x());
  const double rs = r0 + r1 + r2;
  mass += area * rs / 3.0;
  moment += (area / 12.0) * (rs * (s + p1 + p2) + r0 * s + r1 * p1 + r2 * p2);
  const double q11 = q1.squaredNorm(), q22 = q2.squaredNorm(), q12 = q1.dot(q2);
  energy += (area / 60.0) *
            (r0 * 2.0 * (q11 + q22 + q12) + r1 * (6.0 * q11 + 2.0 * q22 + 4.0 * q12) + r2 * (2.0 * q11 + 6.0 * q22 + 4.0 * q12));
  return area;
}

/// Where the perpendicular bisector of ab meets the line bc, as b + t (c - b).
inline Point2 bisector_on_edge(const Point2& a, const Point2& b, const Point2& c) {
  const Point2 d = c - b;
  const double t = (b - a).squaredNorm() / (2.0 * d.dot(a - b));
  return b + t * d;
}

}  // namespace

std::array<std::vector<Point2>, 3> triangle_pieces(const Point2& a, const Point2& b, const Point2& c) {
  const Point2 p[3] = {a, b, c};
  const Point2 m[3] = {0.5 * (b + c), 0.5 * (c + a), 0.5 * (a + b)};  // m[i] opposite corner i
  std::array<std::vector<Point2>, 3> out;
  int obtuse = -1;
  for (int i = 0; i < 3; ++i)
    if ((p[(i + 1) % 3] - p[i]).dot(p[(i + 2) % 3] - p[i]) < 0) obtuse = i;
  if (obtuse < 0) {
    const Point2 o = circumcenter(a, b, c);
    for (int i = 0; i < 3; ++i) out[static_cast<std::size_t>(i)] = {p[i], m[(i + 2) % 3], o, m[(i + 1) % 3]};
    return out;
  }
  const int i = obtuse, j = (i + 1) % 3, k = (i + 2) % 3;
  const Point2 pj = bisector_on_edge(p[i], p[j], p[k]);  // on jk, equidistant from i and j
  const Point2 pk = bisector_on_edge(p[i], p[k], p[j]);  // on jk, equidistant from i and k
  out[static_cast<std::size_t>(i)] = {p[i], m[k], pj, pk, m[j]};
  out[static_cast<std::size_t>(j)] = {p[j], pj, m[k]};
  out[static_cast<std::size_t>(k)] = {p[k], m[j], pk};
  return out;
}

void compute_cells(const Mesh& mesh, const SizeField& field, CellIntegrals& out, CellWorkspace& ws, const std::vector<FaceHandle>* faces) {
  const std::size_t nv = mesh.n_vertices();
  out.area.assign(nv, 0.0);
  out.mass.assign(nv, 0.0);
  out.moment.assign(nv, Point2(0, 0));
  out.energy = 0;
  out.total_area = 0;
  const bool uniform = field.is_uniform();
  auto rho_of_h = [](double h) { return 1.0 / ((h * h) * (h * h)); };
  const double rho_u = rho_of_h(field.max_value());
  if (ws.vertex_hint.size() != nv) ws.vertex_hint.assign(nv, -1);
  ws.vertex_rho.resize(nv);
  auto vertex_rho = [&](VertexHandle vh) {
    const auto i = static_cast<std::size_t>(vh.idx());
    ws.vertex_rho[i] = uniform ? rho_u : rho_of_h(field.eval(point2(mesh, vh), ws.vertex_hint[i]));
  };
  if (faces) {
    for (FaceHandle fh : *faces)
      for (auto vh : mesh.fv_range(fh)) vertex_rho(vh);
  } else {
    for (auto vh : mesh.vertices()) vertex_rho(vh);
  }

  auto process = [&](FaceHandle fh) {
    VertexHandle v[3];
    Point2 p[3];
    double r[3];
    {
      auto h = mesh.halfedge_handle(fh);
      for (int i = 0; i < 3; ++i, h = mesh.next_halfedge_handle(h)) {
        v[i] = mesh.to_vertex_handle(h);
        p[i] = point2(mesh, v[i]);
        r[i] = ws.vertex_rho[static_cast<std::size_t>(v[i].idx())];
      }
    }
    int hint = uniform ? -1 : ws.vertex_hint[static_cast<std::size_t>(v[0].idx())];
    auto rho_at = [&](const Point2& x) { return uniform ? rho_u : rho_of_h(field.eval(x, hint)); };
    const Point2 m[3] = {0.5 * (p[1] + p[2]), 0.5 * (p[2] + p[0]), 0.5 * (p[0] + p[1])};  // opposite corner i
    const double rm[3] = {rho_at(m[0]), rho_at(m[1]), rho_at(m[2])};
    int obtuse = -1;
    for (int i = 0; i < 3; ++i)
      if ((p[(i + 1) % 3] - p[i]).dot(p[(i + 2) % 3] - p[i]) < 0) obtuse = i;
    auto acc = [&](int site, const Point2& q1, const Point2& q2, double r1, double r2) {
      const auto s = static_cast<std::size_t>(v[site].idx());
      out.area[s] += integrate(p[site], q1, q2, r[site], r1, r2, out.mass[s], out.moment[s], out.energy);
    };
    if (obtuse < 0) {
      const Point2 o = circumcenter(p[0], p[1], p[2]);
      const double ro = rho_at(o);
      for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        acc(i, m[k], o, rm[k], ro);  // (i, m_ij, o)
        acc(i, o, m[j], ro, rm[j]);  // (i, o, m_ki)
      }
    } else {
      const int i = obtuse, j = (i + 1) % 3, k = (i + 2) % 3;
      const Point2 pj = bisector_on_edge(p[i], p[j], p[k]), pk = bisector_on_edge(p[i], p[k], p[j]);
      const double rpj = rho_at(pj), rpk = rho_at(pk);
      acc(i, m[k], pj, rm[k], rpj);
      acc(i, pj, pk, rpj, rpk);
      acc(i, pk, m[j], rpk, rm[j]);
      acc(j, pj, m[k], rpj, rm[k]);
      acc(k, m[j], pk, rm[j], rpk);
    }
    out.total_area += 0.5 * signed_area2(p[0], p[1], p[2]);
  };
  if (faces) {
    for (FaceHandle fh : *faces) process(fh);
  } else {
    for (auto fh : mesh.faces()) process(fh);
  }
}

}  // namespace acute
