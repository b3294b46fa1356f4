acute_add_layer(ops
  SOURCES
    src/ops/flip.cpp
    src/ops/delaunay_flips.cpp
    src/ops/insert.cpp
    src/ops/remove.cpp
    src/ops/relocate.cpp
  DEPENDS acute_mesh)
