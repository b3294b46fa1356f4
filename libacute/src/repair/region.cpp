#include "repair/region.h"

#include <acute/core/errors.h>
#include <acute/mesh/segments.h>

#include <algorithm>
#include <cmath>

namespace acute::detail {

namespace {

/// Per-thread marks over the elements of a big mesh, put back to T{} on destruction entry by entry
/// (only those written): a region of a few hundred faces costs no allocation nor clearing of the
/// size of the mesh (millions of elements, once per cluster).
template <class T>
class Scratch {
 public:
  Scratch(std::vector<T>& buffer, std::size_t n) : buf_(buffer) {
    if (buf_.size() < n) buf_.resize(n, T{});
  }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;
  ~Scratch() {
    for (auto i : touched_) buf_[i] = T{};
  }
  const T& operator[](std::size_t i) const { return buf_[i]; }
  T& at(std::size_t i) {  // for writing
    touched_.push_back(i);
    return buf_[i];
  }

 private:
  std::vector<T>& buf_;
  std::vector<std::size_t> touched_;
};

thread_local std::vector<char> movable_buffer, region_buffer;
thread_local std::vector<VertexHandle> to_sub_buffer;

}  // namespace

bool extract_region(const Mesh& big, std::vector<VertexHandle> movable, const std::vector<bool>& big_forced, Region& region) {
  Scratch<char> is_movable(movable_buffer, big.n_vertices());
  for (auto vh : movable) is_movable.at(static_cast<std::size_t>(vh.idx())) = 1;
  Scratch<char> in_region(region_buffer, big.n_faces());
  std::vector<FaceHandle> faces;
  auto add_faces_of = [&](VertexHandle vh) {
    for (auto fh : big.vf_range(vh))
      if (!in_region[static_cast<std::size_t>(fh.idx())]) {
        in_region.at(static_cast<std::size_t>(fh.idx())) = 1;
        faces.push_back(fh);
      }
  };
  for (auto vh : movable) add_faces_of(vh);
  // Once the region's faces are removed, a frozen ring vertex must keep a single gap in its fan
  // (gaps of the mesh boundary count too), or re-adding faces would meet a complex vertex.
  auto missing = [&](FaceHandle fh) { return !fh.is_valid() || in_region[static_cast<std::size_t>(fh.idx())]; };
  auto gaps_after_removal = [&](VertexHandle vh) {
    int gaps = 0;
    for (auto heh : big.voh_range(vh))
      gaps += missing(big.face_handle(heh)) && !missing(big.face_handle(big.opposite_halfedge_handle(heh)));
    return gaps;
  };
  // Absorb such vertices into the region (a few passes: absorbing adds faces).
  for (int pass = 0; pass < 4; ++pass) {
    std::vector<VertexHandle> absorb;
    for (auto fh : faces)
      for (auto vh : big.fv_range(fh))
        if (!is_movable[static_cast<std::size_t>(vh.idx())] && gaps_after_removal(vh) > 1) {
          is_movable.at(static_cast<std::size_t>(vh.idx())) = 1;
          absorb.push_back(vh);
        }
    if (absorb.empty()) break;
    for (auto vh : absorb) {
      movable.push_back(vh);
      add_faces_of(vh);
    }
  }
  if (faces.empty()) return false;
  for (auto fh : faces)
    for (auto vh : big.fv_range(fh))
      if (!is_movable[static_cast<std::size_t>(vh.idx())] && gaps_after_removal(vh) > 1) return false;  // leave this cluster alone

  region = Region{};
  Mesh& sub = region.sub;
  Scratch<VertexHandle> to_sub(to_sub_buffer, big.n_vertices());
  auto map_vertex = [&](VertexHandle vh) {
    VertexHandle slot = to_sub[static_cast<std::size_t>(vh.idx())];
    if (!slot.is_valid()) {
      slot = sub.add_vertex(big.point(vh));
      sub.data(slot) = big.data(vh);
      const bool frozen = !is_movable[static_cast<std::size_t>(vh.idx())];
      // An input vertex never moves or goes: it keeps its handle, which the forced-corner flags
      // (indexed by handle) and the callers' lists of input vertices rely on.
      const bool kept = frozen || is_input(big, vh);
      if (frozen) sub.data(slot).kind = VertexKind::Input;
      region.to_big.push_back(kept ? vh : VertexHandle());
      const auto i = static_cast<std::size_t>(vh.idx());
      region.forced.push_back(i < big_forced.size() && big_forced[i]);
      to_sub.at(i) = slot;
    }
    return slot;
  };
  for (auto fh : faces) {
    VertexHandle v[3];
    int k = 0;
    for (auto vh : big.fv_range(fh)) v[k++] = map_vertex(vh);
    if (!sub.add_face(v[0], v[1], v[2]).is_valid()) return false;
  }
  for (auto fh : faces)
    for (auto heh : big.fh_range(fh)) {
      const auto sh = sub.find_halfedge(to_sub[static_cast<std::size_t>(big.from_vertex_handle(heh).idx())],
                                        to_sub[static_cast<std::size_t>(big.to_vertex_handle(heh).idx())]);
      const EdgeHandle se = sub.edge_handle(sh);
      sub.data(se) = big.data(big.edge_handle(heh));
      // A border of the copy that is not a border of the mesh is shared with faces outside it.
      sub.data(se).frozen = sub.is_boundary(se) && !big.is_boundary(big.edge_handle(heh));
    }
  share_segment_table(sub, big);
  region.big_faces = std::move(faces);
  for (auto vh : movable) region.big_inner.push_back(vh);
  return true;
}

std::vector<VertexHandle> commit_region(Mesh& big, const Region& region, const Mesh& sub) {
  for (auto fh : region.big_faces)
    if (!big.status(fh).deleted()) big.delete_face(fh, false);
  for (auto vh : region.big_inner)
    if (!big.status(vh).deleted() && !is_input(big, vh)) big.delete_vertex(vh, false);
  std::vector<VertexHandle> to_big(sub.n_vertices());
  std::vector<VertexHandle> created;
  for (auto vh : sub.vertices()) {
    const auto i = static_cast<std::size_t>(vh.idx());
    if (i < region.to_big.size() && region.to_big[i].is_valid()) {
      to_big[i] = region.to_big[i];
    } else {
      to_big[i] = big.add_vertex(sub.point(vh));
      big.data(to_big[i]) = sub.data(vh);
      created.push_back(to_big[i]);
    }
  }
  for (auto fh : sub.faces()) {
    VertexHandle v[3];
    int k = 0;
    for (auto vh : sub.fv_range(fh)) v[k++] = to_big[static_cast<std::size_t>(vh.idx())];
    if (!big.add_face(v[0], v[1], v[2]).is_valid()) throw InternalError("commit_region: face rejected by the mesh");
  }
  for (auto eh : sub.edges()) {
    const auto h = sub.halfedge_handle(eh, 0);
    const auto bh = big.find_halfedge(to_big[static_cast<std::size_t>(sub.from_vertex_handle(h).idx())],
                                      to_big[static_cast<std::size_t>(sub.to_vertex_handle(h).idx())]);
    if (bh.is_valid()) {
      big.data(big.edge_handle(bh)) = sub.data(eh);
      big.data(big.edge_handle(bh)).frozen = false;
    }
  }
  return created;
}

}  // namespace acute::detail

