/// \file
/// Image files in: one bounded, validating reader for every format RTK reads (textures, HDR
/// environment maps, the tests' renders). It cannot hang or read past its buffer on any input:
/// every count and dimension is checked against the limits below and against the bytes the
/// file actually holds before anything is allocated, and a truncated or header-only file is an
/// error, never an image of black or of whatever memory held.
///
/// Formats, told apart by their first bytes (TGA, which has no signature, by its extension):
/// - Radiance HDR (`#?RADIANCE`, `#?RGBE`), flat and run-length encoded: RTK's own reader;
/// - PFM (`PF` colour, `Pf` grey, either byte order) and binary PPM/PGM (`P6`, `P5`, 8 or 16
///   bits): RTK's own readers;
/// - TGA (true colour, grey and colour-mapped, plain or run-length encoded): RTK's own reader;
/// - PNG through libpng and JPEG through libjpeg(-turbo), maintained and bounds-checked
///   decoders; a JPEG that libjpeg would patch up with a warning (a premature end) is refused;
/// - OpenEXR (magic 76 2F 31 01) through the OpenEXR library, from memory: linear floats.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "image/image.h"

namespace rtk {

/// The widest or tallest image RTK reads: 32,768 pixels, as for the images it renders.
inline constexpr int kMaxImageSide = 1 << 15;
/// The most pixels of an image RTK reads: 2^26 (8192 x 8192), 768 MiB as linear colours.
inline constexpr std::uint64_t kMaxImagePixels = std::uint64_t(1) << 26;

/// An image as a file held it.
struct DecodedImage {
  /// The pixels, top row first. 8- and 16-bit formats give their stored values divided by their
  /// maximum (still display-encoded); HDR and PFM give linear floats.
  Image image;
  /// True for the floating-point formats (HDR, PFM, EXR), whose values are linear radiance.
  bool linear = false;
};

/// Decodes the bytes of an image file; `name` stands for the file in messages. Throws
/// FileError "NAME: reason" for anything that is not a complete, valid image of a supported
/// format within kMaxImageSide and kMaxImagePixels.
DecodedImage decode_image(std::string_view bytes, const std::string& name);

/// Reads and decodes an image file (read_file, then decode_image).
DecodedImage read_image_file(const std::string& path);

}  // namespace rtk
