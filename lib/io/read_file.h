/// \file
/// Whole-file reading and writing: the loaders parse from memory, which is both the fastest way
/// to read a file and the way the fuzzer feeds them.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace rtk {

/// The bytes of a file. Throws FileError naming the file when it cannot be opened or read.
std::string read_file(const std::filesystem::path& path);

/// Replaces a file's contents with `bytes`. Throws FileError naming the file on failure
/// (a full disk is reported, not silently truncated).
void write_file(const std::filesystem::path& path, std::string_view bytes);

}  // namespace rtk
