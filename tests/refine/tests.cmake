acute_add_test(refine_tests
  SOURCES
    refine/refine_test.cpp
  LIBS acute_refine acute_pipeline acute_io)
