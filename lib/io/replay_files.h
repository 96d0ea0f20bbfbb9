/// \file
/// The binary files of ray replay (shared/ray-replay.md): `.rays` (what to trace), `.hits`
/// (closest hits) and `.occl` (occlusion). Each is an 8-byte magic, a uint64 record count and
/// the records, little-endian; a record is exactly the memory of an rtk::Ray, rtk::Hit or a
/// byte, so reading is one size check and one copy.
///
/// Reading is strict: a wrong magic, a file shorter than its header, or a record count that
/// does not match the file's size (short or long) is a FileError naming the file. `.occl`
/// bytes must be 0 or 1. The contents of rays are not judged here: a NaN ray is a legal record
/// that every tracer must report as a miss (rtk::is_valid).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "01_base/ray.h"

namespace rtk {

/// The three kinds of replay file, told apart by their magic.
enum class ReplayFile { rays, hits, occl };

inline constexpr std::string_view kRaysMagic = "RAYS0001";  ///< magic of a `.rays` file
inline constexpr std::string_view kHitsMagic = "HITS0001";  ///< magic of a `.hits` file
inline constexpr std::string_view kOcclMagic = "OCCL0001";  ///< magic of a `.occl` file

/// The kind of replay file whose bytes begin with a known magic, or nothing.
std::optional<ReplayFile> replay_file_kind(std::string_view bytes);

/// Parses the bytes of a `.rays` file; `name` stands for the file in error messages.
std::vector<Ray> parse_rays(std::string_view bytes, std::string_view name);
/// Parses the bytes of a `.hits` file.
std::vector<Hit> parse_hits(std::string_view bytes, std::string_view name);
/// Parses the bytes of a `.occl` file (one byte per ray, 1 = blocked).
std::vector<uint8_t> parse_occlusion(std::string_view bytes, std::string_view name);

/// Reads a `.rays` file; throws FileError naming the file.
std::vector<Ray> read_rays(const std::filesystem::path& path);
/// Reads a `.hits` file; throws FileError naming the file.
std::vector<Hit> read_hits(const std::filesystem::path& path);
/// Reads a `.occl` file; throws FileError naming the file.
std::vector<uint8_t> read_occlusion(const std::filesystem::path& path);

/// The bytes of a `.rays` file holding `rays`.
std::string format_rays(std::span<const Ray> rays);
/// The bytes of a `.hits` file holding `hits`.
std::string format_hits(std::span<const Hit> hits);
/// The bytes of a `.occl` file holding `occluded` (each 0 or 1).
std::string format_occlusion(std::span<const uint8_t> occluded);

/// Writes a `.rays` file; throws FileError naming the file.
void write_rays(const std::filesystem::path& path, std::span<const Ray> rays);
/// Writes a `.hits` file; throws FileError naming the file.
void write_hits(const std::filesystem::path& path, std::span<const Hit> hits);
/// Writes a `.occl` file; throws FileError naming the file.
void write_occlusion(const std::filesystem::path& path, std::span<const uint8_t> occluded);

}  // namespace rtk
