// TGA, read by RTK itself: an 18-byte header, an optional id and colour map, then the pixels,
// plain or as run-length packets. The format has no signature, so every header field is
// checked before it is believed.
#include <algorithm>
#include <cstdint>
#include <vector>

#include "image/image_decoders.h"

namespace rtk::image_detail {

namespace {

constexpr size_t kHeaderBytes = 18;

unsigned le16(const unsigned char* p) { return p[0] | (p[1] << 8); }

// A stored colour (1 to 4 bytes: grey, 15/16-bit BGR, BGR, BGRA) as a colour in [0, 1].
Color decode_pixel(const unsigned char* p, int bytes) {
  switch (bytes) {
    case 1:
      return Color(p[0] / 255.0f);
    case 2: {
      // 5 bits per channel, ARRRRRGG GGGBBBBB little-endian.
      const unsigned v = le16(p);
      return Color(((v >> 10) & 31) / 31.0f, ((v >> 5) & 31) / 31.0f, (v & 31) / 31.0f);
    }
    default:
      return Color(p[2] / 255.0f, p[1] / 255.0f, p[0] / 255.0f);
  }
}

}  // namespace

DecodedImage decode_tga(std::string_view bytes, const std::string& name) {
  if (bytes.size() < kHeaderBytes) fail(name, "truncated: shorter than a TGA header");
  const auto* h = reinterpret_cast<const unsigned char*>(bytes.data());
  const unsigned id_length = h[0], map_type = h[1], type = h[2];
  const unsigned map_first = le16(h + 3), map_length = le16(h + 5), map_bits = h[7];
  const unsigned width = le16(h + 12), height = le16(h + 14), bits = h[16], descriptor = h[17];
  // Step 1: the header, field by field.
  const bool rle = type >= 9;
  const unsigned base = rle ? type - 8 : type;
  if (map_type > 1 || (base != 1 && base != 2 && base != 3) || (type != base && type != base + 8))
    fail(name, "not a TGA file RTK reads (image type " + std::to_string(type) +
                   "; colour-mapped, true-colour and grey, plain or run-length, are read)");
  const bool mapped = base == 1;
  if (mapped != (map_type == 1))
    fail(name, "bad TGA header: the colour map does not match the image type");
  if (mapped      ? bits != 8
      : base == 3 ? bits != 8
                  : (bits != 15 && bits != 16 && bits != 24 && bits != 32))
    fail(name, "bad TGA header: " + std::to_string(bits) + " bits per pixel for image type " +
                   std::to_string(type));
  if (mapped && map_bits != 15 && map_bits != 16 && map_bits != 24 && map_bits != 32)
    fail(name, "bad TGA header: colour-map entries of " + std::to_string(map_bits) + " bits");
  check_dimensions(name, width, height);
  // Step 2: the id and the colour map, which must lie inside the file.
  size_t pos = kHeaderBytes + id_length;
  const int entry_bytes = static_cast<int>((map_bits + 7) / 8);
  const size_t map_bytes = map_type ? static_cast<size_t>(map_length) * entry_bytes : 0;
  if (pos + map_bytes > bytes.size())
    fail(name, "truncated: the file ends inside the TGA colour map");
  const unsigned char* map = h + pos;
  pos += map_bytes;
  // Step 3: the pixel data must be able to hold width x height pixels: exactly that many
  // pixels when plain, and at most 128 pixels per packet of 2 or more bytes when run-length.
  const int pixel_bytes = static_cast<int>((bits + 7) / 8);
  const uint64_t pixels = uint64_t(width) * height, left = bytes.size() - pos;
  if (rle ? pixels > left / (1 + pixel_bytes) * 128 + 128 : pixels * pixel_bytes > left)
    fail(name, "truncated: " + std::to_string(left) + " bytes cannot hold " +
                   std::to_string(width) + " x " + std::to_string(height) + " pixels");
  auto color_of = [&](const unsigned char* p) {
    if (!mapped) return decode_pixel(p, pixel_bytes);
    const unsigned index = p[0];
    if (index < map_first || index - map_first >= map_length)
      fail(name,
           "corrupt TGA data: colour index " + std::to_string(index) + " is not in the colour map");
    return decode_pixel(map + static_cast<size_t>(index - map_first) * entry_bytes, entry_bytes);
  };
  // Step 4: the pixels in file order, then placed by the origin bits of the descriptor.
  std::vector<Color> stored(pixels);
  for (uint64_t i = 0; i < pixels;) {
    auto need = [&](size_t n) {
      if (n > bytes.size() - pos) fail(name, "truncated: the file ends inside the TGA pixel data");
      const unsigned char* p = h + pos;
      pos += n;
      return p;
    };
    const unsigned packet = rle ? *need(1) : 127;
    const uint64_t count = std::min<uint64_t>((packet & 127) + 1, pixels - i);
    if (rle && (packet & 128)) {
      const Color c = color_of(need(static_cast<size_t>(pixel_bytes)));
      std::fill_n(stored.begin() + static_cast<ptrdiff_t>(i), count, c);
      i += count;
    } else {
      for (uint64_t k = 0; k < count; ++k)
        stored[i++] = color_of(need(static_cast<size_t>(pixel_bytes)));
    }
  }
  const bool top_down = descriptor & 0x20, right_to_left = descriptor & 0x10;
  DecodedImage out{Image(static_cast<int>(width), static_cast<int>(height)), false};
  for (unsigned y = 0; y < height; ++y)
    for (unsigned x = 0; x < width; ++x)
      out.image.at(static_cast<int>(right_to_left ? width - 1 - x : x),
                   static_cast<int>(top_down ? y : height - 1 - y)) =
          stored[static_cast<size_t>(y) * width + x];
  return out;
}

}  // namespace rtk::image_detail
