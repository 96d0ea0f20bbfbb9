// Runs a program of the build through the shell and captures what it prints, for the tests
// that check a command line end to end.
#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace rtk::test {

struct ProgramResult {
  int status = -1;     ///< the exit status (-1 if the program did not exit normally)
  std::string output;  ///< stdout and stderr together
};

/// Runs `program args` (a shell command line), capturing stdout and stderr.
inline ProgramResult run_program(const std::string& program, const std::string& args) {
  const std::string command = program + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run " + command);
  ProgramResult result;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

}  // namespace rtk::test
