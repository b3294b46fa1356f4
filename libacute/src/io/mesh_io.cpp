// Triangle meshes: OFF, OBJ, Triangle .node/.ele readers (own parsers, exact line numbers), the
// common mesh builder with its checks, and the OFF / OBJ / .node/.ele writers.
#include "io/atomic_file.h"
#include "io/io_detail.h"

#include <acute/core/errors.h>
#include <acute/io/io.h>
#include <acute/mesh/boundary.h>
#include <acute/predicates/predicates.h>

#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace acute::io {

namespace detail {

namespace {

// OpenMesh reports failed add_face on omerr; the library must not print.
class SilenceOpenMesh {
 public:
  SilenceOpenMesh() : was_enabled_(omerr().is_enabled()) { omerr().disable(); }
  ~SilenceOpenMesh() {
    if (was_enabled_) omerr().enable();
  }
  SilenceOpenMesh(const SilenceOpenMesh&) = delete;
  SilenceOpenMesh& operator=(const SilenceOpenMesh&) = delete;

 private:
  bool was_enabled_;
};

}  // namespace

Mesh build_mesh(Soup s, const WarningSink& warn) {
  const std::size_t nv = s.points.size(), nf = s.faces.size();
  auto at_vertex = [&](std::size_t i) {
    return i < s.point_lines.size() ? s.path + ":" + std::to_string(s.point_lines[i]) + ": " : s.path + ": ";
  };
  auto at_face = [&](std::size_t f) {
    return f < s.face_lines.size() ? s.faces_path + ":" + std::to_string(s.face_lines[f]) + ": " : s.faces_path + ": ";
  };
  auto vname = [&](std::size_t i) { return "vertex " + std::to_string(i + s.base); };
  auto fname = [&](std::size_t f) {
    const auto& t = s.faces[f];
    return "face " + std::to_string(f + s.base) + " (vertices " + std::to_string(t[0] + s.base) + " " +
           std::to_string(t[1] + s.base) + " " + std::to_string(t[2] + s.base) + ")";
  };

  for (std::size_t i = 0; i < nv; ++i)
    for (int k = 0; k < 2; ++k)
      if (!predicates::validate_coordinate(s.points[i][k]))
        throw InvalidInput(at_vertex(i) + vname(i) + ": " + (k ? "y = " : "x = ") + format_double(s.points[i][k]) +
                           (std::isfinite(s.points[i][k]) ? " is outside the exact range (0 or |x| in [2^-142, 2^201])"
                                                          : " is not finite"));
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& t = s.faces[f];
    for (int v : t)
      if (v < 0 || static_cast<std::size_t>(v) >= nv)
        throw InvalidInput(at_face(f) + "face " + std::to_string(f + s.base) + " uses vertex " +
                           std::to_string(v + s.base) + ", out of range (" + std::to_string(nv) + " vertices)");
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) throw InvalidInput(at_face(f) + fname(f) + " repeats a vertex");
  }

  // Orientation: all clockwise is fixed (with a warning), mixed is an error (folded mesh).
  std::size_t n_ccw = 0, n_cw = 0, n_flat = 0, first_flat = nf;
  std::vector<Sign> orientation(nf);
  for (std::size_t f = 0; f < nf; ++f) {
    const auto& t = s.faces[f];
    orientation[f] = predicates::orient2d(s.points[t[0]], s.points[t[1]], s.points[t[2]]);
    if (orientation[f] == Sign::Positive) ++n_ccw;
    else if (orientation[f] == Sign::Negative) ++n_cw;
    else if (n_flat++ == 0) first_flat = f;
  }
  if (n_ccw > 0 && n_cw > 0) {
    const Sign minority = n_cw <= n_ccw ? Sign::Negative : Sign::Positive;
    const std::size_t f = static_cast<std::size_t>(std::find(orientation.begin(), orientation.end(), minority) - orientation.begin());
    throw InvalidInput(at_face(f) + fname(f) + " is " + (minority == Sign::Negative ? "clockwise" : "counter-clockwise") +
                       " while " + std::to_string(std::max(n_cw, n_ccw)) + " faces are " +
                       (minority == Sign::Negative ? "counter-clockwise" : "clockwise") + " (folded or inconsistently oriented)");
  }
  if (n_cw > 0) {
    for (auto& t : s.faces) std::swap(t[1], t[2]);
    if (warn) warn(s.faces_path + ": all faces are clockwise in the xy-plane: reversed");
  }
  if (n_flat > 0 && warn)
    warn(at_face(first_flat) + std::to_string(n_flat) + " face(s) with zero area, first " + fname(first_flat));

  // Edges: each directed edge at most once, each undirected edge at most twice.
  struct DirectedEdge {
    int lo, hi, face;
    bool forward;
  };
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * nf);
  for (std::size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = s.faces[f][k], b = s.faces[f][(k + 1) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), static_cast<int>(f), a < b});
    }
  std::sort(edges.begin(), edges.end(), [](const DirectedEdge& x, const DirectedEdge& y) {
    return std::tie(x.lo, x.hi, x.face) < std::tie(y.lo, y.hi, y.face);
  });
  int bad_face = -1;
  std::string bad_reason;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    const std::string edge = "edge " + std::to_string(edges[i].lo + s.base) + "-" + std::to_string(edges[i].hi + s.base);
    if (j - i > 2 && (bad_face < 0 || edges[i + 2].face < bad_face)) {
      bad_face = edges[i + 2].face;
      bad_reason = " is a third face on " + edge + " (with faces " + std::to_string(edges[i].face + s.base) + " and " +
                   std::to_string(edges[i + 1].face + s.base) + "): non-manifold edge";
    } else if (j - i == 2 && edges[i].forward == edges[i + 1].forward && (bad_face < 0 || edges[i + 1].face < bad_face)) {
      bad_face = edges[i + 1].face;
      bad_reason = " uses " + edge + " in the same direction as face " + std::to_string(edges[i].face + s.base) +
                   " (duplicate or inconsistently oriented face)";
    }
    i = j;
  }
  if (bad_face >= 0) throw InvalidInput(at_face(static_cast<std::size_t>(bad_face)) + fname(bad_face) + bad_reason);

  Mesh mesh;
  mesh.reserve(nv, 3 * nf / 2 + nv, nf);
  for (std::size_t i = 0; i < nv; ++i) {
    const auto vh = mesh.add_vertex(Mesh::Point(s.points[i].x(), s.points[i].y(), 0.0));
    if (i < s.markers.size()) mesh.data(vh).marker = s.markers[i];
  }
  {
    // OpenMesh adds the faces of a pinch vertex (fans meeting only there: a hole touching the
    // boundary, parts sharing a corner) in any order, relinking the fans; what it refuses would
    // make a vertex interior to one fan and a corner of another face (overlapping faces).
    SilenceOpenMesh quiet;
    for (std::size_t f = 0; f < nf; ++f) {
      const auto& t = s.faces[f];
      if (!mesh.add_face(VertexHandle(t[0]), VertexHandle(t[1]), VertexHandle(t[2])).is_valid())
        throw InvalidInput(at_face(f) + fname(f) + " cannot be added: a vertex of it would be non-manifold");
    }
  }
  // Its fans come out in insertion order around the vertex: put them in geometric order.
  order_pinch_vertices(mesh);
  {
    // Fans that cannot be put in order (a degenerate face at the pinch, fans overlapping there)
    // stay unlinked: the one-ring walk from the vertex then misses some of its edges.
    std::vector<int> out_degree(mesh.n_vertices(), 0);
    for (auto heh : mesh.halfedges()) ++out_degree[static_cast<std::size_t>(mesh.from_vertex_handle(heh).idx())];
    for (auto vh : mesh.vertices()) {
      if (!mesh.halfedge_handle(vh).is_valid()) continue;  // unused (warned about below)
      int reached = 0;
      for (auto heh = mesh.halfedge_handle(vh), h0 = heh; reached <= out_degree[static_cast<std::size_t>(vh.idx())];) {
        ++reached;
        heh = mesh.next_halfedge_handle(mesh.opposite_halfedge_handle(heh));
        if (heh == h0) break;
      }
      const auto i = static_cast<std::size_t>(vh.idx());
      if (reached != out_degree[i])
        throw InvalidInput(at_vertex(i) + "the faces meeting only at " + vname(i) +
                           " overlap or are degenerate there: they cannot be ordered around it");
    }
  }
  std::size_t unused = 0, first_unused = nv;
  for (auto vh : mesh.vertices())
    if (mesh.is_isolated(vh) && unused++ == 0) first_unused = static_cast<std::size_t>(vh.idx());
  if (unused > 0 && warn)
    warn(at_vertex(first_unused) + std::to_string(unused) + " vertex(es) used by no face, first " + vname(first_unused));
  return mesh;
}

}  // namespace detail

