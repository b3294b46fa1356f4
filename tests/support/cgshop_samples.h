// The small CG:SHOP 2025 instances the tests solve (one of each class, 10 points), from the shared
// corpus (acute::test::shared_dir()). Empty when the corpus is absent: the caller skips.
#pragma once

#include <acute/io/io.h>

#include "support/paths.h"

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace acute::test {

/// (uid, path) of each small instance present in the shared corpus.
inline std::vector<std::pair<std::string, std::filesystem::path>> small_cgshop_instances() {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(acute::test::shared_dir()) / "domains" / "cgshop2025" / "instances";
  std::vector<std::pair<std::string, fs::path>> out;
  for (const char* uid : {"ortho_10_d2723dcc", "point-set_10_13860916", "simple-polygon_10_297edd18",
                          "simple-polygon-exterior_10_310dc6c7", "simple-polygon-exterior-20_10_8c4306da"}) {
    const fs::path path = dir / (std::string(uid) + ".instance.json");
    if (fs::exists(path)) out.emplace_back(uid, path);
  }
  return out;
}

}  // namespace acute::test
