acute_add_test(predicates_tests
  SOURCES
    predicates/oracle_test.cpp
    predicates/expansion_test.cpp
    predicates/orient2d_test.cpp
    predicates/incircle_test.cpp
    predicates/segment_test.cpp
  LIBS acute::predicates)
# expansion_test.cpp compiles the private expansion arithmetic: it needs the same FP guarantees.
acute_set_exact_fp(predicates_tests)
