// lib/image's readers on valid files of every format, and on every way a file can be cut short
// or lie about its size: each gives an error naming the file, never a hang, a crash or an
// image of black.
#include <doctest/doctest.h>
#include <stb/stb_image_write.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "image/image_decode.h"
#include "image/image_io.h"
#include "io/file_error.h"
#include "io/read_file.h"

using namespace rtk;

namespace {

// An image of w x h pixels with distinct, exactly representable 8-bit values.
Image pattern(int w, int h) {
  Image image(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      image.at(x, y) =
          Color(float((x * 37) % 256), float((y * 91) % 256), float((x + y) * 13 % 256)) / 255.0f;
  return image;
}

void append(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<size_t>(size));
}

std::vector<unsigned char> bytes_of(const Image& image) {
  std::vector<unsigned char> out;
  for (const Color& c : image.pixels)
    for (int k = 0; k < 3; ++k)
      out.push_back(static_cast<unsigned char>(std::lround(c[k] * 255.0f)));
  return out;
}

// The error of decoding `bytes`: it must be a FileError that names the file.
std::string error_of(std::string_view bytes, const std::string& name) {
  try {
    decode_image(bytes, name);
  } catch (const FileError& e) {
    CHECK(e.file() == name);
    return e.what();
  }
  return "";
}

// The CRC-32 of PNG chunks (ISO 3309), bit by bit.
uint32_t crc32(std::string_view bytes) {
  uint32_t c = 0xFFFFFFFFu;
  for (const char b : bytes) {
    c ^= static_cast<unsigned char>(b);
    for (int k = 0; k < 8; ++k) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
  }
  return ~c;
}

bool contains(const std::string& text, const std::string& words) {
  return text.find(words) != std::string::npos;
}

// Every proper prefix of a valid file is refused (a truncated file is never an image).
void check_every_prefix_fails(const std::string& file, const std::string& name) {
  for (size_t n = 0; n < file.size(); ++n) {
    INFO(name << " cut to " << n << " of " << file.size() << " bytes");
    CHECK(!error_of(std::string_view(file).substr(0, n), name).empty());
  }
}

const char* kHdrHeader = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n";

}  // namespace

TEST_CASE("lib_image: Radiance HDR, flat and run-length, reads what stb_image_write wrote") {
  for (int width : {5, 40}) {  // stb writes widths of 8 or more run-length encoded
    const Image image = pattern(width, 3);
    std::string file;
    REQUIRE(stbi_write_hdr_to_func(append, &file, width, 3, 3, &image.pixels[0].r));
    const DecodedImage d = decode_image(file, "a.hdr");
    CHECK(d.linear);
    REQUIRE(d.image.width == width);
    REQUIRE(d.image.height == 3);
    for (size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c)
        CHECK(std::fabs(d.image.pixels[i][c] - image.pixels[i][c]) <=
              max_component(image.pixels[i]) / 128.0f + 1e-6f);
    check_every_prefix_fails(file, "a.hdr");
  }
}

TEST_CASE("lib_image: Radiance HDR files that lie about their size or their runs are refused") {
  // Only a header: no pixels at all (stb_image 2.27 returned uninitialised memory).
  CHECK(contains(error_of(std::string(kHdrHeader) + "-Y 2 +X 2\n", "h.hdr"), "truncated"));
  // 7 x 16,777,216 pixels announced by 52 bytes: refused before anything is allocated.
  CHECK(contains(error_of(std::string(kHdrHeader) + "-Y 16777216 +X 7\n", "h.hdr"),
                 "larger than RTK reads"));
  CHECK(contains(error_of(std::string(kHdrHeader) + "-Y 4000 +X 4000\n\x02\x02\x0f\xa0", "h.hdr"),
                 "truncated"));
  // A run-length scanline cut short (stb_image 2.27 loops forever on it).
  const std::string cut("\x02\x02\x00\x08\x88\x01\x88\x01\x88\x01\x04\x01\x02", 13);
  CHECK(contains(error_of(std::string(kHdrHeader) + "-Y 1 +X 8\n" + cut, "h.hdr"),
                 "ends inside a run-length"));
  // A run of zero, a run longer than the scanline, a literal span past its end.
  const std::string marker("\x02\x02\x00\x08", 4);
  for (const std::string& plane :
       {std::string("\x00", 1), std::string("\x89\x01", 2), std::string("\x09", 1)})
    CHECK(contains(
        error_of(std::string(kHdrHeader) + "-Y 1 +X 8\n" + marker + plane + std::string(64, '\x01'),
                 "h.hdr"),
        "corrupt run-length"));
  CHECK(
      contains(error_of(std::string(kHdrHeader) + "-Y 2 +Z 2\n" + std::string(16, '\x01'), "h.hdr"),
               "resolution"));
  CHECK(
      contains(error_of("#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\nabcd", "h.hdr"), "xyze"));
  CHECK(contains(error_of("#?RADIANCE\n" + std::string(100000, 'x'), "h.hdr"), "header"));
  // A flat file that stores its rows bottom up.
  const DecodedImage up = decode_image(
      std::string(kHdrHeader) + "+Y 2 +X 1\n" + std::string("\x80\x00\x00\x81\x00\x80\x00\x81", 8),
      "u.hdr");
  CHECK(up.image.at(0, 1) == Color(1, 0, 0));
  CHECK(up.image.at(0, 0) == Color(0, 1, 0));
}

