// `acute render`: an SVG picture of a mesh (bad triangles filled, constraints bold, optional
// vertex labels), or of its angle histogram.
#include "commands/commands.h"
#include "commands/pictures.h"

#include <acute/core/errors.h>
#include <acute/io/io.h>
#include <acute/predicates/predicates.h>

#include <algorithm>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace acute::cli {

namespace {

/// More labels than this would hide the mesh: --labels is ignored (with a note) above it.
constexpr std::size_t kMaxLabelledVertices = 500;

struct RenderArgs {
  std::string mesh_path;
  std::string out_path;
  std::string domain_path;
  std::string title;
  double min_angle = 30.0;
  double max_angle = 90.0;
  bool histogram = false;
  double bin_width = 5.0;
  bool labels = false;
};

bool has_svg_extension(const std::string& path) {
  return path.size() >= 4 && (path.compare(path.size() - 4, 4, ".svg") == 0 || path.compare(path.size() - 4, 4, ".SVG") == 0);
}

bool lex_less(const Point2& p, const Point2& q) { return p.x() != q.x() ? p.x() < q.x() : p.y() < q.y(); }

/// Marks the mesh edges that lie on a domain segment as constrained (so they are drawn bold) and
/// the vertices at domain points as input vertices.
void mark_domain(Mesh& mesh, const Domain& domain) {
  std::vector<VertexHandle> sorted;
  for (auto vh : mesh.vertices()) sorted.push_back(vh);
  std::sort(sorted.begin(), sorted.end(), [&](VertexHandle a, VertexHandle b) { return lex_less(point2(mesh, a), point2(mesh, b)); });
  auto first_at_x = [&](double x) {
    return std::lower_bound(sorted.begin(), sorted.end(), x, [&](VertexHandle vh, double v) { return mesh.point(vh)[0] < v; });
  };
  for (std::size_t i = 0; i < domain.points.size(); ++i) {
    const Point2& p = domain.points[i];
    for (auto it = first_at_x(p.x()); it != sorted.end() && mesh.point(*it)[0] == p.x(); ++it)
      if (point2(mesh, *it) == p) {
        mesh.data(*it).kind = VertexKind::Input;
        mesh.data(*it).input_index = int(i);
      }
  }
  const int np = int(domain.points.size());
  for (std::size_t s = 0; s < domain.segments.size(); ++s) {
    const auto [ia, ib] = domain.segments[s];
    if (ia < 0 || ib < 0 || ia >= np || ib >= np) continue;
    const Point2 &a = domain.points[ia], &b = domain.points[ib];
    if (a == b) continue;
    const double xlo = std::min(a.x(), b.x()), xhi = std::max(a.x(), b.x());
    const double ylo = std::min(a.y(), b.y()), yhi = std::max(a.y(), b.y());
    std::vector<char> on(mesh.n_vertices(), 0);
    std::vector<VertexHandle> hits;
    for (auto it = first_at_x(xlo); it != sorted.end() && mesh.point(*it)[0] <= xhi; ++it) {
      const Point2 p = point2(mesh, *it);
      if (p.y() < ylo || p.y() > yhi) continue;
      if (predicates::locate_on_segment(p, a, b) != predicates::SegmentLocation::Outside) {
        on[it->idx()] = 1;
        hits.push_back(*it);
      }
    }
    for (auto vh : hits)
      for (auto heh : mesh.voh_range(vh)) {
        const auto to = mesh.to_vertex_handle(heh);
        if (on[to.idx()]) {
          mesh.data(mesh.edge_handle(heh)).segment = int(s);
          mesh.data(mesh.edge_handle(heh)).marker = domain.segment_markers.size() > s ? domain.segment_markers[s] : 0;
        }
      }
  }
}

int run_render(const RenderArgs& a, const GlobalOptions& global) {
  if (!has_svg_extension(a.out_path)) throw InvalidInput(a.out_path + ": render writes SVG: name the output *.svg");
  Mesh mesh = io::read_mesh(a.mesh_path);
  if (!a.domain_path.empty())
    mark_domain(mesh, io::read_domain(a.domain_path));
  else
    mark_boundary_constrained(mesh);  // a mesh file carries no segments: its boundary is the one we know
  io::WriteOptions opt;
  opt.min_angle_deg = a.min_angle;
  opt.max_angle_deg = a.max_angle;
  opt.title = a.title.empty() ? a.mesh_path : a.title;
  opt.histogram_bin_deg = a.bin_width;
  if (a.histogram) {
    io::write_angle_histogram_svg(mesh, a.out_path, opt);
    return Ok;
  }
  opt.vertex_labels = a.labels && mesh.n_vertices() <= kMaxLabelledVertices;
  if (a.labels && !opt.vertex_labels && !global.quiet)
    std::cerr << "acute: note: --labels ignored: " << mesh.n_vertices() << " vertices (labels are drawn up to "
              << kMaxLabelledVertices << ")\n";
  io::write_svg(mesh, a.out_path, opt);
  return Ok;
}

}  // namespace

void add_render_command(CLI::App& app, const GlobalOptions& global, int& exit_code) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* sub = app.add_subcommand("render", "Draw a mesh, or its angle histogram, as SVG");
  sub->footer(
      "The mesh picture fills triangles with an angle below --min-angle (orange) or not below\n"
      "--max-angle (red); the boundary is drawn bold, and with --domain every mesh edge on one of its\n"
      "segments (interior ones too).\n"
      "--histogram draws all 3T angles in bins of --bin-width degrees over [0, 180] instead: the\n"
      "angles outside the bounds in the same colours, the bounds as dashed lines.\n\n"
      "Examples:\n"
      "  acute render out.off -o out.svg --domain in.poly --min-angle 30 --max-angle 90\n"
      "  acute render out.off -o hist.svg --histogram --bin-width 5\n"
      "  acute render small.off -o small.svg --labels      # vertex indices (up to 500 vertices)\n");
  sub->add_option("mesh", args->mesh_path, "Triangle mesh (.off .obj .ply .node/.ele)")->type_name("MESH")->required()->check(CLI::ExistingFile);
  sub->add_option("-o,--output", args->out_path, "Output SVG file")->type_name("OUT.svg")->required();
  sub->add_option("--domain", args->domain_path, "Input domain (.poly, CG:SHOP .json, or a mesh): draws its segments bold")
      ->type_name("DOMAIN")
      ->check(CLI::ExistingFile);
  sub->add_option("--min-angle", args->min_angle, "Angles below this are bad (degrees, default 30)")->check(CLI::Range(0.0, 180.0));
  sub->add_option("--max-angle", args->max_angle, "Angles not below this are bad (degrees, default 90)")->check(CLI::Range(0.0, 180.0));
  auto* histogram = sub->add_flag("--histogram", args->histogram, "Draw the angle histogram instead of the mesh");
  sub->add_option("--bin-width", args->bin_width, "Histogram bin width in degrees (default 5)")
      ->check(CLI::Range(0.1, 180.0))
      ->needs(histogram);
  sub->add_flag("--labels", args->labels, "Label each vertex with its index (0-based; meshes up to 500 vertices)")
      ->excludes(histogram);
  sub->add_option("--title", args->title, "Legend title (default: the mesh path)");
  sub->add_flag("-q,--quiet", const_cast<GlobalOptions&>(global).quiet, "No output but errors");
  sub->callback([args, &global, &exit_code] { exit_code = run_guarded([&] { return run_render(*args, global); }); });
}

}  // namespace acute::cli
