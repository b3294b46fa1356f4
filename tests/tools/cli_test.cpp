// The `acute` program run as a user runs it: pictures (mesh, labels, angle histogram, before /
// after) and the progress line (on a terminal only).
#include <acute/io/io.h>
#include <acute/mesh/mesh.h>

#include "support/paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

/// The `acute` binary's path (tests/tools/tests.cmake generates the definition).
const char* acute_cli_path();

namespace {

namespace fs = std::filesystem;

std::string mesh_file(const std::string& name) { return std::string(acute::test::meshes_dir()) + "/" + name; }
std::string out(const std::string& name) { return std::string(acute::test::test_output_dir()) + "/cli_" + name; }

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string quoted(const std::string& s) { return "'" + s + "'"; }

struct CliRun {
  int code = -1;
  std::string out, err;
};

/// Runs `acute ARGS` through the shell with stdout and stderr sent to files (not a terminal).
CliRun acute(const std::string& args, const std::string& name) {
  const std::string o = out(name + ".stdout"), e = out(name + ".stderr");
  const std::string command = quoted(acute_cli_path()) + " " + args + " >" + quoted(o) + " 2>" + quoted(e) + " </dev/null";
  const int status = std::system(command.c_str());
  CliRun r;
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = slurp(o);
  r.err = slurp(e);
  return r;
}

/// Runs a shell command, returns its stdout.
std::string shell(const std::string& command, int* code = nullptr) {
  std::string text;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return text;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) text.append(buf, n);
  const int status = pclose(pipe);
  if (code) *code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return text;
}

/// Parses an SVG with python3's XML parser; returns "ok BARS LABELS" (the sum of the bars'
/// data-count and the number of vertex labels) or the parser's complaint.
std::string parse_svg(const std::string& path) {
  const std::string script =
      "import sys, xml.etree.ElementTree as ET\n"
      "ns = '{http://www.w3.org/2000/svg}'\n"
      "root = ET.parse(sys.argv[1]).getroot()\n"
      "bars = sum(int(r.get('data-count')) for r in root.iter(ns + 'rect') if r.get('class') == 'bar')\n"
      "labels = len(root.findall('.//' + ns + 'circle'))\n"
      "print('ok', bars, labels)\n";
  // One script per SVG: tests run in parallel, and a shared script file could be read while
  // another test rewrites it.
  const std::string py = path + ".parse.py";
  std::ofstream(py) << script;
  return shell("python3 " + quoted(py) + " " + quoted(path) + " 2>&1");
}

bool has_python() { return std::system("python3 -c 'import xml.etree.ElementTree' >/dev/null 2>&1") == 0; }

std::size_t n_triangles(const std::string& path) { return acute::io::read_mesh(path).n_faces(); }

/// No trace of the terminal progress line: no carriage return, no escape sequence, no counters.
void expect_no_progress(const std::string& err, const std::string& context) {
  EXPECT_EQ(err.find('\r'), std::string::npos) << context << ": " << err;
  EXPECT_EQ(err.find('\033'), std::string::npos) << context << ": " << err;
  EXPECT_EQ(err.find("iteration"), std::string::npos) << context << ": " << err;
  EXPECT_EQ(err.find("bad triangles "), std::string::npos) << context << ": " << err;
}

TEST(RenderHistogram, WellFormedAndBarsCountEveryAngle) {
  if (!has_python()) GTEST_SKIP() << "python3 is needed to parse the SVG";
  // A bad mesh (the bare CDT: small and obtuse angles) and an acute one.
  ASSERT_EQ(acute("mesh " + quoted(mesh_file("A.poly")) + " -o " + quoted(out("A_cdt.off")) + " --method cdt -q", "cdt").code, 0);
  const CliRun a = acute("mesh " + quoted(mesh_file("A.poly")) + " -o " + quoted(out("A_acute.off")) + " --vertices 600 -q", "acute");
  ASSERT_LE(a.code, 1) << a.err;
  for (const std::string mesh : {"A_cdt", "A_acute"})
    for (const std::string bin : {"5", "7", "180"}) {
      const std::string svg = out(mesh + "_hist" + bin + ".svg");
      const CliRun r = acute("render " + quoted(out(mesh + ".off")) + " -o " + quoted(svg) + " --histogram --bin-width " + bin,
                          "hist");
      ASSERT_EQ(r.code, 0) << r.err;
      const std::size_t t = n_triangles(out(mesh + ".off"));
      ASSERT_GT(t, 0u);
      EXPECT_EQ(parse_svg(svg), "ok " + std::to_string(3 * t) + " 0\n") << svg;
      EXPECT_NE(slurp(svg).find("class=\"bound\""), std::string::npos) << "the bounds are drawn";
    }
  // The CDT of A has small and obtuse angles: bars in both bad colours.
  const std::string cdt = slurp(out("A_cdt_hist5.svg"));
  EXPECT_NE(cdt.find("data-kind=\"small\""), std::string::npos);
  EXPECT_NE(cdt.find("data-kind=\"large\""), std::string::npos);
}

