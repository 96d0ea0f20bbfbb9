#include "output_checks.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "io/file_error.h"
#include "io/read_file.h"
#include "options.h"

namespace rtk::cli {

void check_output_option(const char* option, const std::string& path) {
  try {
    check_output_path(path);
  } catch (const FileError& e) {
    throw UsageError(std::string("-") + option + ": " + e.what());
  }
}

void check_not_an_input(const char* option, const std::string& output,
                        const std::string& input_role, const std::filesystem::path& input) {
  std::error_code ec;  // set, and the answer false, when either file does not exist
  if (std::filesystem::equivalent(output, input, ec))
    throw UsageError(std::string("-") + option + ": " + output + " is also " + input_role +
                     "; writing it would destroy that file");
}

void check_stdout() {
  const int flags = ::fcntl(STDOUT_FILENO, F_GETFL);
  if (flags < 0) throw std::runtime_error("stdout is closed: the results would be lost");
  if ((flags & O_ACCMODE) == O_RDONLY) throw std::runtime_error("stdout is not open for writing");
}

void flush_stdout() {
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout))
    throw std::runtime_error(std::string("cannot write to stdout: ") +
                             (errno ? std::strerror(errno) : "write error"));
}

}  // namespace rtk::cli
