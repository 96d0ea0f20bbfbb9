/// \file
/// The decoders behind decode_image, one per format (lib/image's own, not installed): each
/// takes the whole file and its name, validates before it allocates, and throws FileError.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "image/image_decode.h"
#include "io/file_error.h"

namespace rtk::image_detail {

/// Throws FileError "NAME: message".
[[noreturn]] inline void fail(const std::string& name, const std::string& message) {
  throw FileError(name, 0, message);
}

/// Checks a file's dimensions (each at least 1) against kMaxImageSide and kMaxImagePixels;
/// throws FileError otherwise. Each decoder calls it, and checks that the file holds at least
/// the bytes such an image needs, before it allocates anything.
void check_dimensions(const std::string& name, std::uint64_t width, std::uint64_t height);

/// Radiance HDR (RGBE), flat or run-length encoded scanlines.
DecodedImage decode_radiance_hdr(std::string_view bytes, const std::string& name);
/// PFM: "PF" (RGB) or "Pf" (grey) floats, rows bottom up, byte order from the scale's sign.
DecodedImage decode_pfm(std::string_view bytes, const std::string& name);
/// Binary PPM ("P6") and PGM ("P5"), maximum value 1 to 65535.
DecodedImage decode_pnm(std::string_view bytes, const std::string& name);
/// TGA: image types 1, 2, 3 and their run-length forms 9, 10, 11.
DecodedImage decode_tga(std::string_view bytes, const std::string& name);
/// PNG through libpng's simplified API.
DecodedImage decode_png(std::string_view bytes, const std::string& name);
/// JPEG through libjpeg.
DecodedImage decode_jpeg(std::string_view bytes, const std::string& name);
/// OpenEXR through the OpenEXR library: R, G, B (or Y) as linear floats, whatever their
/// stored type (half, float, uint) and compression.
DecodedImage decode_exr(std::string_view bytes, const std::string& name);

}  // namespace rtk::image_detail