TEST(RenderHistogram, RefusesABadBinWidthAndANonSvgOutput) {
  ASSERT_EQ(acute("mesh " + quoted(mesh_file("A.poly")) + " -o " + quoted(out("A_cdt2.off")) + " --method cdt -q", "cdt2").code, 0);
  EXPECT_EQ(acute("render " + quoted(out("A_cdt2.off")) + " -o " + quoted(out("x.svg")) + " --histogram --bin-width 0", "bin0").code, 2);
  const CliRun r = acute("render " + quoted(out("A_cdt2.off")) + " -o " + quoted(out("x.png")) + " --histogram", "png");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("x.png"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("x.png")));
}

TEST(RenderLabels, OneLabelPerVertexOnSmallMeshesAndANoteAboveTheLimit) {
  if (!has_python()) GTEST_SKIP() << "python3 is needed to parse the SVG";
  const std::string small = mesh_file("A.1.off");
  CliRun r = acute("render " + quoted(small) + " -o " + quoted(out("labels.svg")) + " --labels", "labels");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(parse_svg(out("labels.svg")), "ok 0 " + std::to_string(acute::io::read_mesh(small).n_vertices()) + "\n");
  // A 2,000-vertex mesh is over the limit (500).
  const CliRun m = acute("mesh " + quoted(mesh_file("A.poly")) + " -o " + quoted(out("A_big.off")) + " --vertices 2000 -q", "big");
  ASSERT_LE(m.code, 1) << m.err;
  r = acute("render " + quoted(out("A_big.off")) + " -o " + quoted(out("labels_big.svg")) + " --labels", "labels_big");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.err.find("--labels ignored"), std::string::npos) << r.err;
  EXPECT_EQ(parse_svg(out("labels_big.svg")), "ok 0 0\n");
}

TEST(Pictures, RepairWritesDifferentBeforeAndAfterPictures) {
  const std::string prefix = out("grid_pictures");
  for (const auto& p : {"_before.svg", "_after.svg", "_before_histogram.svg", "_after_histogram.svg"}) fs::remove(prefix + p);
  const CliRun r = acute("repair " + quoted(mesh_file("grid.off")) + " -o " + quoted(out("grid_fixed.off")) + " --pictures " +
                          quoted(prefix) + " --json",
                      "repair_pictures");
  ASSERT_LE(r.code, 1) << r.err;
  for (const auto& p : {"_before.svg", "_after.svg", "_before_histogram.svg", "_after_histogram.svg"}) {
    ASSERT_TRUE(fs::exists(prefix + p)) << prefix + p;
    EXPECT_NE(r.out.find(prefix + p), std::string::npos) << "listed in the JSON report";
  }
  EXPECT_NE(slurp(prefix + "_before.svg"), slurp(prefix + "_after.svg"));
  EXPECT_NE(slurp(prefix + "_before_histogram.svg"), slurp(prefix + "_after_histogram.svg"));
  if (has_python()) {
    EXPECT_EQ(parse_svg(prefix + "_before_histogram.svg"), "ok " + std::to_string(3 * n_triangles(mesh_file("grid.off"))) + " 0\n");
    EXPECT_EQ(parse_svg(prefix + "_after_histogram.svg"), "ok " + std::to_string(3 * n_triangles(out("grid_fixed.off"))) + " 0\n");
    EXPECT_EQ(parse_svg(prefix + "_before.svg"), "ok 0 0\n");
  }
}

/// True when the segment p-q is covered by edges of `mesh`: the vertices within 1e-12 of it (by
/// distance to its line, between its ends) form a chain of edges from p to q.
bool segment_is_a_chain_of_edges(const acute::Mesh& mesh, const acute::Point2& p, const acute::Point2& q) {
  std::vector<std::pair<double, acute::VertexHandle>> on;
  const acute::Point2 d = q - p;
  for (auto vh : mesh.vertices()) {
    const acute::Point2 x(mesh.point(vh)[0], mesh.point(vh)[1]);
    const double t = (x - p).dot(d) / d.squaredNorm();
    const double off = std::abs(d.x() * (x - p).y() - d.y() * (x - p).x()) / d.norm();
    if (t > -1e-12 && t < 1 + 1e-12 && off < 1e-12) on.emplace_back(t, vh);
  }
  std::sort(on.begin(), on.end());
  if (on.size() < 2 || on.front().first > 1e-12 || on.back().first < 1 - 1e-12) return false;
  for (std::size_t k = 0; k + 1 < on.size(); ++k)
    if (!mesh.find_halfedge(on[k].second, on[k + 1].second).is_valid()) return false;
  return true;
}

