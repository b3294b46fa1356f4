// PLY (ascii, binary little/big endian). Own reader: OpenMesh's PLY importer stores points as
// floats and silently repairs bad faces, and we need exact doubles and errors naming the face.
#include "io/io_detail.h"

#include <acute/core/errors.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>

namespace acute::io::detail {

namespace {

enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool type_of(const std::string& s, Type& t) {
  static const std::pair<const char*, Type> names[] = {
      {"char", Type::Int8},     {"int8", Type::Int8},     {"uchar", Type::UInt8},    {"uint8", Type::UInt8},
      {"short", Type::Int16},   {"int16", Type::Int16},   {"ushort", Type::UInt16},  {"uint16", Type::UInt16},
      {"int", Type::Int32},     {"int32", Type::Int32},   {"uint", Type::UInt32},    {"uint32", Type::UInt32},
      {"float", Type::Float32}, {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64}};
  for (const auto& [name, type] : names)
    if (s == name) {
      t = type;
      return true;
    }
  return false;
}

std::size_t size_of(Type t) {
  switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 0;
}

struct Property {
  std::string name;
  Type type = Type::Float64;
  bool is_list = false;
  Type count_type = Type::UInt8;
};

struct Element {
  std::string name;
  long long count = 0;
  std::vector<Property> properties;
};

enum class Format { Ascii, BinaryLittle, BinaryBig };

// Reads binary scalars from a byte buffer.
class BinaryCursor {
 public:
  BinaryCursor(const std::string& bytes, std::size_t pos, bool big_endian, const std::string& path)
      : bytes_(bytes), pos_(pos), big_endian_(big_endian), path_(path) {}

  double read(Type t, const std::string& what) {
    const std::size_t n = size_of(t);
    if (pos_ + n > bytes_.size()) throw InvalidInput(path_ + ": file ends inside " + what);
    unsigned char raw[8];
    std::memcpy(raw, bytes_.data() + pos_, n);
    pos_ += n;
    const std::uint16_t one = 1;
    const bool host_little = *reinterpret_cast<const unsigned char*>(&one) == 1;
    if (big_endian_ == host_little) std::reverse(raw, raw + n);
    switch (t) {
      case Type::Int8: { std::int8_t v; std::memcpy(&v, raw, 1); return v; }
      case Type::UInt8: return raw[0];
      case Type::Int16: { std::int16_t v; std::memcpy(&v, raw, 2); return v; }
      case Type::UInt16: { std::uint16_t v; std::memcpy(&v, raw, 2); return v; }
      case Type::Int32: { std::int32_t v; std::memcpy(&v, raw, 4); return v; }
      case Type::UInt32: { std::uint32_t v; std::memcpy(&v, raw, 4); return v; }
      case Type::Float32: { float v; std::memcpy(&v, raw, 4); return v; }
      case Type::Float64: { double v; std::memcpy(&v, raw, 8); return v; }
    }
    return 0;
  }

 private:
  const std::string& bytes_;
  std::size_t pos_;
  bool big_endian_;
  const std::string& path_;
};

}  // namespace

Mesh read_ply(const std::string& path, const WarningSink& warn) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw IoError(path + ": cannot open (" + std::strerror(errno) + ")");
  std::ostringstream buffer;
  buffer << file.rdbuf();
  const std::string bytes = buffer.str();

