acute_add_layer(io
  SOURCES
    src/io/atomic_file.cpp
    src/io/text_reader.cpp
    src/io/read_poly.cpp
    src/io/read_cgshop.cpp
    src/io/domain_io.cpp
    src/io/mesh_io.cpp
    src/io/read_tagged_edges.cpp
    src/io/read_ply.cpp
    src/io/svg_canvas.cpp
    src/io/write_svg.cpp
    src/io/write_histogram_svg.cpp
    src/io/write_vtk.cpp
    src/io/write_msh.cpp
    src/io/write_ply.cpp
    src/io/write_dual.cpp
    src/io/write_cgshop_solution.cpp
  DEPENDS acute_mesh)
target_link_libraries(acute_io PRIVATE nlohmann_json::nlohmann_json)
