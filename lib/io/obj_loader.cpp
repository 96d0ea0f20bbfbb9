#include "io/obj_loader.h"

#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "io/file_error.h"
#include "io/read_file.h"

namespace rtk {

namespace {

constexpr bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// A byte no text file holds: the C0 controls other than tab and CR (LF ends lines) and DEL.
constexpr bool is_control(unsigned char c) {
  return (c < 0x20 && c != '\t' && c != '\r') || c == 0x7f;
}

constexpr bool is_letter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// One pass over the text, one line at a time. The parser holds the current line as [p_, end_)
// and reads tokens from its front; every failure names the line.
class ObjParser {
 public:
  ObjParser(std::string_view text, std::string_view name) : text_(text), name_(name) {}

  TriangleMesh parse() {
    const char* pos = text_.data();
    const char* const file_end = text_.data() + text_.size();
    // A UTF-8 byte-order mark is not content.
    if (text_.starts_with("\xEF\xBB\xBF")) pos += 3;
    while (pos < file_end) {
      const void* newline = std::memchr(pos, '\n', size_t(file_end - pos));
      const char* line_end = newline ? static_cast<const char*>(newline) : file_end;
      ++line_;
      if (size_t(line_end - pos) > kMaxObjLineBytes)
        fail("line longer than " + std::to_string(kMaxObjLineBytes) + " bytes");
      check_text(pos, line_end);
      p_ = pos;
      end_ = line_end;
      parse_line();
      pos = line_end + 1;
    }
    return std::move(mesh_);
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw FileError(std::string(name_), line_, message);
  }

  // Binary junk is refused wherever it is, comments included: a file with a NUL byte is not
  // an OBJ file that happens to contain one. The loop is branch-free so that it vectorizes.
  void check_text(const char* begin, const char* end) const {
    unsigned bad = 0;
    for (const char* q = begin; q != end; ++q) bad |= is_control(static_cast<unsigned char>(*q));
    if (!bad) return;
    const char* q = begin;
    while (!is_control(static_cast<unsigned char>(*q))) ++q;
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(*q));
    fail(std::string("control byte ") + hex + " at column " + std::to_string(q - begin + 1) +
         " (binary data is not OBJ text)");
  }

  void skip_space() {
    while (p_ != end_ && is_space(*p_)) ++p_;
  }
  // Whether the rest of the line holds nothing but blanks and perhaps a comment.
  bool at_line_end() {
    skip_space();
    return p_ == end_ || *p_ == '#';
  }
  bool at_delimiter(const char* q) const { return q == end_ || is_space(*q) || *q == '#'; }

  // The token that starts at q, for messages (shortened: a message should fit on a line).
  std::string token_at(const char* q) const {
    const char* e = q;
    while (!at_delimiter(e)) ++e;
    std::string token(q, size_t(e - q));
    if (token.size() > 40) token = token.substr(0, 37) + "...";
    return token;
  }

  void parse_line() {
    skip_space();
    if (p_ == end_ || *p_ == '#') return;
    const char* keyword = p_;
    while (!at_delimiter(p_)) ++p_;
    const std::string_view word(keyword, size_t(p_ - keyword));
    if (word == "v") {
      parse_vertex();
    } else if (word == "f") {
      parse_face();
    } else if (word == "vt") {
      ++texcoords_;
    } else if (word == "vn") {
      ++normals_;
    } else if (!is_letter(word.front())) {
      fail("expected a statement such as 'v' or 'f', found '" + token_at(keyword) + "'");
    }
    // Any other statement (o, g, s, usemtl, ...) does not change the geometry.
  }

  // A coordinate: std::from_chars reads exactly the token or the token is wrong.
  float read_coordinate() {
    const char* start = p_;
    const char* q = p_;
    // from_chars refuses a leading '+', which some exporters write; accept it before a digit
    // or a point only, so that "+-1" and "+ 1" stay errors.
    if (*q == '+' && q + 1 != end_ && (std::isdigit(static_cast<unsigned char>(q[1])) || q[1] == '.')) ++q;
    float value = 0.0f;
    auto [ptr, ec] = std::from_chars(q, end_, value);
    if (ec == std::errc::result_out_of_range) {
      // Beyond float's range: read as a double, so that a value below the smallest subnormal
      // rounds to zero as it should, and one beyond FLT_MAX becomes infinite (refused below).
      double wide = 0.0;
      auto [wide_ptr, wide_ec] = std::from_chars(q, end_, wide);
      if (wide_ec != std::errc()) fail("number '" + token_at(start) + "' is out of range");
      ptr = wide_ptr;
      ec = std::errc();
      value = static_cast<float>(wide);
    }
    if (ec != std::errc() || !at_delimiter(ptr)) fail("bad number '" + token_at(start) + "'");
    if (!std::isfinite(value))
      fail("number '" + token_at(start) + "' is not finite (or out of float's range)");
    p_ = ptr;
    return value;
  }