TEST_CASE("lib_image: PNG and JPEG through libpng and libjpeg, and their damaged forms") {
  const Image image = pattern(19, 7);
  const std::vector<unsigned char> rgb = bytes_of(image);
  std::string png, jpg;
  REQUIRE(stbi_write_png_to_func(append, &png, 19, 7, 3, rgb.data(), 19 * 3));
  REQUIRE(stbi_write_jpg_to_func(append, &jpg, 19, 7, 3, rgb.data(), 100));
  const DecodedImage p = decode_image(png, "a.png");
  CHECK(!p.linear);
  CHECK(p.image.pixels == image.pixels);
  const DecodedImage j = decode_image(jpg, "a.jpg");
  REQUIRE(j.image.width == 19);
  REQUIRE(j.image.height == 7);
  CHECK(std::fabs(j.image.at(10, 3).g - image.at(10, 3).g) < 0.1f);  // lossy, but close
  check_every_prefix_fails(png, "a.png");
  // libjpeg would fill a truncated file with grey and warn: here it is an error.
  for (size_t n : {size_t(2), size_t(20), jpg.size() / 2, jpg.size() - 2})
    CHECK(!error_of(std::string_view(jpg).substr(0, n), "a.jpg").empty());
  // An IHDR (with a correct checksum) claiming 30000 x 30000 pixels in a file of a hundred
  // bytes: refused after libpng read the header and before it is asked for pixels (the fuzzer
  // found that libpng's memory was not released on this way out).
  std::string huge = png;
  for (int k : {16, 20}) huge.replace(static_cast<size_t>(k), 4, std::string("\0\0\x75\x30", 4));
  const uint32_t crc = crc32(std::string_view(huge).substr(12, 17));
  for (int k = 0; k < 4; ++k) huge[29 + k] = static_cast<char>(crc >> (24 - 8 * k));
  CHECK(contains(error_of(huge, "big.png"), "30000 x 30000 pixels is larger than RTK reads"));
}

TEST_CASE("lib_image: TGA, plain and run-length, every origin, and damaged headers") {
  const Image image = pattern(9, 4);
  const std::vector<unsigned char> rgb = bytes_of(image);
  std::string rle;
  REQUIRE(stbi_write_tga_to_func(append, &rle, 9, 4, 3, rgb.data()));
  CHECK(decode_image(rle, "a.tga").image.pixels == image.pixels);
  check_every_prefix_fails(rle, "a.tga");
  // Plain true colour, top-left origin, BGR bytes.
  std::string plain("\0\0\2\0\0\0\0\0\0\0\0\0\x09\0\x04\0\x18\x20", 18);
  for (int i = 0; i < 36; ++i)
    plain += {char(rgb[3 * i + 2]), char(rgb[3 * i + 1]), char(rgb[3 * i])};
  CHECK(decode_image(plain, "p.TGA").image.pixels == image.pixels);
  check_every_prefix_fails(plain, "p.tga");
  std::string bad_type = plain;
  bad_type[2] = 7;
  CHECK(contains(error_of(bad_type, "p.tga"), "image type 7"));
  std::string bad_bits = plain;
  bad_bits[16] = 12;
  CHECK(contains(error_of(bad_bits, "p.tga"), "12 bits"));
  // A colour-mapped file whose index is outside its map.
  std::string mapped("\0\1\1\0\0\2\0\x18\0\0\0\0\x01\0\x01\0\x08\x20", 18);
  mapped += std::string("\1\2\3\4\5\6", 6) + "\5";
  CHECK(contains(error_of(mapped, "m.tga"), "colour index 5"));
  mapped.back() = 1;
  CHECK(decode_image(mapped, "m.tga").image.at(0, 0) == Color(6, 5, 4) / 255.0f);
}

TEST_CASE("lib_image: PPM, PGM and PFM headers and data are checked against each other") {
  const std::string ppm =
      std::string("P6\n# a comment\n2 1\n255\n") + std::string("\x00\x80\xff\x10\x20\x30", 6);
  const DecodedImage p = decode_image(ppm, "a.ppm");
  CHECK(p.image.at(0, 0) == Color(0, 128, 255) / 255.0f);
  check_every_prefix_fails(ppm, "a.ppm");
  const DecodedImage g = decode_image(std::string("P5 1 1 1000\n\x01\xf4", 14), "g.pgm");
  CHECK(g.image.at(0, 0) == Color(0.5f));
  CHECK(contains(error_of("P6\n2 1\n0\n", "a.ppm"), "maximum value"));
  CHECK(contains(error_of("P6\n99999 1\n255\n", "a.ppm"), "width"));
  CHECK(contains(error_of("P6\n-2 1\n255\n", "a.ppm"), "width"));
  const float big[3] = {1.0f, 2.0f, 3.0f};
  const std::string pfm = "PF\n1 1\n-1\n" + std::string(reinterpret_cast<const char*>(big), 12);
  CHECK(decode_image(pfm, "a.pfm").image.at(0, 0) == Color(1, 2, 3));
  check_every_prefix_fails(pfm, "a.pfm");
  CHECK(contains(error_of("PF\n1 1\nnan\n" + std::string(12, '\0'), "a.pfm"), "scale"));
}

TEST_CASE("lib_image: what is not an image is refused with the formats RTK reads") {
  CHECK(contains(error_of("", "e.png"), "empty"));
  CHECK(contains(error_of("BM\x10\0\0\0", "a.bmp"), "not an image RTK reads"));
  CHECK(contains(error_of("GIF89a", "a.gif"), "PNG, JPEG, TGA"));
  CHECK_THROWS_AS(read_image_file("/nonexistent_dir_rtk/y.hdr"), FileError);
  CHECK_THROWS_AS(read_image_file("/dev/zero"), FileError);  // a device is not read at all
}
