acute_add_test(repair_tests
  SOURCES
    repair/angle_bounds_test.cpp
    repair/exact_triangulation_test.cpp
    repair/hub_ring_test.cpp
    repair/joint_relaxation_test.cpp
    repair/local_remesh_test.cpp
    repair/non_obtuse_test.cpp
    repair/polar_fan_test.cpp
    repair/region_test.cpp
    repair/relocation_test.cpp
    repair/repair_test.cpp
    repair/sector_refan_test.cpp
  LIBS acute_pipeline acute_io)
target_include_directories(repair_tests PRIVATE ${GMPXX_INCLUDE_DIR})
target_link_libraries(repair_tests PRIVATE ${GMPXX_LIBRARY} ${GMP_LIBRARY})
