acute_add_test(cvt_tests
  SOURCES
    cvt/size_field_test.cpp
    cvt/voronoi_test.cpp
    cvt/cvt_test.cpp
    cvt/regression_test.cpp
    cvt/site_delaunay_test.cpp
  LIBS acute_cvt acute_io)
