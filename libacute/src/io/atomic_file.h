// Layer: io (private). Writes a file atomically: the text goes to a temporary file in the same
// directory, which replaces the target by std::rename only when commit() succeeds.
#pragma once

#include <fstream>
#include <string>

namespace acute::io::detail {

class AtomicFile {
 public:
  /// Opens a fresh temporary file next to `path`. \throws IoError
  explicit AtomicFile(std::string path);
  /// Removes the temporary file unless commit() succeeded.
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  std::ostream& stream() { return out_; }
  /// Flushes, closes and renames onto the target. \throws IoError
  void commit();

  const std::string& path() const { return path_; }
  const std::string& temp_path() const { return temp_path_; }

 private:
  std::string path_;
  std::string temp_path_;
  std::ofstream out_;
  bool committed_ = false;
};

}  // namespace acute::io::detail
