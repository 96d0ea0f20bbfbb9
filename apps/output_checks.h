/// \file
/// The outputs of a command, checked before it does any work: a file it will write must be
/// writable (lib/io's check_output_path), and standard output, where `rtk trace`, `rays` and
/// `compare` print their JSON lines, must be open for writing. A write that fails later (a
/// full disk, `> /dev/full`) is still an error, exit status 2: JsonLine::print and main()
/// check every write to stdout.
#pragma once

#include <filesystem>
#include <string>

namespace rtk::cli {

/// Throws UsageError "-NAME: FILE: reason" when `path`, the value of option -NAME, cannot be
/// written.
void check_output_option(const char* option, const std::string& path);

/// Throws UsageError "-NAME: FILE is also INPUT; ..." when `output`, the value of option -NAME,
/// is the same file as `input`, which the command reads (`input_role` says which: "the input
/// of -i"). Files are compared as the system knows them, so that another spelling of the path,
/// a symbolic or a hard link is caught too; an output that does not exist yet is no input.
/// The input was read by the time the output is written, but it would be gone.
void check_not_an_input(const char* option, const std::string& output,
                        const std::string& input_role, const std::filesystem::path& input);

/// Throws std::runtime_error when standard output is closed or not open for writing.
void check_stdout();

/// Flushes standard output; throws std::runtime_error naming the system's reason when what
/// was printed could not be written.
void flush_stdout();

}  // namespace rtk::cli
