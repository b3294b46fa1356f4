acute_add_layer(delaunay
  SOURCES
    src/delaunay/triangulation.cpp
    src/delaunay/cdt.cpp
  DEPENDS acute_mesh)
