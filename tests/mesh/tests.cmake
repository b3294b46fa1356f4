acute_add_test(mesh_tests
  SOURCES
    mesh/mesh_test.cpp
    mesh/check_test.cpp
    mesh/quality_test.cpp
    mesh/segments_test.cpp
    mesh/modular_search_test.cpp
    mesh/sectors_test.cpp
    mesh/geometry_test.cpp
  LIBS acute_mesh)
acute_add_test(mesh_dual_tests
  SOURCES
    mesh/dual_test.cpp
  LIBS acute_mesh)
