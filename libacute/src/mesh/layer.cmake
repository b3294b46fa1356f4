acute_add_layer(mesh
  SOURCES
    src/mesh/mesh.cpp
    src/mesh/quality.cpp
    src/mesh/check.cpp
    src/mesh/segments.cpp
    src/mesh/geometry.cpp
    src/mesh/dual.cpp
    src/mesh/sectors.cpp
    src/mesh/boundary.cpp
  DEPENDS acute_predicates acute_openmesh)
