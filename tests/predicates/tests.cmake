acute_add_test(predicates_tests
  SOURCES
    predicates/oracle_test.cpp
    predicates/orient2d_test.cpp
    predicates/incircle_test.cpp
    predicates/segment_test.cpp
  LIBS acute::predicates)
