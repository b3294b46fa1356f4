// SVG picture of a mesh: edges (constrained ones bold), bad triangles filled, optional vertex
// labels, a legend.
#include "io/atomic_file.h"
#include "io/io_detail.h"
#include "io/svg_canvas.h"

#include <acute/core/errors.h>
#include <acute/io/io.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <cmath>

namespace acute::io {

namespace {

using detail::svg_fixed;

constexpr const char* kSmallFill = "#fdb863";  // an angle below the min bound
constexpr const char* kLargeFill = "#d7191c";  // an angle at or above the max bound

double angle_deg(const Point2& apex, const Point2& p, const Point2& q) {
  const Point2 u = p - apex, v = q - apex;
  return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v)) * (180.0 / M_PI);
}

}  // namespace

void write_svg(const Mesh& mesh, const std::string& path, const WriteOptions& options) {
  detail::SvgBox box;
  std::size_t n_vertices = 0;
  for (auto vh : mesh.vertices()) box.add(point2(mesh, vh)), ++n_vertices;
  const detail::SvgFrame frame(box);
  auto at = [&](VertexHandle vh) { return frame.at(point2(mesh, vh)); };

  // Classify triangles; fills only for bad ones to keep big meshes small.
  std::size_t n_triangles = 0, n_small = 0, n_large = 0;
  double min_angle = 180, max_angle = 0, edge_sum = 0;
  std::string small_path, large_path;
  const bool exact_right = options.max_angle_deg == 90.0;
  for (auto fh : mesh.faces()) {
    VertexHandle v[3];
    int k = 0;
    for (auto fv : mesh.fv_range(fh))
      if (k < 3) v[k++] = fv;
    const Point2 a = point2(mesh, v[0]), b = point2(mesh, v[1]), c = point2(mesh, v[2]);
    const double angles[3] = {angle_deg(a, b, c), angle_deg(b, c, a), angle_deg(c, a, b)};
    const double lo = std::min({angles[0], angles[1], angles[2]}), hi = std::max({angles[0], angles[1], angles[2]});
    min_angle = std::min(min_angle, lo);
    max_angle = std::max(max_angle, hi);
    edge_sum += (b - a).norm() + (c - b).norm() + (a - c).norm();
    ++n_triangles;
    const bool large = exact_right ? (predicates::angle_kind(a, b, c) != AngleKind::Acute ||
                                      predicates::angle_kind(b, c, a) != AngleKind::Acute ||
                                      predicates::angle_kind(c, a, b) != AngleKind::Acute)
                                   : hi >= options.max_angle_deg - 1e-9;
    const bool small = lo < options.min_angle_deg;
    n_large += large;
    n_small += small;
    if (large || small) {
      std::string& d = large ? large_path : small_path;
      d += 'M' + at(v[0]) + 'L' + at(v[1]) + 'L' + at(v[2]) + 'Z';
    }
  }
  const double mean_edge =
      n_triangles ? edge_sum / (3.0 * double(n_triangles)) * frame.scale() : detail::SvgFrame::kDrawWidth / 10;
  const double thin = std::clamp(0.08 * mean_edge, 0.03, 1.0);
  const double bold = std::clamp(3.0 * thin, 0.3, 3.0);

  std::string edges, constrained;
  for (auto eh : mesh.edges()) {
    const auto heh = mesh.halfedge_handle(eh, 0);
    std::string& d = is_constrained(mesh, eh) ? constrained : edges;
    d += 'M' + at(mesh.from_vertex_handle(heh)) + 'L' + at(mesh.to_vertex_handle(heh));
  }

  std::vector<std::string> legend;
  if (!options.title.empty()) legend.push_back(options.title);
  legend.push_back(std::to_string(n_vertices) + " vertices, " + std::to_string(n_triangles) + " triangles");
  if (n_triangles)
    legend.push_back("angles from " + svg_fixed(min_angle) + "\u00b0 to " + svg_fixed(max_angle) + "\u00b0");
  const std::string bounds_small = "angle < " + svg_fixed(options.min_angle_deg, 1) + "\u00b0: ";
  const std::string bounds_large = "angle \u2265 " + svg_fixed(options.max_angle_deg, 1) + "\u00b0: ";

  detail::AtomicFile file(path);
  std::ostream& out = file.stream();
  detail::begin_svg(out, frame.page_width(), frame.page_height(legend.size() + 2));
  if (!small_path.empty()) out << "<path fill=\"" << kSmallFill << "\" stroke=\"none\" d=\"" << small_path << "\"/>\n";
  if (!large_path.empty()) out << "<path fill=\"" << kLargeFill << "\" stroke=\"none\" d=\"" << large_path << "\"/>\n";
  if (!edges.empty())
    out << "<path fill=\"none\" stroke=\"#333\" stroke-width=\"" << svg_fixed(thin, 3)
        << "\" stroke-linecap=\"round\" d=\"" << edges << "\"/>\n";
  if (!constrained.empty())
    out << "<path fill=\"none\" stroke=\"black\" stroke-width=\"" << svg_fixed(bold, 3)
        << "\" stroke-linecap=\"round\" d=\"" << constrained << "\"/>\n";
  if (options.vertex_labels && n_vertices) {
    // Index in vertex order (the order of the written mesh file, 0-based), beside the vertex.
    const double size = std::clamp(0.3 * mean_edge, 2.0, 14.0);
    out << "<g font-family=\"sans-serif\" font-size=\"" << svg_fixed(size, 1) << "\" fill=\"#1f4e9c\" stroke=\"white\" stroke-width=\""
        << svg_fixed(0.2 * size) << "\" paint-order=\"stroke\">\n";
    for (auto vh : mesh.vertices()) {
      const Point2 p = point2(mesh, vh);
      const double x = frame.page_x(p), y = frame.page_y(p);
      out << "<circle cx=\"" << svg_fixed(x) << "\" cy=\"" << svg_fixed(y) << "\" r=\"" << svg_fixed(0.15 * size) << "\"/>"
          << "<text x=\"" << svg_fixed(x + 0.25 * size) << "\" y=\"" << svg_fixed(y - 0.25 * size) << "\">" << vh.idx()
          << "</text>\n";
    }
    out << "</g>\n";
  }
  detail::begin_text_group(out);
  const double y = detail::write_text_lines(out, legend, frame.margin(), frame.legend_top());
  // No min bound (0, e.g. the keep-vertices repair): its swatch would say nothing.
  const bool min_bound = options.min_angle_deg > 0;
  if (min_bound) detail::write_swatch(out, frame.margin(), y, kSmallFill, bounds_small + std::to_string(n_small) + " triangles");
  detail::write_swatch(out, frame.margin(), min_bound ? y + detail::SvgFrame::kLineGap : y, kLargeFill,
                       bounds_large + std::to_string(n_large) + " triangles");
  out << "</g>\n</svg>\n";
  file.commit();
}

}  // namespace acute::io
