// Layer: io (private). What the SVG writers share: number formatting, escaping, the map from
// mesh coordinates to the page, and the document preamble and legend.
#pragma once

#include <acute/core/types.h>

#include <algorithm>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace acute::io::detail {

/// `digits` decimals, C locale.
std::string svg_fixed(double x, int digits = 2);
/// Escapes & < > " for text and attribute values.
std::string xml_escape(const std::string& s);

/// The bounding box of the points added to it.
struct SvgBox {
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  void add(const Point2& p) {
    xmin = std::min(xmin, p.x()), xmax = std::max(xmax, p.x());
    ymin = std::min(ymin, p.y()), ymax = std::max(ymax, p.y());
  }
};

/// Maps a bounding box onto a page kDrawWidth units wide (y up becomes y down), with a margin.
class SvgFrame {
 public:
  static constexpr double kDrawWidth = 1000.0;
  static constexpr double kFont = 16.0;
  static constexpr double kLineGap = 1.3 * kFont;

  /// An empty box (xmin > xmax) becomes the unit square.
  explicit SvgFrame(SvgBox box);

  double scale() const { return scale_; }
  double margin() const { return margin_; }
  /// Page coordinates of a point, and "x y" of them.
  double page_x(const Point2& p) const { return (p.x() - xmin_) * scale_ + margin_; }
  double page_y(const Point2& p) const { return (ymax_ - p.y()) * scale_ + margin_; }
  std::string at(const Point2& p) const;
  /// Top of the legend below the drawing.
  double legend_top() const { return draw_h_ + 2 * margin_; }
  /// Page size for a legend of n lines.
  double page_width() const;
  double page_height(std::size_t legend_lines) const;

 private:
  double xmin_, ymax_, scale_, margin_, draw_w_, draw_h_;
};

/// XML declaration, <svg> with its viewBox and a white background.
void begin_svg(std::ostream& out, double width, double height);
/// Opens the <g> of the legend text (sans-serif, kFont); close it with "</g>\n".
void begin_text_group(std::ostream& out);
/// Lines of text from y = top (baseline of the first at top + font); returns the next baseline.
double write_text_lines(std::ostream& out, const std::vector<std::string>& lines, double x, double top);
/// A colour swatch followed by a text, on the baseline y.
void write_swatch(std::ostream& out, double x, double y, const char* fill, const std::string& text);

}  // namespace acute::io::detail
