#include "commands/pictures.h"

#include <acute/core/errors.h>

#include <filesystem>

namespace acute::cli {

std::vector<std::string> picture_paths(const std::string& prefix) {
  return {prefix + "_before.svg", prefix + "_after.svg", prefix + "_before_histogram.svg", prefix + "_after_histogram.svg"};
}

void check_picture_prefix(const std::string& prefix, const std::vector<std::string>& outputs) {
  if (prefix.empty()) throw InvalidInput("--pictures needs a prefix, e.g. --pictures out/A");
  const std::filesystem::path folder = std::filesystem::path(prefix).parent_path();
  std::error_code ec;
  if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
    throw IoError(prefix + ": --pictures folder '" + folder.string() + "' does not exist");
  for (const auto& picture : picture_paths(prefix))
    for (const auto& out : outputs)
      if (picture == out) throw InvalidInput(out + ": is also a --pictures file; choose another prefix");
}

std::vector<std::string> write_pictures(const std::string& prefix, const Mesh& before, const Mesh& after,
                                        const io::WriteOptions& options) {
  const auto paths = picture_paths(prefix);
  io::WriteOptions o = options;
  o.title = "before: " + options.title;
  io::write_svg(before, paths[0], o);
  io::write_angle_histogram_svg(before, paths[2], o);
  o.title = "after: " + options.title;
  io::write_svg(after, paths[1], o);
  io::write_angle_histogram_svg(after, paths[3], o);
  return paths;
}

void mark_boundary_constrained(Mesh& mesh) {
  for (auto eh : mesh.edges())
    if (mesh.is_boundary(eh) && !is_constrained(mesh, eh)) mesh.data(eh).segment = 0;
}

}  // namespace acute::cli
