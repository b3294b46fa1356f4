# The `acute` program as a user runs it: each test starts the built binary and checks its files,
# stdout and stderr.
if(TARGET acute_cli)
  acute_add_test(tools_tests
    SOURCES
      tools/cli_test.cpp
    LIBS acute_io)
  add_dependencies(tools_tests acute_cli)
  target_compile_definitions(tools_tests PRIVATE ACUTE_CLI="$<TARGET_FILE:acute_cli>")
endif()
