/// \file
/// The one exception that every reader in lib/io throws: it names the file and, for text
/// formats, the line, so that a user can open the file at the place that is wrong.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>

namespace rtk {

/// A file that cannot be read or does not follow its format. what() reads like a compiler's
/// diagnostic, `FILE:LINE: message` (or `FILE: message` where no line applies), so that editors
/// and terminals can jump to it.
class FileError : public std::runtime_error {
 public:
  /// An error at `line` (counted from 1) of `file`; line 0 means the whole file.
  FileError(std::string file, std::size_t line, const std::string& message)
      : std::runtime_error(format(file, line, message)), file_(std::move(file)), line_(line) {}

  /// The file's name as the caller gave it.
  const std::string& file() const { return file_; }
  /// The line (from 1), or 0 when the error is not about one line.
  std::size_t line() const { return line_; }

 private:
  static std::string format(const std::string& file, std::size_t line, const std::string& message) {
    return line == 0 ? file + ": " + message : file + ":" + std::to_string(line) + ": " + message;
  }
  std::string file_;
  std::size_t line_;
};

}  // namespace rtk
