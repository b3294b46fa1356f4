acute_add_test(io_tests
  SOURCES
    io/read_domain_test.cpp
    io/validate_test.cpp
    io/read_mesh_test.cpp
    io/write_test.cpp
    io/corpus_test.cpp
  LIBS acute_io)
acute_add_test(io_formats_tests
  SOURCES
    io/formats_test.cpp
  LIBS acute_io)
