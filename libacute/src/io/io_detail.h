// Layer: io (private). Shared pieces of the readers and writers.
#pragma once

#include <acute/core/domain.h>
#include <acute/io/io.h>
#include <acute/mesh/mesh.h>

#include <array>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace acute::io::detail {

/// Reads a text file line by line: strips `#` comments, '\r' and blank lines, splits on
/// whitespace, and builds "path:line: ..." messages.
class LineReader {
 public:
  /// \throws IoError when the file cannot be read.
  explicit LineReader(std::string path);

  /// The next line with at least one token; false at the end of the file.
  bool next();
  const std::vector<std::string_view>& tokens() const { return tokens_; }
  std::size_t size() const { return tokens_.size(); }
  std::string_view operator[](std::size_t i) const { return tokens_[i]; }
  int line() const { return line_; }
  const std::string& path() const { return path_; }

  /// Throws InvalidInput "path:line: message".
  [[noreturn]] void fail(const std::string& message) const;
  /// Throws when fewer than n tokens are on the line; `what` names the line's role.
  void require(std::size_t n, const char* what) const;
  /// A finite double (no range check). \throws InvalidInput naming `what`.
  double to_double(std::size_t i, const std::string& what) const;
  /// An integer. \throws InvalidInput naming `what`.
  long long to_int(std::size_t i, const std::string& what) const;
  /// "path:line: " for the current line.
  std::string where() const;

 private:
  std::string path_;
  std::string text_;
  std::size_t pos_ = 0;
  int line_ = 0;
  std::vector<std::string_view> tokens_;
};

/// Parses a whole token as a double (C locale; accepts a leading '+'). False when malformed.
bool parse_double(std::string_view token, double& value);
/// Parses a whole token as an integer. False when malformed or out of range.
bool parse_int(std::string_view token, long long& value);
/// 17 significant digits (round-trips every double), C locale.
std::string format_double(double x);

/// Text for a large file built in memory and handed to the stream in large blocks: a million
/// triangles through `ostream <<` cost 0.5 s, most of it in the stream's per-call overhead.
class TextBlock {
 public:
  explicit TextBlock(std::ostream& out) : out_(out) { text_.reserve(kBlock + 256); }
  ~TextBlock() { flush(); }
  TextBlock(const TextBlock&) = delete;
  TextBlock& operator=(const TextBlock&) = delete;

  TextBlock& operator<<(char c) {
    text_.push_back(c);
    return spill();
  }
  TextBlock& operator<<(std::string_view s) {
    text_.append(s);
    return spill();
  }
  /// An integer in decimal.
  TextBlock& operator<<(long long v);
  TextBlock& operator<<(int v) { return *this << static_cast<long long>(v); }
  TextBlock& operator<<(std::size_t v) { return *this << static_cast<long long>(v); }
  /// As format_double: 17 significant digits.
  TextBlock& operator<<(double v);
  void flush();

 private:
  static constexpr std::size_t kBlock = std::size_t{1} << 20;
  TextBlock& spill() {
    if (text_.size() >= kBlock) flush();
    return *this;
  }
  std::ostream& out_;
  std::string text_;
};

/// Lower-case extension with the dot (".poly"), or "".
std::string extension_of(const std::string& path);
/// File name without directory and last extension.
std::string stem_of(const std::string& path);
/// `path` with its last extension replaced by `ext` (".node").
std::string with_extension(const std::string& path, const std::string& ext);

/// Where the elements of a domain were read from, so that messages can name file and line.
struct DomainSource {
  std::string points_file;
  std::vector<int> point_lines;
  std::string segments_file;
  std::vector<int> segment_lines;
  std::vector<int> hole_lines;
  int index_base = 0;  ///< numbering shown in messages (1 for 1-based files)
};

/// validate_domain with file:line prefixes and the file's numbering.
void validate_domain(const Domain& domain, const DomainSource* source, bool allow_crossings = false);

/// Drops repeated segments (same two points, either order), keeping the first; warns once.
void remove_duplicate_segments(Domain& domain, DomainSource* source, const WarningSink& warn);

/// The vertices of a Triangle .node file (also the vertex section of a .poly file).
struct NodeList {
  std::vector<Point2> points;
  std::vector<int> markers;
  std::vector<int> lines;
  int base = 0;  ///< 0 or 1, from the first vertex index
};

/// Reads `count` vertex lines (after the header) with the given layout.
NodeList read_node_lines(LineReader& in, long long count, long long n_attributes, long long n_markers,
                         const WarningSink& warn);
/// Reads a whole .node file (header + vertices).
NodeList read_node_file(const std::string& path, const WarningSink& warn);

/// A triangle soup read from a file, before it becomes a Mesh.
struct Soup {
  std::string path;              ///< vertex file, for messages
  std::string faces_path;        ///< face file (differs for .node/.ele)
  std::vector<Point2> points;
  std::vector<int> markers;      ///< empty or one per point
  std::vector<int> point_lines;  ///< empty or one per point
  std::vector<std::array<int, 3>> faces;  ///< 0-based
  std::vector<int> face_lines;   ///< one per face
  int base = 0;                  ///< numbering shown in messages
};

/// Builds the mesh: checks coordinates, orientation (all-clockwise input is reversed with a
/// warning, mixed orientation is an error), and manifoldness, naming the first bad element.
Mesh build_mesh(Soup soup, const WarningSink& warn);

/// PLY via OpenMesh (separate file: OpenMesh IO must be included before the mesh type).
Mesh read_ply(const std::string& path, const WarningSink& warn);

}  // namespace acute::io::detail
