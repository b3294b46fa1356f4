// SVG bar chart of the angles of a mesh: bins over [0, 180] degrees, the angles outside the
// bounds stacked on top in the colours of the mesh picture, the bounds drawn as vertical lines.
#include "io/atomic_file.h"
#include "io/svg_canvas.h"

#include <acute/core/errors.h>
#include <acute/io/io.h>
#include <acute/mesh/quality.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace acute::io {

namespace {

using detail::svg_fixed;

constexpr const char* kOkFill = "#6b8fb3";
constexpr const char* kSmallFill = "#fdb863";  // as write_svg: below the min bound
constexpr const char* kLargeFill = "#d7191c";  // as write_svg: at or above the max bound

enum Kind { kOk = 0, kSmall = 1, kLarge = 2 };

/// A round step giving about `target` ticks up to `top`.
double tick_step(double top, int target) {
  const double raw = std::max(top / target, 1.0);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

}  // namespace

void write_angle_histogram_svg(const Mesh& mesh, const std::string& path, const WriteOptions& options) {
  const double width = options.histogram_bin_deg;
  if (!(width > 0 && width <= 180)) throw InvalidInput("histogram bin width must lie in (0, 180] degrees");
  const int n_bins = std::max(1, int(std::ceil(180.0 / width - 1e-9)));
  std::vector<std::array<std::size_t, 3>> counts(n_bins, {0, 0, 0});
  std::array<std::size_t, 3> totals{0, 0, 0};
  std::size_t n_triangles = 0;
  const bool exact_right = options.max_angle_deg == 90.0;
  for (auto fh : mesh.faces()) {
    std::array<Point2, 3> p;
    int k = 0;
    for (auto fv : mesh.fv_range(fh))
      if (k < 3) p[k++] = point2(mesh, fv);
    const auto angles = triangle_angles_deg(p[0], p[1], p[2]);
    for (int i = 0; i < 3; ++i) {
      const double a = angles[i];
      const bool large = exact_right ? predicates::angle_kind(p[i], p[(i + 1) % 3], p[(i + 2) % 3]) != AngleKind::Acute
                                     : a >= options.max_angle_deg - 1e-9;
      const Kind kind = large ? kLarge : (a < options.min_angle_deg ? kSmall : kOk);
      const int bin = std::clamp(int(std::floor(a / width)), 0, n_bins - 1);
      ++counts[bin][kind];
      ++totals[kind];
    }
    ++n_triangles;
  }
  std::size_t tallest = 1;
  for (const auto& c : counts) tallest = std::max(tallest, c[0] + c[1] + c[2]);

  // Plot area in page units; x in degrees, y in counts.
  const double left = 70, top = 30, plot_w = 900, plot_h = 400;
  const double step = tick_step(double(tallest), 5);
  const double y_top = std::ceil(double(tallest) / step) * step;
  auto X = [&](double deg) { return left + deg / 180.0 * plot_w; };
  auto H = [&](std::size_t n) { return n ? std::max(1.0, double(n) / y_top * plot_h) : 0.0; };  // 1 unit at least
  const double base = top + plot_h;

  std::vector<std::string> legend;
  if (!options.title.empty()) legend.push_back(options.title);
  legend.push_back("all " + std::to_string(3 * n_triangles) + " angles of " + std::to_string(n_triangles) +
                   " triangles, bins of " + svg_fixed(width, width == std::floor(width) ? 0 : 2) + "\u00b0");
  const double legend_top = base + 45;
  const double page_w = left + plot_w + 30;
  const double page_h = legend_top + double(legend.size() + 2) * detail::SvgFrame::kLineGap + 20;

  detail::AtomicFile file(path);
  std::ostream& out = file.stream();
  detail::begin_svg(out, page_w, page_h);
  // Axes, ticks and grid (under the bars).
  out << "<g stroke=\"black\" stroke-width=\"1\" fill=\"none\">\n<path d=\"M" << svg_fixed(left) << ' ' << svg_fixed(top)
      << "V" << svg_fixed(base) << "H" << svg_fixed(left + plot_w) << "\"/>\n</g>\n";
  out << "<g font-family=\"sans-serif\" font-size=\"13\" fill=\"black\">\n";
  for (int deg = 0; deg <= 180; deg += 30)
    out << "<path stroke=\"black\" d=\"M" << svg_fixed(X(deg)) << ' ' << svg_fixed(base) << "v5\"/><text x=\""
        << svg_fixed(X(deg)) << "\" y=\"" << svg_fixed(base + 20) << "\" text-anchor=\"middle\">" << deg
        << "\u00b0</text>\n";
  for (double v = step; v <= y_top + 0.5; v += step) {
    const double y = base - v / y_top * plot_h;
    out << "<path stroke=\"#ddd\" d=\"M" << svg_fixed(left) << ' ' << svg_fixed(y) << "H" << svg_fixed(left + plot_w)
        << "\"/><text x=\"" << svg_fixed(left - 6) << "\" y=\"" << svg_fixed(y + 4) << "\" text-anchor=\"end\">"
        << static_cast<long long>(v) << "</text>\n";
  }
  out << "<text x=\"" << svg_fixed(left - 6) << "\" y=\"" << svg_fixed(base + 4) << "\" text-anchor=\"end\">0</text>\n";
  out << "<text x=\"" << svg_fixed(left + plot_w / 2) << "\" y=\"" << svg_fixed(base + 38)
      << "\" text-anchor=\"middle\">angle (degrees)</text>\n</g>\n";
  // Bars: within the bounds at the bottom, below the min bound, then at or above the max bound.
  const char* fills[3] = {kOkFill, kSmallFill, kLargeFill};
  const char* names[3] = {"ok", "small", "large"};
  for (int b = 0; b < n_bins; ++b) {
    const double x0 = X(b * width), x1 = X(std::min(180.0, (b + 1) * width));
    double y = base;
    for (int kind : {kOk, kSmall, kLarge}) {
      const std::size_t n = counts[b][kind];
      if (!n) continue;
      const double h = H(n);
      y -= h;
      out << "<rect class=\"bar\" data-bin=\"" << b << "\" data-kind=\"" << names[kind] << "\" data-count=\"" << n
          << "\" x=\"" << svg_fixed(x0 + 0.5) << "\" y=\"" << svg_fixed(y) << "\" width=\""
          << svg_fixed(std::max(0.5, x1 - x0 - 1.0)) << "\" height=\"" << svg_fixed(h) << "\" fill=\"" << fills[kind]
          << "\"><title>" << svg_fixed(b * width, 1) << "\u2013" << svg_fixed(std::min(180.0, (b + 1) * width), 1)
          << "\u00b0: " << n << "</title></rect>\n";
    }
  }
  // The bounds.
  for (const auto& [deg, colour] : {std::pair{options.min_angle_deg, kSmallFill}, std::pair{options.max_angle_deg, kLargeFill}}) {
    if (!(deg > 0 && deg < 180)) continue;
    out << "<path class=\"bound\" stroke=\"" << colour << "\" stroke-width=\"2\" stroke-dasharray=\"6 4\" d=\"M"
        << svg_fixed(X(deg)) << ' ' << svg_fixed(top - 10) << "V" << svg_fixed(base) << "\"/>\n"
        << "<text font-family=\"sans-serif\" font-size=\"13\" x=\"" << svg_fixed(X(deg) + 4) << "\" y=\""
        << svg_fixed(top - 2) << "\" fill=\"black\">" << svg_fixed(deg, 1) << "\u00b0</text>\n";
  }
  detail::begin_text_group(out);
  const double y = detail::write_text_lines(out, legend, 20, legend_top);
  const bool min_bound = options.min_angle_deg > 0;  // as write_svg: no swatch for a min bound of 0
  if (min_bound)
    detail::write_swatch(out, 20, y, kSmallFill,
                         "angle < " + svg_fixed(options.min_angle_deg, 1) + "\u00b0: " + std::to_string(totals[kSmall]) + " angles");
  detail::write_swatch(out, 20, min_bound ? y + detail::SvgFrame::kLineGap : y, kLargeFill,
                       "angle \u2265 " + svg_fixed(options.max_angle_deg, 1) + "\u00b0: " + std::to_string(totals[kLarge]) +
                           " angles");
  out << "</g>\n</svg>\n";
  file.commit();
}

}  // namespace acute::io