  // Header (always text).
  Format format = Format::Ascii;
  std::vector<Element> elements;
  std::size_t pos = 0;
  int line = 0;
  bool ended = false;
  while (pos < bytes.size() && !ended) {
    std::size_t end = bytes.find('\n', pos);
    if (end == std::string::npos) end = bytes.size();
    std::string text = bytes.substr(pos, end - pos);
    pos = end + 1;
    ++line;
    if (!text.empty() && text.back() == '\r') text.pop_back();
    const std::string where = path + ":" + std::to_string(line) + ": ";
    std::istringstream words(text);
    std::string key;
    words >> key;
    if (line == 1) {
      if (key != "ply") throw InvalidInput(where + "expected 'ply'");
      continue;
    }
    if (key == "format") {
      std::string f;
      words >> f;
      if (f == "ascii") format = Format::Ascii;
      else if (f == "binary_little_endian") format = Format::BinaryLittle;
      else if (f == "binary_big_endian") format = Format::BinaryBig;
      else throw InvalidInput(where + "unknown PLY format '" + f + "'");
    } else if (key == "element") {
      Element e;
      if (!(words >> e.name >> e.count) || e.count < 0) throw InvalidInput(where + "bad element line");
      elements.push_back(e);
    } else if (key == "property") {
      if (elements.empty()) throw InvalidInput(where + "property before any element");
      Property p;
      std::string t;
      words >> t;
      if (t == "list") {
        std::string ct, it;
        words >> ct >> it >> p.name;
        p.is_list = true;
        if (!type_of(ct, p.count_type) || !type_of(it, p.type)) throw InvalidInput(where + "bad list property types");
      } else {
        words >> p.name;
        if (!type_of(t, p.type)) throw InvalidInput(where + "unknown property type '" + t + "'");
      }
      elements.back().properties.push_back(p);
    } else if (key == "end_header") {
      ended = true;
    } else if (key != "comment" && key != "obj_info" && !key.empty()) {
      throw InvalidInput(where + "unexpected header line '" + text + "'");
    }
  }
  if (!ended) throw InvalidInput(path + ": no end_header");

  Soup s;
  s.path = s.faces_path = path;
  bool warned_z = false;
  std::unique_ptr<LineReader> ascii;
  if (format == Format::Ascii) {
    ascii = std::make_unique<LineReader>(path);
    while (ascii->line() < line && ascii->next()) {
    }  // stops on the end_header line (blank header lines are skipped)
  }
  BinaryCursor binary(bytes, pos, format == Format::BinaryBig, path);

  for (const Element& e : elements) {
    const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
    for (long long i = 0; i < e.count; ++i) {
      const std::string item = e.name + " " + std::to_string(i);
      std::size_t token = 0;
      if (ascii && !ascii->next())
        ascii->fail("expected " + std::to_string(e.count) + " " + e.name + " lines, file ends after " + std::to_string(i));
      auto scalar = [&](Type t, const std::string& what) {
        if (!ascii) return binary.read(t, item);
        if (token >= ascii->size()) ascii->fail(item + ": missing " + what);
        return ascii->to_double(token++, item + " " + what);
      };
      double x = 0, y = 0, z = 0;
      bool got_face = false;
      std::array<int, 3> tri{};
      for (const Property& p : e.properties) {
        if (!p.is_list) {
          const double v = scalar(p.type, p.name);
          if (is_vertex && p.name == "x") x = v;
          if (is_vertex && p.name == "y") y = v;
          if (is_vertex && p.name == "z") z = v;
          continue;
        }
        const double count = scalar(p.count_type, p.name + " count");
        const bool indices = is_face && (p.name == "vertex_indices" || p.name == "vertex_index");
        if (indices && count != 3) {
          const std::string message = "face " + std::to_string(i) + " has " + format_double(count) +
                                      " vertices, only triangles are supported";
          if (ascii) ascii->fail(message);
          throw InvalidInput(path + ": " + message);
        }
        for (long long k = 0; k < static_cast<long long>(count); ++k) {
          const double v = scalar(p.type, p.name);
          if (indices) {
            const long long nv = static_cast<long long>(s.points.size());
            if (v != std::floor(v) || v < 0 || v >= double(nv)) {
              const std::string message = "face " + std::to_string(i) + " uses vertex " + format_double(v) +
                                          ", out of range (" + std::to_string(nv) + " vertices)";
              if (ascii) ascii->fail(message);
              throw InvalidInput(path + ": " + message);
            }
            tri[static_cast<std::size_t>(k)] = static_cast<int>(v);
          }
        }
        got_face = got_face || indices;
      }
      if (is_vertex) {
        s.points.emplace_back(x, y);
        if (ascii) s.point_lines.push_back(ascii->line());
        if (z != 0 && !warned_z && warn) {
          warn(path + ": nonzero z coordinates are dropped (the mesh is projected onto the xy-plane)");
          warned_z = true;
        }
      }
      if (is_face) {
        if (!got_face) throw InvalidInput(path + ": face element without a vertex_indices list");
        s.faces.push_back(tri);
        s.face_lines.push_back(ascii ? ascii->line() : 0);
      }
    }
  }
  if (!ascii) s.face_lines.clear();  // no line numbers in binary files
  return build_mesh(std::move(s), warn);
}

}  // namespace acute::io::detail
