#include "io/svg_canvas.h"

#include <algorithm>
#include <charconv>
#include <limits>

namespace acute::io::detail {

std::string svg_fixed(double x, int digits) {
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

SvgFrame::SvgFrame(SvgBox box) {
  if (!(box.xmin <= box.xmax) || !(box.ymin <= box.ymax)) box = SvgBox{0, 0, 1, 1};
  const auto [xmin, ymin, xmax, ymax] = box;
  const double extent = std::max({xmax - xmin, ymax - ymin, std::numeric_limits<double>::min()});
  xmin_ = xmin;
  ymax_ = ymax;
  scale_ = kDrawWidth / extent;
  margin_ = 0.02 * kDrawWidth;
  draw_w_ = (xmax - xmin) * scale_;
  draw_h_ = (ymax - ymin) * scale_;
}

std::string SvgFrame::at(const Point2& p) const {
  return svg_fixed(page_x(p)) + ' ' + svg_fixed(page_y(p));
}

double SvgFrame::page_width() const { return std::max(draw_w_ + 2 * margin_, 420.0); }

double SvgFrame::page_height(std::size_t legend_lines) const {
  return legend_top() + double(legend_lines) * kLineGap + margin_;
}

void begin_svg(std::ostream& out, double width, double height) {
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " << svg_fixed(width) << ' ' << svg_fixed(height)
      << "\" width=\"" << svg_fixed(width, 0) << "\" height=\"" << svg_fixed(height, 0) << "\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

void begin_text_group(std::ostream& out) {
  out << "<g font-family=\"sans-serif\" font-size=\"" << svg_fixed(SvgFrame::kFont, 0) << "\" fill=\"black\">\n";
}

double write_text_lines(std::ostream& out, const std::vector<std::string>& lines, double x, double top) {
  double y = top + SvgFrame::kFont;
  for (const auto& text : lines) {
    out << "<text x=\"" << svg_fixed(x) << "\" y=\"" << svg_fixed(y) << "\">" << xml_escape(text) << "</text>\n";
    y += SvgFrame::kLineGap;
  }
  return y;
}

void write_swatch(std::ostream& out, double x, double y, const char* fill, const std::string& text) {
  const double box = 0.8 * SvgFrame::kFont;
  out << "<rect x=\"" << svg_fixed(x) << "\" y=\"" << svg_fixed(y - box) << "\" width=\"" << svg_fixed(box)
      << "\" height=\"" << svg_fixed(box) << "\" fill=\"" << fill << "\"/>\n"
      << "<text x=\"" << svg_fixed(x + 1.5 * box) << "\" y=\"" << svg_fixed(y) << "\">" << xml_escape(text) << "</text>\n";
}

}  // namespace acute::io::detail
