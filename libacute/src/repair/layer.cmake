acute_add_layer(repair
  SOURCES
    src/repair/angle_bounds.cpp
    src/repair/clusters.cpp
    src/repair/exact_triangulation.cpp
    src/repair/hub_ring.cpp
    src/repair/joint_relaxation.cpp
    src/repair/local_remesh.cpp
    src/repair/non_obtuse.cpp
    src/repair/polar_fan.cpp
    src/repair/polygon_centre.cpp
    src/repair/region.cpp
    src/repair/relocation.cpp
    src/repair/repair.cpp
    src/repair/sector_refan.cpp
  DEPENDS acute_ops acute_delaunay)
# Exact rationals for the non-obtuse mode (Steiner points on slanted segments are not doubles).
find_path(GMPXX_INCLUDE_DIR gmpxx.h REQUIRED)
find_library(GMPXX_LIBRARY gmpxx REQUIRED)
find_library(GMP_LIBRARY gmp REQUIRED)
target_include_directories(acute_repair PRIVATE ${GMPXX_INCLUDE_DIR})
target_link_libraries(acute_repair PRIVATE ${GMPXX_LIBRARY} ${GMP_LIBRARY})
