// Meshes an L-shaped polygon given as a coarse OpenMesh TriMesh with float points, writes the
// acute mesh with OpenMesh, and its circumcentric dual with libacute.
//   acute_example [OUT.off] [DUAL.vtu]
#include <OpenMesh/Core/IO/MeshIO.hh>  // before any OpenMesh mesh type
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include <acute/core/errors.h>
#include <acute/io/io.h>
#include <acute/mesh/dual.h>
#include <acute/mesh/mesh.h>
#include <acute/mesher.h>

#include <iostream>
#include <string>
#include <vector>

using UserMesh = OpenMesh::TriMesh_ArrayKernelT<>;  // the application's own mesh type (float points)

int main(int argc, char** argv) {
  const std::string out_path = argc > 1 ? argv[1] : "l_shape_acute.off";
  const std::string dual_path = argc > 2 ? argv[2] : "";
  try {
    // The application's coarse triangulation of an L-shaped region (6 corners, 4 triangles).
    UserMesh coarse;
    std::vector<UserMesh::VertexHandle> v;
    const float corners[][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    for (const auto& c : corners) v.push_back(coarse.add_vertex(UserMesh::Point(c[0], c[1], 0.f)));
    coarse.add_face(v[0], v[1], v[2]);
    coarse.add_face(v[0], v[2], v[3]);
    coarse.add_face(v[0], v[3], v[4]);
    coarse.add_face(v[0], v[4], v[5]);

    // Its boundary becomes the domain; the mesher keeps the corners and the boundary exactly.
    const acute::Mesh input = acute::from_openmesh(coarse);
    const acute::Domain domain = acute::io::domain_of_mesh(input);
    acute::MeshOptions options;  // method "acute": every angle in [30°, 90°)
    options.size = 0.25;         // target edge length
    const acute::MeshResult result = acute::generate_mesh(domain, options);

    const acute::DualCheck check = acute::check_well_centered(result.mesh);
    std::cout << "acute mesh: " << result.mesh.n_vertices() << " vertices, " << result.mesh.n_faces()
              << " triangles, bounds " << (result.status == acute::MeshStatus::Ok ? "met" : "NOT met")
              << ", " << (check.well_centered() ? "well-centred" : "not well-centred") << '\n';

    UserMesh fine;
    acute::to_openmesh(result.mesh, fine);
    if (!OpenMesh::IO::write_mesh(fine, out_path, OpenMesh::IO::Options::Default, 17)) {
      std::cerr << "acute_example: cannot write " << out_path << '\n';
      return 3;
    }
    std::cout << "wrote " << out_path << '\n';
    if (!dual_path.empty()) {
      acute::io::write_dual(acute::circumcentric_dual(result.mesh), dual_path, &result.mesh);
      std::cout << "wrote " << dual_path << '\n';
    }
    return result.status == acute::MeshStatus::Ok ? 0 : 1;
  } catch (const acute::InvalidInput& e) {
    std::cerr << "acute_example: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "acute_example: " << e.what() << '\n';
    return 3;
  }
}