namespace {

using detail::LineReader;

void check_z(LineReader& in, std::size_t i, int vertex, bool& warned, const WarningSink& warn) {
  if (in.size() <= i) return;
  const double z = in.to_double(i, "vertex " + std::to_string(vertex) + " z");
  if (z != 0 && !warned && warn) {
    warn(in.where() + "nonzero z coordinates are dropped (the mesh is projected onto the xy-plane)");
    warned = true;
  }
}

Mesh read_off(const std::string& path, const WarningSink& warn) {
  LineReader in(path);
  detail::Soup s;
  s.path = s.faces_path = path;
  if (!in.next()) in.fail("empty file, expected an OFF header");
  const std::string head(in[0]);
  const bool off_keyword = head.size() >= 3 && head.compare(head.size() - 3, 3, "OFF") == 0;
  if (!off_keyword) in.fail("expected 'OFF', found '" + head + "'");
  if (head.find_first_of("n4") != std::string::npos) in.fail("'" + head + "': only 3D OFF files are supported");
  std::size_t first = 1;  // the counts may follow the keyword on the same line
  if (in.size() == 1) {
    if (!in.next()) in.fail("missing counts (vertices faces edges)");
    first = 0;
  }
  in.require(first + 2, "counts (vertices faces edges)");
  const long long nv = in.to_int(first, "vertex count"), nf = in.to_int(first + 1, "face count");
  if (nv < 0 || nf < 0) in.fail("negative vertex or face count");
  bool warned_z = false;
  for (long long i = 0; i < nv; ++i) {
    if (!in.next()) in.fail("expected " + std::to_string(nv) + " vertices, file ends after " + std::to_string(i));
    in.require(3, "vertex line (x y z)");
    const std::string name = "vertex " + std::to_string(i);
    s.points.emplace_back(in.to_double(0, name + " x"), in.to_double(1, name + " y"));
    check_z(in, 2, static_cast<int>(i), warned_z, warn);
    s.point_lines.push_back(in.line());
  }
  for (long long f = 0; f < nf; ++f) {
    if (!in.next()) in.fail("expected " + std::to_string(nf) + " faces, file ends after " + std::to_string(f));
    const long long k = in.to_int(0, "face " + std::to_string(f) + " vertex count");
    if (k != 3) in.fail("face " + std::to_string(f) + " has " + std::to_string(k) + " vertices, only triangles are supported");
    in.require(4, "face line (3 a b c)");
    std::array<int, 3> t{};
    for (int c = 0; c < 3; ++c) {
      const long long v = in.to_int(1 + c, "face " + std::to_string(f) + " vertex");
      if (v < 0 || v >= nv)
        in.fail("face " + std::to_string(f) + " uses vertex " + std::to_string(v) + ", out of range (" +
                std::to_string(nv) + " vertices)");
      t[c] = static_cast<int>(v);
    }
    s.faces.push_back(t);
    s.face_lines.push_back(in.line());
  }
  if (in.next() && warn) warn(in.where() + "unexpected content after the last face ignored");
  return detail::build_mesh(std::move(s), warn);
}

Mesh read_obj(const std::string& path, const WarningSink& warn) {
  LineReader in(path);
  detail::Soup s;
  s.path = s.faces_path = path;
  s.base = 1;
  bool warned_z = false;
  std::vector<long long> raw;  // indices as resolved so far, range-checked at the end
  while (in.next()) {
    const std::string_view key = in[0];
    if (key == "v") {
      const std::string name = "vertex " + std::to_string(s.points.size() + 1);
      in.require(3, "vertex line (v x y z)");
      s.points.emplace_back(in.to_double(1, name + " x"), in.to_double(2, name + " y"));
      check_z(in, 3, static_cast<int>(s.points.size()), warned_z, warn);
      s.point_lines.push_back(in.line());
    } else if (key == "f") {
      const std::string name = "face " + std::to_string(s.faces.size() + 1);
      if (in.size() != 4)
        in.fail(name + " has " + std::to_string(in.size() - 1) + " vertices, only triangles are supported");
      std::array<int, 3> t{};
      for (int c = 0; c < 3; ++c) {
        std::string_view tok = in[1 + c];
        tok = tok.substr(0, tok.find('/'));  // v/vt/vn: keep v
        long long v = 0;
        if (!detail::parse_int(tok, v)) in.fail(name + ": '" + std::string(in[1 + c]) + "' is not a vertex index");
        if (v < 0) v += static_cast<long long>(s.points.size()) + 1;  // relative index
        if (v <= 0) in.fail(name + " uses vertex " + std::string(in[1 + c]) + ", out of range");
        raw.push_back(v);
        t[c] = v > static_cast<long long>(std::numeric_limits<int>::max()) ? -1 : static_cast<int>(v - 1);
      }
      s.faces.push_back(t);
      s.face_lines.push_back(in.line());
    }
    // vt, vn, g, o, s, usemtl, mtllib, l, ...: ignored
  }
  for (std::size_t f = 0; f < s.faces.size(); ++f)
    for (int c = 0; c < 3; ++c)
      if (raw[3 * f + c] > static_cast<long long>(s.points.size()))
        throw InvalidInput(path + ":" + std::to_string(s.face_lines[f]) + ": face " + std::to_string(f + 1) +
                           " uses vertex " + std::to_string(raw[3 * f + c]) + ", out of range (" +
                           std::to_string(s.points.size()) + " vertices)");
  return detail::build_mesh(std::move(s), warn);
}

Mesh read_node_ele(const std::string& path, const WarningSink& warn) {
  detail::Soup s;
  s.path = detail::with_extension(path, ".node");
  s.faces_path = detail::with_extension(path, ".ele");
  detail::NodeList nodes = detail::read_node_file(s.path, warn);
  s.points = std::move(nodes.points);
  s.markers = std::move(nodes.markers);
  s.point_lines = std::move(nodes.lines);
  s.base = nodes.base;
  const long long nv = static_cast<long long>(s.points.size());

  LineReader in(s.faces_path);
  if (!in.next()) in.fail("missing header (triangles nodes-per-triangle attributes)");
  const long long nf = in.to_int(0, "triangle count");
  const long long per = in.size() > 1 ? in.to_int(1, "nodes per triangle") : 3;
  if (nf < 0) in.fail("negative triangle count");
  if (per != 3 && per != 6) in.fail("nodes per triangle is " + std::to_string(per) + ", expected 3 or 6");
  if (per == 6 && warn) warn(in.where() + "second-order triangles: only the corners are kept");
  for (long long f = 0; f < nf; ++f) {
    if (!in.next()) in.fail("expected " + std::to_string(nf) + " triangles, file ends after " + std::to_string(f));
    const std::string name = "triangle " + std::to_string(f + s.base);
    in.require(4, "triangle line (index a b c)");
    std::array<int, 3> t{};
    for (int c = 0; c < 3; ++c) {
      const long long v = in.to_int(1 + c, name + " vertex");
      if (v < s.base || v >= s.base + nv)
        in.fail(name + " uses vertex " + std::to_string(v) + ", out of range (" + std::to_string(nv) +
                " vertices numbered from " + std::to_string(s.base) + ")");
      t[c] = static_cast<int>(v - s.base);
    }
    s.faces.push_back(t);
    s.face_lines.push_back(in.line());
  }
  return detail::build_mesh(std::move(s), warn);
}

// Dense numbering of the live vertices.
std::vector<int> dense_vertex_numbers(const Mesh& mesh, std::size_t& count) {
  std::vector<int> number(mesh.n_vertices(), -1);
  count = 0;
  for (auto vh : mesh.vertices()) number[vh.idx()] = static_cast<int>(count++);
  return number;
}

std::size_t count_faces(const Mesh& mesh) {
  std::size_t n = 0;
  for (auto fh : mesh.faces()) {
    (void)fh;
    ++n;
  }
  return n;
}

void write_off(const Mesh& mesh, const std::string& path) {
  detail::AtomicFile file(path);
  {
    detail::TextBlock out(file.stream());
    std::size_t nv = 0;
    const auto number = dense_vertex_numbers(mesh, nv);
    out << "OFF\n" << nv << ' ' << count_faces(mesh) << " 0\n";
    for (auto vh : mesh.vertices()) {
      const auto& p = mesh.point(vh);
      out << p[0] << ' ' << p[1] << " 0\n";
    }
    for (auto fh : mesh.faces()) {
      out << '3';
      for (auto fv : mesh.fv_range(fh)) out << ' ' << number[fv.idx()];
      out << '\n';
    }
  }
  file.commit();
}

void write_obj(const Mesh& mesh, const std::string& path) {
  detail::AtomicFile file(path);
  {
    detail::TextBlock out(file.stream());
    std::size_t nv = 0;
    const auto number = dense_vertex_numbers(mesh, nv);
    out << "# libacute mesh: " << nv << " vertices, " << count_faces(mesh) << " triangles\n";
    for (auto vh : mesh.vertices()) {
      const auto& p = mesh.point(vh);
      out << "v " << p[0] << ' ' << p[1] << " 0\n";
    }
    for (auto fh : mesh.faces()) {
      out << 'f';
      for (auto fv : mesh.fv_range(fh)) out << ' ' << number[fv.idx()] + 1;
      out << '\n';
    }
  }
  file.commit();
}

void write_node_ele(const Mesh& mesh, const std::string& path) {
  detail::AtomicFile node(detail::with_extension(path, ".node"));
  detail::AtomicFile ele(detail::with_extension(path, ".ele"));
  {
    std::size_t nv = 0;
    const auto number = dense_vertex_numbers(mesh, nv);
    detail::TextBlock out(node.stream());
    out << nv << " 2 0 1\n";
    for (auto vh : mesh.vertices()) {
      const auto& p = mesh.point(vh);
      out << number[vh.idx()] + 1 << ' ' << p[0] << ' ' << p[1] << ' ' << mesh.data(vh).marker << '\n';
    }
    detail::TextBlock elements(ele.stream());
    elements << count_faces(mesh) << " 3 0\n";
    std::size_t f = 0;
    for (auto fh : mesh.faces()) {
      elements << ++f;
      for (auto fv : mesh.fv_range(fh)) elements << ' ' << number[fv.idx()] + 1;
      elements << '\n';
    }
  }
  node.commit();
  ele.commit();
}

}  // namespace

