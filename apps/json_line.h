/// \file
/// One JSON object on one line, the output format of `rtk trace`, `rtk rays` and
/// `rtk compare` (shared/ray-replay.md): easy to read for people and for `jq` or a script.
#pragma once

#include <cmath>
#include <concepts>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <type_traits>

#include "output_checks.h"

namespace rtk::cli {

/// Builds `{"key":value,...}` in the order the fields are added.
class JsonLine {
 public:
  /// Adds a string field (escaped as JSON requires).
  JsonLine& add(std::string_view key, std::string_view value) {
    key_(key);
    text_ += '"';
    for (char c : value) {
      if (c == '"' || c == '\\') {
        text_ += '\\';
        text_ += c;
      } else if (static_cast<unsigned char>(c) < 0x20) {
        char escape[8];
        std::snprintf(escape, sizeof escape, "\\u%04x", unsigned(c));
        text_ += escape;
      } else {
        text_ += c;
      }
    }
    text_ += '"';
    return *this;
  }
  JsonLine& add(std::string_view key, const char* value) { return add(key, std::string_view(value)); }
  /// Adds an integer field.
  template <std::integral T>
  JsonLine& add(std::string_view key, T value) {
    key_(key);
    if constexpr (std::is_same_v<T, bool>) {
      text_ += value ? "true" : "false";
    } else {
      text_ += std::to_string(value);
    }
    return *this;
  }
  /// Adds a number with 6 significant digits (null for NaN or infinity, which JSON lacks).
  JsonLine& add(std::string_view key, double value) {
    key_(key);
    if (!std::isfinite(value)) {
      text_ += "null";
    } else {
      char buffer[32];
      std::snprintf(buffer, sizeof buffer, "%.6g", value);
      text_ += buffer;
    }
    return *this;
  }
  /// Adds a field whose value is already JSON (an object or an array).
  JsonLine& add_raw(std::string_view key, std::string_view json) {
    key_(key);
    text_ += json;
    return *this;
  }
  /// The object's text, without a line end.
  std::string str() const { return text_.empty() ? "{}" : text_ + "}"; }
  /// Prints the object and a line end on stdout, flushed (a pipe sees each line at once).
  /// Throws std::runtime_error when it cannot be written (`rtk trace > /dev/full`): results
  /// that were not delivered are an error, never a silent exit 0.
  void print() const {
    std::fputs(str().c_str(), stdout);
    std::fputc('\n', stdout);
    flush_stdout();
  }

 private:
  void key_(std::string_view key) {
    text_ += text_.empty() ? "{\"" : ",\"";
    text_ += key;
    text_ += "\":";
  }
  std::string text_;
};

}  // namespace rtk::cli
