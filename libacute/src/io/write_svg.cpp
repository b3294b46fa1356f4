// SVG picture of a mesh: edges (constrained ones bold), bad triangles filled, a legend.
#include "io/atomic_file.h"
#include "io/io_detail.h"

#include <acute/core/errors.h>
#include <acute/io/io.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace acute::io {

namespace {

constexpr double kWidth = 1000.0;  // drawing width in SVG user units
constexpr const char* kSmallFill = "#fdb863";  // an angle below the min bound
constexpr const char* kLargeFill = "#d7191c";  // an angle at or above the max bound

std::string fixed(double x, int digits = 2) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::fixed, digits);
  (void)ec;
  return std::string(buf, ptr);
}

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

double angle_deg(const Point2& apex, const Point2& p, const Point2& q) {
  const Point2 u = p - apex, v = q - apex;
  return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v)) * (180.0 / M_PI);
}

}  // namespace

void write_svg(const Mesh& mesh, const std::string& path, const WriteOptions& options) {
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  std::size_t n_vertices = 0;
  for (auto vh : mesh.vertices()) {
    const Point2 p = point2(mesh, vh);
    xmin = std::min(xmin, p.x());
    xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y());
    ymax = std::max(ymax, p.y());
    ++n_vertices;
  }
  const bool empty = n_vertices == 0;
  if (empty) xmin = ymin = 0, xmax = ymax = 1;
  const double extent = std::max({xmax - xmin, ymax - ymin, std::numeric_limits<double>::min()});
  const double scale = kWidth / extent;
  const double margin = 0.02 * kWidth;
  const double draw_w = (xmax - xmin) * scale, draw_h = (ymax - ymin) * scale;
  auto X = [&](double x) { return fixed((x - xmin) * scale + margin); };
  auto Y = [&](double y) { return fixed((ymax - y) * scale + margin); };  // SVG y goes down
  auto at = [&](VertexHandle vh) {
    const auto& p = mesh.point(vh);
    return X(p[0]) + ' ' + Y(p[1]);
  };

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
  const double mean_edge = n_triangles ? edge_sum / (3.0 * double(n_triangles)) * scale : kWidth / 10;
  const double thin = std::clamp(0.08 * mean_edge, 0.03, 1.0);
  const double bold = std::clamp(3.0 * thin, 0.3, 3.0);

  std::string edges, constrained;
  for (auto eh : mesh.edges()) {
    const auto heh = mesh.halfedge_handle(eh, 0);
    std::string& d = is_constrained(mesh, eh) ? constrained : edges;
    d += 'M' + at(mesh.from_vertex_handle(heh)) + 'L' + at(mesh.to_vertex_handle(heh));
  }

  const double font = 16.0, line_gap = 1.3 * font;
  std::vector<std::string> legend;
  if (!options.title.empty()) legend.push_back(options.title);
  legend.push_back(std::to_string(n_vertices) + " vertices, " + std::to_string(n_triangles) + " triangles");
  if (n_triangles)
    legend.push_back("angles from " + fixed(min_angle) + "\u00b0 to " + fixed(max_angle) + "\u00b0");
  const std::string bounds_small = "angle < " + fixed(options.min_angle_deg, 1) + "\u00b0: ";
  const std::string bounds_large = "angle \u2265 " + fixed(options.max_angle_deg, 1) + "\u00b0: ";
  const double legend_top = draw_h + 2 * margin;
  const double total_h = legend_top + (double(legend.size()) + 2) * line_gap + margin;
  const double total_w = std::max(draw_w + 2 * margin, 420.0);

  detail::AtomicFile file(path);
  std::ostream& out = file.stream();
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << fixed(total_w) << ' ' << fixed(total_h)
      << "\" width=\"" << fixed(total_w, 0) << "\" height=\"" << fixed(total_h, 0) << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!small_path.empty()) out << "<path fill=\"" << kSmallFill << "\" stroke=\"none\" d=\"" << small_path << "\"/>\n";
  if (!large_path.empty()) out << "<path fill=\"" << kLargeFill << "\" stroke=\"none\" d=\"" << large_path << "\"/>\n";
  if (!edges.empty())
    out << "<path fill=\"none\" stroke=\"#333\" stroke-width=\"" << fixed(thin, 3)
        << "\" stroke-linecap=\"round\" d=\"" << edges << "\"/>\n";
  if (!constrained.empty())
    out << "<path fill=\"none\" stroke=\"black\" stroke-width=\"" << fixed(bold, 3)
        << "\" stroke-linecap=\"round\" d=\"" << constrained << "\"/>\n";
  out << "<g font-family=\"sans-serif\" font-size=\"" << fixed(font, 0) << "\" fill=\"black\">\n";
  double y = legend_top + font;
  for (const auto& text : legend) {
    out << "<text x=\"" << fixed(margin) << "\" y=\"" << fixed(y) << "\">" << xml_escape(text) << "</text>\n";
    y += line_gap;
  }
  const double box = 0.8 * font;
  out << "<rect x=\"" << fixed(margin) << "\" y=\"" << fixed(y - box) << "\" width=\"" << fixed(box) << "\" height=\""
      << fixed(box) << "\" fill=\"" << kSmallFill << "\"/>\n"
      << "<text x=\"" << fixed(margin + 1.5 * box) << "\" y=\"" << fixed(y) << "\">" << xml_escape(bounds_small)
      << n_small << " triangles</text>\n";
  y += line_gap;
  out << "<rect x=\"" << fixed(margin) << "\" y=\"" << fixed(y - box) << "\" width=\"" << fixed(box) << "\" height=\""
      << fixed(box) << "\" fill=\"" << kLargeFill << "\"/>\n"
      << "<text x=\"" << fixed(margin + 1.5 * box) << "\" y=\"" << fixed(y) << "\">" << xml_escape(bounds_large)
      << n_large << " triangles</text>\n";
  out << "</g>\n</svg>\n";
  file.commit();
}

}  // namespace acute::io
