/// \file
/// OpenEXR files (lib/image's own, not installed): the encoder behind write_image's `.exr`.
/// The decoder is image_detail::decode_exr (image_decoders.h), reached through decode_image.
#pragma once

#include <string>

#include "image/image.h"

namespace rtk {

/// The bytes of an OpenEXR file of `image`: 32-bit float R, G and B, ZIP-compressed, so that
/// reading it back gives exactly the same floats.
std::string encode_exr(const Image& image);

}  // namespace rtk
