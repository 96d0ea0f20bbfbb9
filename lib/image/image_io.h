/// \file
/// Image files: writers for PNG, TGA, PPM (8-bit, tone-mapped), Radiance HDR and PFM
/// (floating point, linear), chosen from the file name's extension, and a reader for tests
/// and tools.
#pragma once

#include <string>

#include "image/image.h"
#include "image/tonemap.h"

namespace rtk {

/// The file formats of write_image and read_image.
enum class ImageFormat { png, tga, ppm, hdr, pfm, exr };

/// The format named by a path's extension (case-insensitive: .png, .tga, .ppm, .hdr, .pfm, .exr);
/// throws std::invalid_argument listing the supported extensions otherwise.
ImageFormat image_format_from_path(const std::string& path);

// [image-write]
/// Writes an image to `path` in the format its extension names. PNG, TGA and PPM hold 8 bits
/// per channel, made by `tone` (gamma, then clamping to [0, 1]); HDR (Radiance RGBE, through
/// stb_image_write) and PFM hold linear floats and ignore `tone`. PFM is written by hand:
/// the "PF" header, width and height, the scale -1 (negative: little-endian floats), then the
/// rows from the BOTTOM row up, as the format requires. EXR holds the linear floats too (32-bit
/// R, G, B, ZIP-compressed, through the OpenEXR library) and ignores `tone`. The file is encoded in memory and
/// written all or nothing (lib/io's write_file: a temporary file renamed when complete).
/// Throws std::invalid_argument for an unknown extension or an empty image, FileError (a
/// std::runtime_error) naming the path and the system's reason when the file cannot be written.
void write_image(const std::string& path, const Image& image, const ToneMap& tone = {});
// [image-write]

/// Reads an image written by write_image, or any image image/image_decode.h reads (PNG, JPEG,
/// TGA, PPM/PGM, Radiance HDR, PFM). 8-bit files come back as their stored values / 255, with
/// no attempt to undo the tone mapping; HDR and PFM as the linear floats. Rows are returned top
/// row first whatever the file's order. Throws FileError (a std::runtime_error) naming the
/// path and the reason.
Image read_image(const std::string& path);

}  // namespace rtk
