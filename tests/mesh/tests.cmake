acute_add_test(mesh_tests
  SOURCES
    mesh/mesh_test.cpp
    mesh/check_test.cpp
    mesh/quality_test.cpp
  LIBS acute_mesh)
