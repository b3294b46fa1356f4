#include "io/io_detail.h"

#include <acute/core/errors.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <sstream>

namespace acute::io::detail {

LineReader::LineReader(std::string path) : path_(std::move(path)) {
  std::ifstream in(path_, std::ios::in | std::ios::binary);
  if (!in) throw IoError(path_ + ": cannot open (" + std::strerror(errno) + ")");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw IoError(path_ + ": read error");
  text_ = buffer.str();
}

bool LineReader::next() {
  tokens_.clear();
  while (pos_ < text_.size()) {
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string::npos) end = text_.size();
    std::string_view row(text_.data() + pos_, end - pos_);
    pos_ = end + 1;
    ++line_;
    const auto hash = row.find('#');
    if (hash != std::string_view::npos) row = row.substr(0, hash);
    std::size_t i = 0;
    while (i < row.size()) {
      while (i < row.size() && std::isspace(static_cast<unsigned char>(row[i]))) ++i;
      std::size_t j = i;
      while (j < row.size() && !std::isspace(static_cast<unsigned char>(row[j]))) ++j;
      if (j > i) tokens_.push_back(row.substr(i, j - i));
      i = j;
    }
    if (!tokens_.empty()) return true;
  }
  ++line_;  // messages about a missing line point past the last one
  return false;
}

std::string LineReader::where() const { return path_ + ":" + std::to_string(line_) + ": "; }

void LineReader::fail(const std::string& message) const { throw InvalidInput(where() + message); }

void LineReader::require(std::size_t n, const char* what) const {
  if (tokens_.size() < n)
    fail(std::string(what) + ": expected " + std::to_string(n) + " fields, found " + std::to_string(tokens_.size()));
}

double LineReader::to_double(std::size_t i, const std::string& what) const {
  double v = 0;
  const std::string tok(tokens_.at(i));
  if (!parse_double(tokens_[i], v)) fail(what + ": '" + tok + "' is not a number");
  if (!std::isfinite(v)) fail(what + " is not finite ('" + tok + "')");
  return v;
}

long long LineReader::to_int(std::size_t i, const std::string& what) const {
  long long v = 0;
  if (!parse_int(tokens_.at(i), v)) fail(what + ": '" + std::string(tokens_[i]) + "' is not an integer");
  return v;
}

bool parse_double(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char* first = token.data();
  const char* last = first + token.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range) {
    // Keep the magnitude class so that the range check rejects it: overflow becomes inf,
    // underflow the smallest subnormal (never a silent 0).
    const double v = std::strtod(std::string(token).c_str(), nullptr);
    if (std::isinf(v)) value = v;
    else value = std::copysign(v == 0 ? std::numeric_limits<double>::denorm_min() : v, token.front() == '-' ? -1.0 : 1.0);
    return ptr == last;
  }
  return ec == std::errc() && ptr == last;
}

bool parse_int(std::string_view token, long long& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char* last = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), last, value);
  return ec == std::errc() && ptr == last;
}

std::string format_double(double x) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general,
                                       std::numeric_limits<double>::max_digits10);
  (void)ec;
  return std::string(buf, ptr);
}

TextBlock& TextBlock::operator<<(long long v) {
  char buf[24];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v);
  (void)ec;
  text_.append(buf, ptr);
  return spill();
}

TextBlock& TextBlock::operator<<(double v) {
  char buf[64];
  const auto [ptr, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, std::numeric_limits<double>::max_digits10);
  (void)ec;
  text_.append(buf, ptr);
  return spill();
}

void TextBlock::flush() {
  out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
  text_.clear();
}

std::string extension_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

std::string stem_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const auto dot = name.find_last_of('.');
  if (dot != std::string::npos && dot > 0) name.resize(dot);
  return name;
}

std::string with_extension(const std::string& path, const std::string& ext) {
  const auto slash = path.find_last_of('/');
  const auto dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path + ext;
  return path.substr(0, dot) + ext;
}

}  // namespace acute::io::detail
