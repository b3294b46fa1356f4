acute_add_test(delaunay_tests
  SOURCES
    delaunay/cdt_test.cpp
    delaunay/split_crossings_test.cpp
  LIBS acute_delaunay acute_io)
