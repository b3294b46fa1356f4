acute_add_layer(cvt
  SOURCES
    src/cvt/size_field.cpp
    src/cvt/lattice.cpp
    src/cvt/narrow_sectors.cpp
    src/cvt/sampling.cpp
    src/cvt/settled_cells.cpp
    src/cvt/site_delaunay.cpp
    src/cvt/voronoi.cpp
    src/cvt/optimize.cpp
  DEPENDS acute_delaunay acute_ops)
