// libFuzzer target: the Triangle .poly reader (then validate_domain and, when small, build_cdt).
#include "fuzz_reader_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace acute_fuzz;
  const std::string path = write_input(data, size, ".poly");
  Domain d;
  if (run_guarded("read_poly", [&] { d = acute::io::read_poly(path, [](const std::string&) {}); }))
    check_read_domain(d, "read_poly");
  return 0;
}