TEST(RepairFeatures, ObjPolylinesInTheInputAreKeptAsEdges) {
  const std::string in = std::string(acute::test::test_data_dir()) + "/tagged_polyline.obj", fixed = out("tagged_fixed.off");
  const CliRun r = acute("repair " + quoted(in) + " -o " + quoted(fixed), "repair_tagged");
  ASSERT_EQ(r.code, 0) << r.err;
  const acute::Mesh m = acute::io::read_mesh(fixed);
  EXPECT_TRUE(segment_is_a_chain_of_edges(m, {1, 1}, {2, 2}));
  EXPECT_TRUE(segment_is_a_chain_of_edges(m, {2, 2}, {1, 2}));
  // The same mesh without the tag: the repair is free to cross the polyline (and does).
  const std::string plain = out("untagged.obj");
  {
    std::ifstream src(in);
    std::ofstream dst(plain);
    for (std::string line; std::getline(src, line);)
      if (line.rfind("l ", 0) != 0) dst << line << "\n";
  }
  const CliRun u = acute("repair " + quoted(plain) + " -o " + quoted(out("untagged_fixed.off")), "repair_untagged");
  ASSERT_EQ(u.code, 0) << u.err;
  const acute::Mesh mu = acute::io::read_mesh(out("untagged_fixed.off"));
  EXPECT_FALSE(segment_is_a_chain_of_edges(mu, {1, 1}, {2, 2}) && segment_is_a_chain_of_edges(mu, {2, 2}, {1, 2}));
}

TEST(RepairFeatures, ATaggedPairThatIsNoEdgeIsRefusedWithItsLine) {
  const std::string bad = out("tagged_not_an_edge.obj");
  {
    std::ofstream f(bad);
    f << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\nl 2 4\n";
  }
  const CliRun r = acute("repair " + quoted(bad) + " -o " + quoted(out("tagged_not_an_edge.off")), "repair_tagged_bad");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find(bad + ":7: polyline edge 2-4 is not an edge of the mesh"), std::string::npos) << r.err;
}

TEST(Pictures, MeshWritesTheCdtAsBefore) {
  const std::string prefix = out("A_pictures");
  const CliRun r = acute("mesh " + quoted(mesh_file("A.poly")) + " -o " + quoted(out("A_pic.off")) + " --vertices 300 --pictures " +
                          quoted(prefix),
                      "mesh_pictures");
  ASSERT_LE(r.code, 1) << r.err;
  ASSERT_TRUE(fs::exists(prefix + "_before.svg"));
  ASSERT_TRUE(fs::exists(prefix + "_after.svg"));
  EXPECT_NE(slurp(prefix + "_before.svg"), slurp(prefix + "_after.svg"));
  // The CDT of A.poly: its 29 points, nothing added.
  EXPECT_NE(slurp(prefix + "_before.svg").find(">29 vertices, "), std::string::npos);
}

TEST(Pictures, MissingFolderFailsBeforeTheRun) {
  const CliRun r = acute("mesh " + quoted(mesh_file("A.poly")) + " -o " + quoted(out("A_nofolder.off")) +
                          " --pictures /nonexistent-folder/x",
                      "nofolder");
  EXPECT_EQ(r.code, 3);
  EXPECT_NE(r.err.find("/nonexistent-folder"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out("A_nofolder.off")));
}

