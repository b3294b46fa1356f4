acute_add_layer(predicates
  SOURCES
    src/predicates/orient2d.cpp
    src/predicates/incircle.cpp
    src/predicates/segment.cpp
  DEPENDS Eigen3::Eigen)
acute_set_exact_fp(acute_predicates)
