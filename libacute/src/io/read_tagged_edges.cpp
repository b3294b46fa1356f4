// Edges a mesh file tags: OBJ polyline elements (`l a b c ...`), the format's own way to mark
// curves on a surface; acute repair keeps them as interior features.
#include "io/io_detail.h"

#include <acute/core/errors.h>
#include <acute/io/io.h>

#include <string>

namespace acute::io {

std::vector<TaggedEdge> read_tagged_edges(const std::string& path) {
  std::vector<TaggedEdge> edges;
  if (detail::extension_of(path) != ".obj") return edges;
  detail::LineReader in(path);
  long long n_vertices = 0;
  std::vector<long long> raw;  // 1-based indices as written (relative ones resolved), checked at the end
  while (in.next()) {
    const std::string_view key = in[0];
    if (key == "v") {
      ++n_vertices;
    } else if (key == "l") {
      in.require(3, "polyline (l a b ...)");
      long long previous = 0;
      for (std::size_t k = 1; k < in.size(); ++k) {
        std::string_view tok = in[k];
        tok = tok.substr(0, tok.find('/'));  // v/vt: keep v
        long long v = 0;
        if (!detail::parse_int(tok, v)) in.fail("polyline: '" + std::string(in[k]) + "' is not a vertex index");
        if (v < 0) v += n_vertices + 1;  // relative to the vertices so far
        if (v <= 0) in.fail("polyline uses vertex " + std::string(in[k]) + ", out of range");
        if (k > 1) {
          if (v == previous) in.fail("polyline repeats vertex " + std::to_string(v) + " in a row");
          raw.push_back(previous);
          raw.push_back(v);
          edges.push_back({{0, 0}, in.line()});
        }
        previous = v;
      }
    }
  }
  for (std::size_t e = 0; e < edges.size(); ++e)
    for (int c = 0; c < 2; ++c) {
      const long long v = raw[2 * e + static_cast<std::size_t>(c)];
      if (v > n_vertices)
        throw InvalidInput(path + ":" + std::to_string(edges[e].line) + ": polyline uses vertex " + std::to_string(v) +
                           ", out of range (" + std::to_string(n_vertices) + " vertices)");
      edges[e].vertices[static_cast<std::size_t>(c)] = static_cast<int>(v - 1);
    }
  return edges;
}

}  // namespace acute::io