TEST(Bounds, AnInputCornerNoMeshCanMeetIsNamedAndTheBestMeshIsStillWritten) {
  // An 8-degree corner: its triangle's other two angles sum to 172, so one is at least 86.
  const std::string poly = out("wedge8.poly");
  const double c = std::cos(8 * M_PI / 180), s = std::sin(8 * M_PI / 180);
  std::ofstream(poly) << "3 2 0 0\n1 0 0\n2 10 0\n3 " << 10 * c << " " << 10 * s << "\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n";
  const CliRun r = acute("mesh " + quoted(poly) + " -o " + quoted(out("wedge8.off")) + " --vertices 200 --min-angle 35 --max-angle 85 --time-limit 2",
                         "wedge8");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("unsatisfiable bounds at 1 input corner(s)"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the 8-degree sector at (0, 0) leaves its triangle an angle of at least 86 degrees"), std::string::npos) << r.err;
  EXPECT_GT(n_triangles(out("wedge8.off")), 0u);
  // The default bounds hold there (the corner's 8 degrees are forced, its other angles 86).
  const CliRun ok = acute("mesh " + quoted(poly) + " -o " + quoted(out("wedge8_ok.off")) + " --vertices 200", "wedge8_ok");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_EQ(ok.err.find("unsatisfiable"), std::string::npos) << ok.err;
}

TEST(Notes, FeaturesThatDecideTheCountAreToldEarlyUnlessQuiet) {
  // A 1 x 0.001 strip at a 10-vertex request: its features ask for hundreds of vertices.
  const std::string poly = out("strip.poly");
  std::ofstream(poly) << "4 2 0 0\n1 0 0\n2 1 0\n3 1 0.001\n4 0 0.001\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n";
  const CliRun r = acute("mesh " + quoted(poly) + " -o " + quoted(out("strip.off")) + " --vertices 10", "strip");
  EXPECT_EQ(r.code, 0) << r.err;
  const auto note = r.err.find("acute: note: the domain's small features need");
  EXPECT_NE(note, std::string::npos) << r.err;
  EXPECT_LT(note, r.err.find("acute: warning: the mesh has")) << "the note comes before the end: " << r.err;
  // -q: nothing on stderr, the same exit status; --json with -q still reports the figures.
  const CliRun q = acute("mesh " + quoted(poly) + " -o " + quoted(out("strip_q.off")) + " --vertices 10 -q", "strip_q");
  EXPECT_EQ(q.code, 0);
  EXPECT_EQ(q.err, "");
  const CliRun j = acute("mesh " + quoted(poly) + " -o " + quoted(out("strip_j.off")) + " --vertices 10 -q --json", "strip_j");
  EXPECT_EQ(j.code, 0);
  EXPECT_NE(j.out.find("\"n_triangles\""), std::string::npos) << j.out;
  EXPECT_EQ(j.out.find("\"n_triangles\": 0"), std::string::npos) << j.out;
}

TEST(Progress, NeverInStderrThatIsNotATerminal) {
  CliRun r = acute("mesh " + quoted(mesh_file("A.poly")) + " -o " + quoted(out("A_p1.off")) + " --vertices 800", "p_mesh");
  ASSERT_LE(r.code, 1) << r.err;
  expect_no_progress(r.err, "mesh");
  r = acute("repair " + quoted(mesh_file("grid.off")) + " -o " + quoted(out("grid_p.off")), "p_repair");
  ASSERT_LE(r.code, 1) << r.err;
  expect_no_progress(r.err, "repair");
  // -v logs phases one per line, still without the terminal line's carriage returns.
  r = acute("repair " + quoted(mesh_file("grid.off")) + " -o " + quoted(out("grid_pv.off")) + " -v", "p_repair_v");
  ASSERT_LE(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("acute repair"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\033'), std::string::npos) << r.err;
}

TEST(Progress, ShownOnATerminalUnlessQuiet) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) GTEST_SKIP() << "util-linux `script` is needed for a pseudo-terminal";
  // script(1) runs the command on a pseudo-terminal and copies what it shows to our stdout.
  auto on_terminal = [](const std::string& args) {
    const std::string command = quoted(acute_cli_path()) + " " + args;
    return shell("script -qec " + quoted(command) + " /dev/null </dev/null 2>&1");
  };
  // Bounds of [55, 65) are never met on A: the repair runs to the 3 s limit, long enough for the
  // line to be redrawn with counts (a few times a second).
  const std::string shown = on_terminal("mesh " + mesh_file("A.poly") + " -o " + out("A_tty.off") + " --min-angle 55 --max-angle 65 --time-limit 3");
  EXPECT_NE(shown.find("\r\033[Kacute: acute repair"), std::string::npos) << shown;
  EXPECT_TRUE(std::regex_search(shown, std::regex("bad triangles +[0-9]+ +[0-9]+\\.[0-9] s"))) << shown;
  EXPECT_TRUE(std::regex_search(shown, std::regex("acute: [0-9]+ vertices"))) << "the summary line follows";
  const std::string quiet = on_terminal("repair " + mesh_file("grid.off") + " -o " + out("grid_tty_q.off") + " -q");
  EXPECT_EQ(quiet.find("acute repair"), std::string::npos) << quiet;
  EXPECT_EQ(quiet.find('\033'), std::string::npos) << quiet;
}

TEST(Restarts, ANegativeCountIsRefusedAndZeroRunsOnce) {
  fs::remove(out("A_restarts.off"));
  const CliRun bad = acute("mesh " + quoted(mesh_file("A.poly")) + " -o " + quoted(out("A_restarts.off")) + " --restarts -1", "restarts_bad");
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.err.find("--restarts"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(out("A_restarts.off")));
  EXPECT_EQ(acute("mesh " + quoted(mesh_file("A.poly")) + " -o " + quoted(out("A_restarts.off")) + " --restarts 0 -q", "restarts_0").code, 0);
}

}  // namespace
