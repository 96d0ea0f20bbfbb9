/// \file
/// The outputs of a command, checked before it does any work: a file it will write must be
/// writable (lib/io's check_output_path), and standard output, where `rtk trace`, `rays` and
/// `compare` print their JSON lines, must be open for writing. A write that fails later (a
/// full disk, `> /dev/full`) is still an error, exit status 2: JsonLine::print and main()
/// check every write to stdout.
#pragma once

#include <string>

namespace rtk::cli {

/// Throws UsageError "-NAME: FILE: reason" when `path`, the value of option -NAME, cannot be
/// written.
void check_output_option(const char* option, const std::string& path);

/// Throws std::runtime_error when standard output is closed or not open for writing.
void check_stdout();

/// Flushes standard output; throws std::runtime_error naming the system's reason when what
/// was printed could not be written.
void flush_stdout();

}  // namespace rtk::cli
