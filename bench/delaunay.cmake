# Delaunay / CDT benchmarks. CGAL (Debian libcgal-dev) is optional and used only here: when found,
# cdt_bench_cgal runs the same inputs through acute and CGAL in the same run.
add_executable(cdt_bench cdt_bench.cpp)
target_link_libraries(cdt_bench PRIVATE acute_delaunay benchmark::benchmark)
target_include_directories(cdt_bench PRIVATE ${CMAKE_SOURCE_DIR}/libacute/src)
acute_set_warnings(cdt_bench)

find_package(CGAL QUIET)
if(CGAL_FOUND)
  add_executable(cdt_bench_cgal cdt_bench.cpp)
  target_link_libraries(cdt_bench_cgal PRIVATE acute_delaunay benchmark::benchmark CGAL::CGAL)
  target_include_directories(cdt_bench_cgal PRIVATE ${CMAKE_SOURCE_DIR}/libacute/src)
  target_compile_definitions(cdt_bench_cgal PRIVATE ACUTE_BENCH_CGAL CGAL_DISABLE_ROUNDING_MATH_CHECK)
  message(STATUS "CGAL ${CGAL_VERSION} found: building cdt_bench_cgal")
else()
  message(STATUS "CGAL not found: cdt_bench_cgal skipped")
endif()