Mesh read_mesh(const std::string& path, const WarningSink& warn) {
  const std::string ext = detail::extension_of(path);
  if (ext == ".off") return read_off(path, warn);
  if (ext == ".obj") return read_obj(path, warn);
  if (ext == ".ply") return detail::read_ply(path, warn);
  if (ext == ".node" || ext == ".ele") return read_node_ele(path, warn);
  throw IoError(path + ": unknown mesh format '" + ext + "' (expected .off, .obj, .ply, .node, .ele)");
}

void write_mesh(const Mesh& mesh, const std::string& path, const WriteOptions& options) {
  const std::string ext = detail::extension_of(path);
  if (ext == ".off") return write_off(mesh, path);
  if (ext == ".obj") return write_obj(mesh, path);
  if (ext == ".node" || ext == ".ele") return write_node_ele(mesh, path);
  if (ext == ".svg") return write_svg(mesh, path, options);
  if (ext == ".ply") return write_ply(mesh, path);
  if (ext == ".vtk") return write_vtk(mesh, path);
  if (ext == ".vtu") return write_vtu(mesh, path);
  if (ext == ".msh") return write_msh(mesh, path);
  throw IoError(path + ": unknown output format '" + ext +
                "' (expected .off, .obj, .ply, .vtk, .vtu, .msh, .node, .ele, .svg)");
}

}  // namespace acute::io
