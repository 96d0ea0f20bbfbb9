// Radiance HDR (RGBE) files, read by RTK itself: the decoder of stb_image 2.27 loops forever on
// a truncated run-length scanline, and trusts the header's dimensions before it knows whether
// the file holds that many pixels.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "image/image_decoders.h"

namespace rtk::image_detail {

namespace {

// A header longer than this is not a Radiance header (real ones take a few hundred bytes).
constexpr size_t kMaxHeaderBytes = 1 << 16;

// The shortest encoding of one scanline of `width` pixels: flat RGBE takes 4 bytes a pixel; a
// run-length scanline (only for widths 8 to 32767) a 4-byte marker and, in each of its 4
// channel planes, at least 2 bytes (a run) for every 127 pixels.
uint64_t min_scanline_bytes(uint64_t width) {
  const uint64_t flat = 4 * width;
  if (width < 8 || width > 0x7fff) return flat;
  return std::min(flat, 4 + 4 * 2 * ((width + 126) / 127));
}

// Reads bytes [pos, end) as the decoder walks through them; every read is checked.
class Reader {
 public:
  Reader(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}
  size_t left() const { return bytes_.size() - pos_; }
  // The next n bytes without taking them, or null when fewer are left.
  const unsigned char* peek(size_t n) const {
    return n <= left() ? reinterpret_cast<const unsigned char*>(bytes_.data() + pos_) : nullptr;
  }
  const unsigned char* take(size_t n, const char* what) {
    if (n > left()) fail(name_, std::string("truncated: the file ends inside ") + what);
    const auto* p = reinterpret_cast<const unsigned char*>(bytes_.data() + pos_);
    pos_ += n;
    return p;
  }
  // The next line without its '\n'; the header must end within kMaxHeaderBytes.
  std::string_view line() {
    const size_t end = bytes_.find('\n', pos_);
    if (end == std::string_view::npos || end > kMaxHeaderBytes)
      fail(name_, "truncated or not a Radiance header: no end of the header line");
    const std::string_view l = bytes_.substr(pos_, end - pos_);
    pos_ = end + 1;
    return l;
  }

 private:
  std::string_view bytes_;
  const std::string& name_;
  size_t pos_ = 0;
};

// "-Y 480 +X 640": rows from the top (or, with +Y, from the bottom), columns left to right.
struct Resolution {
  uint64_t width = 0, height = 0;
  bool bottom_up = false;
};

Resolution parse_resolution(std::string_view line, const std::string& name) {
  auto bad = [&] {
    fail(name, "the resolution line must read '-Y height +X width' (or '+Y height +X width')");
  };
  Resolution r;
  if (line.starts_with("-Y "))
    r.bottom_up = false;
  else if (line.starts_with("+Y "))
    r.bottom_up = true;
  else
    bad();
  const char* p = line.data() + 3;
  const char* end = line.data() + line.size();
  auto [q, ec] = std::from_chars(p, end, r.height);
  if (ec != std::errc() || end - q < 4 || std::string_view(q, 4) != " +X ") bad();
  auto [q2, ec2] = std::from_chars(q + 4, end, r.width);
  if (ec2 != std::errc() || q2 != end) bad();
  return r;
}

float channel(unsigned char mantissa, unsigned char exponent) {
  // Each channel is mantissa / 256 * 2^(exponent - 128); exponent 0 is black.
  return exponent == 0 ? 0.0f : std::ldexp(static_cast<float>(mantissa), int(exponent) - 136);
}

}  // namespace

// [image-hdr-reader]
DecodedImage decode_radiance_hdr(std::string_view bytes, const std::string& name) {
  Reader in(bytes, name);
  // Step 1: the header, "#?RADIANCE" then VARIABLE=value lines up to an empty line.
  const std::string_view magic = in.line();
  if (!magic.starts_with("#?")) fail(name, "not a Radiance HDR file (no '#?' signature)");
  for (std::string_view line = in.line(); !line.empty(); line = in.line())
    if (line.starts_with("FORMAT=") && line != "FORMAT=32-bit_rle_rgbe")
      fail(name, "unsupported Radiance format '" + std::string(line.substr(7, 40)) +
                     "' (only 32-bit_rle_rgbe)");
  const Resolution res = parse_resolution(in.line(), name);
  // Step 2: the dimensions against the limits and against the bytes that follow.
  check_dimensions(name, res.width, res.height);
  if (res.height > in.left() / min_scanline_bytes(res.width))
    fail(name, "truncated: " + std::to_string(in.left()) + " bytes cannot hold " +
                   std::to_string(res.height) + " scanlines of " + std::to_string(res.width) +
                   " pixels");
  const int width = static_cast<int>(res.width), height = static_cast<int>(res.height);
  // Step 3: the scanlines, each flat (4 bytes a pixel) or run-length encoded (a 2, 2 marker
  // with the width, then the R, G, B and E planes, each a series of runs and literal spans).
  DecodedImage out{Image(width, height), true};
  std::vector<unsigned char> planes(4 * static_cast<size_t>(width));
  for (int row = 0; row < height; ++row) {
    unsigned char* scan = planes.data();
    const unsigned char* marker = in.peek(4);
    const bool encoded = width >= 8 && width <= 0x7fff && marker && marker[0] == 2 &&
                         marker[1] == 2 && ((marker[2] << 8) | marker[3]) == width;
    if (encoded) {
      in.take(4, "a scanline marker");
      for (int c = 0; c < 4; ++c) {
        unsigned char* plane = scan + static_cast<size_t>(c) * width;
        for (int x = 0; x < width;) {
          const unsigned count = *in.take(1, "a run-length scanline");
          const bool run = count > 128;
          const int n = static_cast<int>(run ? count - 128 : count);
          if (n == 0 || n > width - x)
            fail(name, "corrupt run-length data in scanline " + std::to_string(row) +
                           " (a run of " + std::to_string(n) + " at pixel " + std::to_string(x) +
                           " of " + std::to_string(width) + ")");
          if (run)
            std::memset(plane + x, *in.take(1, "a run-length scanline"), static_cast<size_t>(n));
          else
            std::memcpy(plane + x, in.take(static_cast<size_t>(n), "a run-length scanline"),
                        static_cast<size_t>(n));
          x += n;
        }
      }
      for (int x = 0; x < width; ++x) {
        const unsigned char e = scan[3 * width + x];
        out.image.at(x, res.bottom_up ? height - 1 - row : row) = Color(
            channel(scan[x], e), channel(scan[width + x], e), channel(scan[2 * width + x], e));
      }
    } else {
      const unsigned char* p = in.take(4 * static_cast<size_t>(width), "a flat scanline");
      for (int x = 0; x < width; ++x, p += 4)
        out.image.at(x, res.bottom_up ? height - 1 - row : row) =
            Color(channel(p[0], p[3]), channel(p[1], p[3]), channel(p[2], p[3]));
    }
  }
  return out;
}
// [image-hdr-reader]

}  // namespace rtk::image_detail
