/// \file
/// Numbers in scene files, read exactly (std::from_chars) and refused with the file and line
/// when a token is not one.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <string_view>

#include "io/file_error.h"

namespace rtk::scene_io {

/// Where a token came from: a file and a line, or the command line (line 0, file
/// "command line").
struct Where {
  std::string file;
  size_t line = 0;
};

/// A token as a message shows it: bytes outside printable ASCII as \\xNN, and a token longer
/// than 40 bytes clipped with its length (a 10 MB token is not echoed whole).
inline std::string shown(std::string_view token) {
  constexpr size_t kShown = 40;
  std::string out;
  for (const char c : token.substr(0, kShown)) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", u);
      out += hex;
    }
  }
  if (token.size() > kShown) out += "... (" + std::to_string(token.size()) + " bytes)";
  return out;
}

/// Throws the FileError "FILE:LINE: message".
[[noreturn]] inline void fail(const Where& where, const std::string& message) {
  throw FileError(where.file, where.line, message);
}

/// A finite float in [min, max]; `what` names the argument in the message ("-fov", "Kd").
inline float parse_float(std::string_view token, const Where& where, std::string_view what,
                         float min = -std::numeric_limits<float>::max(),
                         float max = std::numeric_limits<float>::max()) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') ++first;
  float value = 0.0f;
  auto [ptr, ec] = std::from_chars(first, last, value);
  // Beyond a float's range, read as a double (as the OBJ reader does): a number too close to 0
  // (1e-50) becomes the float it rounds to, a signed 0, and one too large (1e40) is said to be
  // too large, not malformed.
  if (ec == std::errc::result_out_of_range) {
    double wide = 0.0;
    const auto [wide_ptr, wide_ec] = std::from_chars(first, last, wide);
    if (wide_ptr == last && wide_ec == std::errc::result_out_of_range)
      fail(where, std::string(what) + ": '" + shown(token) + "' is out of range");
    if (wide_ptr == last && wide_ec == std::errc()) {
      value = static_cast<float>(wide);
      if (std::isinf(value))
        fail(where,
             std::string(what) + ": " + shown(token) + " is beyond a float's range (3.4e38)");
      ptr = wide_ptr;
      ec = wide_ec;
    }
  }
  if (ec != std::errc() || ptr != last || !std::isfinite(value))
    fail(where, std::string(what) + ": '" + shown(token) + "' is not a finite number");
  if (value < min || value > max) {
    char range[64];
    std::snprintf(range, sizeof range, "from %g to %g", double(min), double(max));
    fail(where, std::string(what) + ": " + shown(token) + " is not " + range);
  }
  return value;
}

/// An integer in [min, max].
inline long long parse_int(std::string_view token, const Where& where, std::string_view what,
                           long long min, long long max) {
  const char* first = token.data();
  const char* last = first + token.size();
  if (first != last && *first == '+') ++first;
  long long value = 0;
  const auto [ptr, ec] = std::from_chars(first, last, value);
  const bool too_large = ec == std::errc::result_out_of_range && ptr == last;  // beyond 2^63
  if (!too_large && (ec != std::errc() || ptr != last))
    fail(where, std::string(what) + ": '" + shown(token) + "' is not an integer");
  if (too_large || value < min || value > max)
    fail(where, std::string(what) + ": " + shown(token) + " is not from " + std::to_string(min) +
                    " to " + std::to_string(max));
  return value;
}

}  // namespace rtk::scene_io
