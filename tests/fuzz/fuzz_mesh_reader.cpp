// libFuzzer target: the mesh readers (.off, .obj, .ply chosen by sniffing the content), then
// check_mesh at Topology level on what was read, and read_domain (domain_of_mesh) on the same file.
#include "fuzz_reader_common.h"

#include <cstring>

namespace {

std::string extension_of(const std::uint8_t* data, std::size_t size) {
  const std::string head(reinterpret_cast<const char*>(data), std::min<std::size_t>(size, 16));
  if (head.rfind("ply", 0) == 0) return ".ply";
  if (head.find("OFF") != std::string::npos) return ".off";
  return ".obj";
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace acute_fuzz;
  const std::string ext = extension_of(data, size);
  const std::string path = write_input(data, size, ext);
  Mesh mesh;
  if (!run_guarded("read_mesh", [&] { mesh = acute::io::read_mesh(path, [](const std::string&) {}); })) return 0;
  // read_mesh rejects non-manifold input and non-triangles: what it returns is a valid topology.
  // Vertices at the same position are not rejected by read_mesh (its contract does not say so):
  // they are left to domain_of_mesh / validate_domain. Everything else check_mesh finds counts.
  const acute::CheckReport rep = acute::check_mesh(mesh, acute::CheckLevel::Topology, 100000);
  for (const std::string& v : rep.violations)
    if (v.find("same position") == std::string::npos) {
      fail("read_mesh" + ext + ": returned an invalid mesh: " + v + " (" + rep.summary() + ")");
      return 0;
    }
  Domain d;
  if (run_guarded("read_domain", [&] { d = acute::io::read_domain(path, [](const std::string&) {}); }))
    check_read_domain(d, "read_domain");
  return 0;
}
