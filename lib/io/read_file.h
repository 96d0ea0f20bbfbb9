/// \file
/// Whole-file reading and writing: the loaders parse from memory, which is both the fastest way
/// to read a file and the way the fuzzer feeds them.
///
/// Reading is bounded: a file that has no end (`/dev/zero`, a terminal) or that is larger
/// than its kind of file may be is refused before it fills the memory. Writing is all or
/// nothing: the bytes go to a temporary file in the same folder, which is renamed over the
/// target only once it is complete, so that a reader never sees half a file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace rtk {

/// The most bytes read_file reads unless the caller gives a smaller limit: 4 GiB, a hundred
/// million rays or triangles. A larger file is refused with its size and this limit.
inline constexpr std::uint64_t kMaxFileBytes = std::uint64_t(1) << 32;

/// The most bytes of a file that people write by hand (scene scripts, MTL libraries): 64 MiB.
inline constexpr std::uint64_t kMaxTextFileBytes = std::uint64_t(64) << 20;

/// The bytes of a file. Regular files and pipes are read, up to `max_bytes` (a larger file
/// is refused, a pipe as soon as it has sent more); folders, devices (`/dev/zero`) and
/// sockets are refused without reading. Throws FileError naming the file for all of these
/// and when it cannot be opened or read.
std::string read_file(const std::filesystem::path& path, std::uint64_t max_bytes = kMaxFileBytes);

/// Replaces a file's contents with `bytes`, all or nothing: they are written to a temporary
/// file in the same folder, which is renamed over `path` once complete; on any failure the
/// temporary file is removed and `path` is left as it was. A target that exists and is not
/// a regular file (`/dev/null`, a pipe) is written in place. Throws FileError naming the file
/// on failure (a full disk is reported, never a silently truncated file).
void write_file(const std::filesystem::path& path, std::string_view bytes);

/// Checks, before any work is done, that write_file can later write `path`: it is not a
/// folder, its folder exists, and the process may write both (or, for a device or a pipe,
/// the target itself). Creates nothing. Throws FileError naming the file and the reason.
void check_output_path(const std::filesystem::path& path);

}  // namespace rtk
