# CVT benchmarks: time per iteration at 10k / 100k / 1M vertices and total time to a converged CVT.
add_executable(cvt_bench cvt_bench.cpp)
target_link_libraries(cvt_bench PRIVATE acute_cvt benchmark::benchmark)
acute_set_warnings(cvt_bench)