namespace acute::detail {

std::string constraint_violation(const Mesh& mesh) {
  const auto& table = segment_table(mesh);
  auto off_line = [&](const Point2& p, int seg) {
    if (seg < 0 || static_cast<std::size_t>(seg) >= table.size()) return false;
    const auto& [a, b] = table[static_cast<std::size_t>(seg)];
    const Point2 d = b - a;
    const double cross = d.x() * (p - a).y() - d.y() * (p - a).x();
    const double t = (p - a).dot(d) / d.squaredNorm();
    return std::abs(cross) / d.norm() > 1e-9 * d.norm() || t < -1e-9 || t > 1 + 1e-9;
  };
  for (auto fh : mesh.faces()) {
    Point2 p[3];
    int k = 0;
    for (auto vh : mesh.fv_range(fh)) p[k++] = point2(mesh, vh);
    if ((p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x() <= 0)
      return "face " + std::to_string(fh.idx()) + " not counter-clockwise";
  }
  for (auto eh : mesh.edges()) {
    const int seg = mesh.data(eh).segment;
    if (seg < 0) {
      if (mesh.is_boundary(eh)) return "edge " + std::to_string(eh.idx()) + " on the boundary but unconstrained";
      continue;
    }
    const auto h = mesh.halfedge_handle(eh, 0);
    for (auto vh : {mesh.from_vertex_handle(h), mesh.to_vertex_handle(h)})
      if (off_line(point2(mesh, vh), seg))
        return "edge " + std::to_string(eh.idx()) + " of segment " + std::to_string(seg) + ": vertex " + std::to_string(vh.idx()) + " off the segment";
  }
  for (auto vh : mesh.vertices())
    if (mesh.data(vh).kind == VertexKind::OnSegment && off_line(point2(mesh, vh), mesh.data(vh).segment))
      return "vertex " + std::to_string(vh.idx()) + " off its segment " + std::to_string(mesh.data(vh).segment);
  return {};
}

}  // namespace acute::detail
