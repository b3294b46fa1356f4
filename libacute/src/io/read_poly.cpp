// Triangle's .poly and .node formats.
#include "io/io_detail.h"

#include <acute/core/errors.h>
#include <acute/io/io.h>

#include <algorithm>

namespace acute::io {

namespace detail {

NodeList read_node_lines(LineReader& in, long long count, long long n_attributes, long long n_markers,
                         const WarningSink& warn) {
  NodeList nodes;
  // Counts come from the file: reserve at most a bounded amount (a bogus header must not exhaust memory).
  const auto cap = std::min<std::size_t>(static_cast<std::size_t>(count), std::size_t{1} << 20);
  nodes.points.reserve(cap);
  nodes.markers.reserve(cap);
  nodes.lines.reserve(cap);
  bool warned_numbering = false;
  for (long long i = 0; i < count; ++i) {
    if (!in.next())
      in.fail("expected " + std::to_string(count) + " vertices, file ends after " + std::to_string(i));
    in.require(3, "vertex line (index x y)");
    const long long index = in.to_int(0, "vertex index");
    if (i == 0) {
      if (index != 0 && index != 1) in.fail("first vertex is numbered " + std::to_string(index) + ", expected 0 or 1");
      nodes.base = static_cast<int>(index);
    } else if (index != nodes.base + i && !warned_numbering && warn) {
      // Triangle ignores these numbers too; vertices are numbered by position.
      warn(in.where() + "vertex numbered " + std::to_string(index) + ", expected " + std::to_string(nodes.base + i) +
           " (numbering by position)");
      warned_numbering = true;
    }
    const std::string name = "vertex " + std::to_string(nodes.base + i);
    const double x = in.to_double(1, name + " x");
    const double y = in.to_double(2, name + " y");
    int marker = 0;
    const std::size_t marker_pos = 3 + static_cast<std::size_t>(n_attributes);
    if (n_markers > 0 && in.size() > marker_pos) marker = static_cast<int>(in.to_int(marker_pos, name + " marker"));
    nodes.points.emplace_back(x, y);
    nodes.markers.push_back(marker);
    nodes.lines.push_back(in.line());
  }
  return nodes;
}

namespace {

struct NodeHeader {
  long long count = 0, dim = 2, attributes = 0, markers = 0;
};

NodeHeader read_node_header(LineReader& in, const char* what) {
  if (!in.next()) in.fail(std::string("missing ") + what + " header (count dimension attributes markers)");
  NodeHeader h;
  h.count = in.to_int(0, std::string(what) + " count");
  if (in.size() > 1) h.dim = in.to_int(1, "dimension");
  if (in.size() > 2) h.attributes = in.to_int(2, "number of attributes");
  if (in.size() > 3) h.markers = in.to_int(3, "number of boundary markers");
  if (h.count < 0) in.fail(std::string(what) + " count is negative");
  if (h.dim != 2) in.fail("dimension is " + std::to_string(h.dim) + ", only 2 is supported");
  if (h.attributes < 0 || h.markers < 0 || h.markers > 1) in.fail("bad attribute or marker count");
  return h;
}

}  // namespace

NodeList read_node_file(const std::string& path, const WarningSink& warn) {
  LineReader in(path);
  const NodeHeader h = read_node_header(in, "vertex");
  return read_node_lines(in, h.count, h.attributes, h.markers, warn);
}

}  // namespace detail

Domain read_poly(const std::string& path, const WarningSink& warn, const ReadOptions& options) {
  using namespace detail;
  LineReader in(path);
  Domain domain;
  domain.name = stem_of(path);
  domain.source_path = path;
  DomainSource source;
  source.points_file = path;
  source.segments_file = path;

  // Vertices, here or in the sibling .node file.
  const NodeHeader h = read_node_header(in, "vertex");
  NodeList nodes;
  if (h.count == 0) {
    source.points_file = with_extension(path, ".node");
    nodes = read_node_file(source.points_file, warn);
  } else {
    nodes = read_node_lines(in, h.count, h.attributes, h.markers, warn);
  }
  domain.points = std::move(nodes.points);
  domain.point_markers = std::move(nodes.markers);
  source.point_lines = std::move(nodes.lines);
  source.index_base = nodes.base;
  const long long n_points = static_cast<long long>(domain.points.size());

  // Segments.
  if (!in.next()) in.fail("missing segment header (count markers)");
  const long long n_segments = in.to_int(0, "segment count");
  const long long seg_markers = in.size() > 1 ? in.to_int(1, "number of segment markers") : 0;
  if (n_segments < 0) in.fail("segment count is negative");
  domain.segments.reserve(std::min<std::size_t>(static_cast<std::size_t>(n_segments), std::size_t{1} << 20));
  for (long long i = 0; i < n_segments; ++i) {
    if (!in.next())
      in.fail("expected " + std::to_string(n_segments) + " segments, file ends after " + std::to_string(i));
    in.require(3, "segment line (index a b)");
    const std::string name = "segment " + std::to_string(nodes.base + i);
    std::array<int, 2> seg{};
    for (int k = 0; k < 2; ++k) {
      const long long v = in.to_int(1 + k, name + " endpoint");
      if (v < nodes.base || v >= nodes.base + n_points)
        in.fail(name + " uses vertex " + std::to_string(v) + ", which is out of range (" + std::to_string(n_points) +
                " vertices numbered from " + std::to_string(nodes.base) + ")");
      seg[k] = static_cast<int>(v - nodes.base);
    }
    domain.segments.push_back(seg);
    domain.segment_markers.push_back(seg_markers > 0 && in.size() > 3 ? static_cast<int>(in.to_int(3, name + " marker")) : 0);
    source.segment_lines.push_back(in.line());
  }

  // Holes (Triangle requires the count line; we accept its absence with a warning).
  if (!in.next()) {
    if (warn) warn(in.where() + "no hole section, assuming no holes");
  } else {
    const long long n_holes = in.to_int(0, "hole count");
    if (n_holes < 0) in.fail("hole count is negative");
    for (long long i = 0; i < n_holes; ++i) {
      if (!in.next()) in.fail("expected " + std::to_string(n_holes) + " holes, file ends after " + std::to_string(i));
      in.require(3, "hole line (index x y)");
      const std::string name = "hole " + std::to_string(nodes.base + i);
      domain.holes.emplace_back(in.to_double(1, name + " x"), in.to_double(2, name + " y"));
      source.hole_lines.push_back(in.line());
    }
    // Optional regional attributes / area constraints: read for syntax, then ignored.
    if (in.next()) {
      const long long n_regions = in.to_int(0, "region count");
      if (n_regions < 0) in.fail("region count is negative");
      const int first_line = in.line();
      for (long long i = 0; i < n_regions; ++i) {
        if (!in.next())
          in.fail("expected " + std::to_string(n_regions) + " regions, file ends after " + std::to_string(i));
        in.require(3, "region line (index x y attribute area)");
        const std::string name = "region " + std::to_string(nodes.base + i);
        in.to_double(1, name + " x");
        in.to_double(2, name + " y");
      }
      if (n_regions > 0 && warn)
        warn(path + ":" + std::to_string(first_line) + ": " + std::to_string(n_regions) +
             " regional attributes / area constraints ignored");
      if (in.next() && warn) warn(in.where() + "unexpected content after the region section ignored");
    }
  }

  remove_duplicate_segments(domain, &source, warn);
  validate_domain(domain, &source, options.allow_crossing_segments);
  return domain;
}

}  // namespace acute::io
