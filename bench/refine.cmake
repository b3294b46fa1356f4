# Delaunay refinement benchmarks: refinement of the unit square to about 1M triangles. When CGAL
# (Debian libcgal-dev) is found, refine_bench also runs CGAL's Delaunay_mesher_2 in the same run
# with B = 0.125 (20.7 degrees) and a size bound calibrated to the same vertex count.
add_executable(refine_bench refine_bench.cpp)
target_link_libraries(refine_bench PRIVATE acute_refine acute_pipeline benchmark::benchmark)
acute_set_warnings(refine_bench)

find_package(CGAL QUIET)
if(CGAL_FOUND)
  target_link_libraries(refine_bench PRIVATE CGAL::CGAL)
  target_compile_definitions(refine_bench PRIVATE ACUTE_BENCH_CGAL CGAL_DISABLE_ROUNDING_MATH_CHECK)
endif()
