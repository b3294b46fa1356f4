acute_add_test(ops_tests
  SOURCES
    ops/flip_test.cpp
    ops/insert_test.cpp
    ops/remove_test.cpp
    ops/relocate_test.cpp
  LIBS acute_ops)
