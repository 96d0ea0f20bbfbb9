#include "image/image_decode.h"

#include <algorithm>
#include <cctype>

#include "image/image_decoders.h"
#include "io/read_file.h"

namespace rtk {

namespace image_detail {

void check_dimensions(const std::string& name, std::uint64_t width, std::uint64_t height) {
  if (width < 1 || height < 1)
    fail(name, "an image of " + std::to_string(width) + " x " + std::to_string(height) +
                   " pixels is empty");
  if (width > kMaxImageSide || height > kMaxImageSide || width * height > kMaxImagePixels)
    fail(name, std::to_string(width) + " x " + std::to_string(height) +
                   " pixels is larger than RTK reads (" + std::to_string(kMaxImageSide) +
                   " on a side, " + std::to_string(kMaxImagePixels) + " pixels in all)");
}

}  // namespace image_detail

namespace {

bool has_extension(const std::string& name, std::string_view ext) {
  if (name.size() < ext.size()) return false;
  return std::equal(
      ext.begin(), ext.end(), name.end() - static_cast<ptrdiff_t>(ext.size()),
      [](char a, char b) { return a == std::tolower(static_cast<unsigned char>(b)); });
}

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

}  // namespace

// [image-decode]
DecodedImage decode_image(std::string_view bytes, const std::string& name) {
  using namespace image_detail;
  // The format from the first bytes: a file named .png that holds a JPEG is read as a JPEG.
  if (bytes.empty()) fail(name, "the file is empty");
  if (bytes.starts_with("#?")) return decode_radiance_hdr(bytes, name);
  if (bytes.starts_with("\x89PNG\r\n\x1a\n")) return decode_png(bytes, name);
  if (bytes.starts_with("\xFF\xD8\xFF")) return decode_jpeg(bytes, name);
  if (bytes.starts_with(std::string_view("\x76\x2F\x31\x01", 4))) return decode_exr(bytes, name);
  if (bytes.size() >= 3 && (bytes.starts_with("PF") || bytes.starts_with("Pf")) &&
      is_blank(bytes[2]))
    return decode_pfm(bytes, name);
  if (bytes.size() >= 3 && (bytes.starts_with("P6") || bytes.starts_with("P5")) &&
      is_blank(bytes[2]))
    return decode_pnm(bytes, name);
  if (has_extension(name, ".tga")) return decode_tga(bytes, name);
  fail(name, "not an image RTK reads (PNG, JPEG, TGA, binary PPM or PGM, Radiance HDR, PFM, OpenEXR)");
}
// [image-decode]

DecodedImage read_image_file(const std::string& path) {
  // No supported image within the limits is larger than its pixels as float RGB (PFM) plus a
  // header: a larger file, or one that never ends, is refused before it is read.
  return decode_image(read_file(path, kMaxImagePixels * 12 + (1 << 20)), path);
}

}  // namespace rtk
