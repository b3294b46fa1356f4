# Throughput of the filtered exact predicates against the naive double determinants.
add_executable(predicates_bench predicates_bench.cpp)
target_link_libraries(predicates_bench PRIVATE acute::predicates benchmark::benchmark)
acute_set_warnings(predicates_bench)
