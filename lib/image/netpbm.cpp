// The Netpbm family RTK reads: binary PPM and PGM (8 or 16 bits) and PFM (floats). Each is a
// short text header (a signature, the width, the height, the maximum value or the scale)
// followed by exactly the bytes of the pixels.
#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

#include "image/image_decoders.h"

namespace rtk::image_detail {

namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

// The header's fields, read one at a time; '#' starts a comment up to the end of the line.
class Header {
 public:
  Header(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name), pos_(2) {}

  std::string_view token(const char* what) {
    while (pos_ < bytes_.size() && pos_ < kMaxHeaderBytes) {
      if (is_blank(bytes_[pos_]))
        ++pos_;
      else if (bytes_[pos_] == '#')
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
      else
        break;
    }
    const size_t start = pos_;
    while (pos_ < bytes_.size() && pos_ - start < 32 && !is_blank(bytes_[pos_])) ++pos_;
    if (pos_ == start) fail(name_, std::string("truncated header: no ") + what);
    return bytes_.substr(start, pos_ - start);
  }
  uint64_t count(const char* what, uint64_t min, uint64_t max) {
    const std::string_view t = token(what);
    uint64_t value = 0;
    const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || p != t.data() + t.size() || value < min || value > max)
      fail(name_, std::string("bad header: the ") + what + " '" + std::string(t) +
                      "' is not a whole number from " + std::to_string(min) + " to " +
                      std::to_string(max));
    return value;
  }
  double number(const char* what) {
    const std::string_view t = token(what);
    double value = 0;
    const auto [p, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
    if (ec != std::errc() || p != t.data() + t.size() || !std::isfinite(value) || value == 0)
      fail(name_, std::string("bad header: the ") + what + " '" + std::string(t) +
                      "' is not a non-zero number");
    return value;
  }
  // The pixel data: after the single blank that ends the header, exactly `size` bytes (more
  // is tolerated, as other readers do; fewer is a truncated file).
  std::string_view data(uint64_t size) {
    if (pos_ >= bytes_.size() || !is_blank(bytes_[pos_]))
      fail(name_, "truncated: no pixel data after the header");
    ++pos_;
    if (bytes_.size() - pos_ < size)
      fail(name_, "truncated: " + std::to_string(bytes_.size() - pos_) + " bytes of pixel data, " +
                      std::to_string(size) + " expected");
    return bytes_.substr(pos_, size);
  }

 private:
  static constexpr size_t kMaxHeaderBytes = 4096;
  std::string_view bytes_;
  const std::string& name_;
  size_t pos_;
};

}  // namespace

DecodedImage decode_pfm(std::string_view bytes, const std::string& name) {
  Header header(bytes, name);
  const int channels = bytes[1] == 'F' ? 3 : 1;
  const uint64_t width = header.count("width", 1, kMaxImageSide);
  const uint64_t height = header.count("height", 1, kMaxImageSide);
  check_dimensions(name, width, height);
  // The scale's sign gives the byte order (negative: little-endian); its size is not used.
  const bool little = header.number("scale") < 0;
  const std::string_view data = header.data(width * height * channels * 4);
  const bool swap = little != (std::endian::native == std::endian::little);
  DecodedImage out{Image(static_cast<int>(width), static_cast<int>(height)), true};
  for (uint64_t row = 0; row < height; ++row)
    for (uint64_t x = 0; x < width; ++x) {
      float v[3];
      for (int k = 0; k < channels; ++k) {
        uint32_t bits;
        std::memcpy(&bits, data.data() + ((row * width + x) * channels + k) * 4, 4);
        if (swap)
          bits = (bits >> 24) | ((bits >> 8) & 0xff00u) | ((bits << 8) & 0xff0000u) | (bits << 24);
        v[k] = std::bit_cast<float>(bits);
      }
      // Rows are stored bottom-up.
      out.image.at(static_cast<int>(x), static_cast<int>(height - 1 - row)) =
          channels == 3 ? Color(v[0], v[1], v[2]) : Color(v[0]);
    }
  return out;
}

DecodedImage decode_pnm(std::string_view bytes, const std::string& name) {
  Header header(bytes, name);
  const int channels = bytes[1] == '6' ? 3 : 1;
  const uint64_t width = header.count("width", 1, kMaxImageSide);
  const uint64_t height = header.count("height", 1, kMaxImageSide);
  check_dimensions(name, width, height);
  const uint64_t maximum = header.count("maximum value", 1, 65535);
  const int sample_bytes = maximum > 255 ? 2 : 1;
  const std::string_view data = header.data(width * height * channels * sample_bytes);
  const auto* p = reinterpret_cast<const unsigned char*>(data.data());
  auto sample = [&](uint64_t i) {
    // 16-bit samples are big-endian; a sample above the maximum is clamped to it.
    const unsigned v = sample_bytes == 2 ? (p[2 * i] << 8) | p[2 * i + 1] : p[i];
    return static_cast<float>(std::min<unsigned>(v, static_cast<unsigned>(maximum))) /
           static_cast<float>(maximum);
  };
  DecodedImage out{Image(static_cast<int>(width), static_cast<int>(height)), false};
  for (uint64_t i = 0; i < width * height; ++i)
    out.image.pixels[i] = channels == 3 ? Color(sample(3 * i), sample(3 * i + 1), sample(3 * i + 2))
                                        : Color(sample(i));
  return out;
}

}  // namespace rtk::image_detail