  void parse_vertex() {
    float xyz[3];
    int count = 0;
    while (!at_line_end()) {
      if (count == 6)
        fail("'v' takes 3 coordinates (4 with a weight, 6 with a colour), found more than 6 numbers");
      const float value = read_coordinate();
      if (count < 3) xyz[count] = value;
      ++count;
    }
    if (count != 3 && count != 4 && count != 6)
      fail("'v' takes 3 coordinates (4 with a weight, 6 with a colour), found " +
           std::to_string(count));
    if (mesh_.vertices.size() == kMaxVertices) fail("more than 2^32 - 1 vertices");
    mesh_.vertices.push_back({xyz[0], xyz[1], xyz[2]});
  }

  // An index of a corner: 1 is the first element read, -1 the last one read so far.
  uint32_t read_index(size_t count, const char* kind) {
    const char* start = p_;
    const char* q = p_;
    if (q != end_ && *q == '+' && q + 1 != end_ && std::isdigit(static_cast<unsigned char>(q[1]))) ++q;
    int64_t index = 0;
    auto [ptr, ec] = std::from_chars(q, end_, index);
    if (ec == std::errc::invalid_argument) fail(std::string("bad ") + kind + " index '" + token_at(start) + "'");
    if (ec == std::errc::result_out_of_range)
      fail(std::string(kind) + " index '" + token_at(start) + "' is out of range");
    p_ = ptr;
    if (index == 0) fail(std::string(kind) + " index 0 is invalid (OBJ indices count from 1)");
    const int64_t n = static_cast<int64_t>(count);
    if (index > n)
      fail(std::string(kind) + " index " + std::to_string(index) + " is out of range (" +
           std::to_string(count) + " read so far)");
    if (index < -n)
      fail(std::string(kind) + " index " + std::to_string(index) + " reaches before the first (" +
           std::to_string(count) + " read so far)");
    return static_cast<uint32_t>(index > 0 ? index - 1 : n + index);
  }

  // A corner is i, i/t, i//n or i/t/n; t and n are checked but not kept.
  uint32_t read_corner() {
    const char* start = p_;
    const uint32_t vertex = read_index(mesh_.vertices.size(), "vertex");
    if (p_ != end_ && *p_ == '/') {
      ++p_;
      if (p_ == end_ || *p_ != '/') read_index(texcoords_, "texture");
      if (p_ != end_ && *p_ == '/') {
        ++p_;
        read_index(normals_, "normal");
      }
    }
    if (!at_delimiter(p_)) fail("bad face corner '" + token_at(start) + "' (expected i, i/t, i//n or i/t/n)");
    return vertex;
  }

  void parse_face() {
    corners_.clear();
    while (!at_line_end()) corners_.push_back(read_corner());
    if (corners_.size() < 3)
      fail("a face needs at least 3 corners, found " + std::to_string(corners_.size()));
    // A polygon becomes a fan around its first corner, in the order the corners are listed,
    // so that primIDs and barycentric coordinates follow the file.
    for (size_t i = 1; i + 1 < corners_.size(); ++i)
      mesh_.triangles.push_back({corners_[0], corners_[i], corners_[i + 1]});
  }

  static constexpr size_t kMaxVertices = 0xFFFFFFFFu;  // 0xFFFFFFFF is not a usable index

  std::string_view text_;
  std::string_view name_;
  size_t line_ = 0;
  const char* p_ = nullptr;
  const char* end_ = nullptr;
  size_t texcoords_ = 0;
  size_t normals_ = 0;
  std::vector<uint32_t> corners_;
  TriangleMesh mesh_;
};

}  // namespace

TriangleMesh parse_obj(std::string_view text, std::string_view name) {
  return ObjParser(text, name).parse();
}

TriangleMesh load_obj(const std::filesystem::path& path) {
  return parse_obj(read_file(path), path.string());
}

}  // namespace rtk
