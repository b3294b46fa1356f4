// Helpers for the io tests.
#pragma once

#include <acute/core/errors.h>

#include "support/paths.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace acute::test {

inline std::string data(const std::string& name) { return std::string(acute::test::test_data_dir()) + "/" + name; }
inline std::string bad(const std::string& name) { return data("bad/" + name); }
inline std::string output(const std::string& name) { return std::string(acute::test::test_output_dir()) + "/" + name; }
inline std::string shared_path(const std::string& sub) { return std::string(acute::test::shared_dir()) + "/" + sub; }

/// Files with one of the extensions in a folder (sorted), or empty when the folder is absent.
inline std::vector<std::string> files_in(const std::string& dir, std::initializer_list<const char*> exts) {
  std::vector<std::string> out;
  if (!std::filesystem::is_directory(dir)) return out;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    for (const char* ext : exts) {
      const std::string e(ext);
      if (name.size() > e.size() && name.compare(name.size() - e.size(), e.size(), e) == 0) out.push_back(entry.path().string());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// Runs f, expects exception E whose one-line message contains every piece.
template <class E, class F>
void expect_error(F&& f, std::initializer_list<std::string> pieces, const std::string& context) {
  try {
    f();
    ADD_FAILURE() << context << ": no exception";
  } catch (const E& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find('\n'), std::string::npos) << context << ": multi-line message: " << message;
    for (const auto& piece : pieces)
      EXPECT_NE(message.find(piece), std::string::npos) << context << ": message '" << message << "' lacks '" << piece << "'";
  } catch (const std::exception& e) {
    ADD_FAILURE() << context << ": wrong exception type: " << e.what();
  }
}

}  // namespace acute::test
