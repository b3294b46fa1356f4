acute_add_test(pipeline_tests
  SOURCES
    pipeline/repair_mesh_test.cpp
    pipeline/cgshop_solution_test.cpp
    pipeline/random_polygons_test.cpp
    pipeline/segment_rounding_test.cpp
    pipeline/resource_bounds_test.cpp
    pipeline/convex_hull_test.cpp
    pipeline/mesh_domain_test.cpp
    pipeline/hub_patch_test.cpp
  LIBS acute_pipeline acute_io nlohmann_json::nlohmann_json)
