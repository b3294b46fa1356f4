// libFuzzer target: the CG:SHOP 2025 instance JSON reader (then validate_domain and, when small,
// build_cdt).
#include "fuzz_reader_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace acute_fuzz;
  const std::string path = write_input(data, size, ".json");
  Domain d;
  if (run_guarded("read_cgshop", [&] { d = acute::io::read_cgshop(path, [](const std::string&) {}); }))
    check_read_domain(d, "read_cgshop");
  return 0;
}
