// lib/image tests: framebuffer accumulation, tone mapping, and the image files' round trips.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "image/framebuffer.h"
#include "image/image_decode.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "image/tonemap.h"

using namespace rtk;

namespace {
std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("rtk_image_" + name)).string();
}

// A 5 x 3 image (odd sizes catch row-stride bugs) with distinct values per pixel and channel.
Image test_image(float scale) {
  Image image(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x) image.at(x, y) = Color(x * 0.2f, y * 0.4f, (x + y) * 0.1f) * scale;
  return image;
}
}  // namespace

TEST_CASE("lib_image: the framebuffer averages weighted samples and drops bad ones") {
  Framebuffer fb(4, 2);
  fb.add_sample(1, 1, Color(1, 2, 3));
  fb.add_sample(1, 1, Color(3, 2, 1));
  fb.add_sample(2, 0, Color(4), 0.25f);
  fb.add_sample(2, 0, Color(0), 0.75f);
  fb.add_sample(0, 0, Color(NAN, 0, 0));
  fb.add_sample(0, 0, Color(INFINITY));
  const Image image = fb.resolve();
  CHECK(image.at(1, 1) == Color(2, 2, 2));
  CHECK(image.at(2, 0) == Color(1));
  CHECK(image.at(0, 0) == Color());  // no valid sample: black, not NaN
  CHECK(fb.invalid_samples() == 2);
  CHECK(fb.weight(1, 1) == 2.0f);
  const Framebuffer copy = fb;
  CHECK(copy.invalid_samples() == 2);
  fb.clear();
  CHECK(fb.resolve().at(1, 1) == Color());
  CHECK_THROWS_AS(fb.add_sample(4, 0, Color(1)), std::out_of_range);
  CHECK_THROWS_AS(Framebuffer(-1, 5), std::invalid_argument);
}

TEST_CASE("lib_image: tone mapping clamps, applies gamma and quantises by rounding") {
  const ToneMap linear;
  CHECK(linear.to_8bit(0.0f) == 0);
  CHECK(linear.to_8bit(1.0f) == 255);
  CHECK(linear.to_8bit(7.5f) == 255);  // clamped, not compressed
  CHECK(linear.to_8bit(-1.0f) == 0);
  CHECK(linear.to_8bit(NAN) == 0);
  CHECK(linear.to_8bit(INFINITY) == 255);
  CHECK(linear.to_8bit(0.5f) == 128);  // 127.5 rounds up
  CHECK(linear.to_8bit(100.0f / 255.0f) == 100);
  const ToneMap g22{2.2f};
  CHECK(g22.apply(0.5f) == doctest::Approx(std::pow(0.5f, 1 / 2.2f)));
  CHECK(g22.to_8bit(0.2177f) == 128);  // 0.2177^(1/2.2) = 0.50004
}

TEST_CASE("lib_image: float formats round-trip exactly (PFM) or to RGBE precision (HDR)") {
  const Image image = test_image(37.0f);  // values far above 1
  const std::string pfm = temp_path("a.pfm"), hdr = temp_path("a.hdr");
  write_image(pfm, image);
  write_image(hdr, image);
  const Image p = read_image(pfm), h = read_image(hdr);
  REQUIRE(p.width == 5);
  REQUIRE(p.height == 3);
  CHECK(p.pixels == image.pixels);  // bit for bit, rows back in top-down order
  REQUIRE(h.width == 5);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    const float m = max_component(image.pixels[i]);
    // RGBE shares one exponent e with max in [2^(e-1), 2^e) and 8-bit mantissas: each channel
    // is within one step 2^e / 256 < max / 128 of its value.
    for (int c = 0; c < 3; ++c)
      CHECK(std::fabs(h.pixels[i][c] - image.pixels[i][c]) <= m / 128.0f + 1e-6f);
  }
  // The PFM header and the first stored row (the bottom one) are where the format says.
  std::ifstream in(pfm, std::ios::binary);
  std::string magic, scale;
  int w = 0, hh = 0;
  in >> magic >> w >> hh >> scale;
  in.get();
  CHECK(magic == "PF");
  CHECK(scale == "-1.0");
  float first[3];
  in.read(reinterpret_cast<char*>(first), sizeof first);
  CHECK(Color(first[0], first[1], first[2]) == image.at(0, 2));
  in.close();
  std::remove(pfm.c_str());
  std::remove(hdr.c_str());
}

TEST_CASE("lib_image: OpenEXR round-trips the floats exactly, and a damaged file is an error") {
  const Image image = test_image(37.0f);
  const std::string exr = temp_path("a.exr");
  write_image(exr, image);
  const DecodedImage d = read_image_file(exr);
  CHECK(d.linear);
  REQUIRE(d.image.width == 5);
  REQUIRE(d.image.height == 3);
  CHECK(d.image.pixels == image.pixels);  // 32-bit floats, lossless compression
  // Cut short anywhere, the file is an error that names it, never an image of zeros.
  std::string bytes;
  {
    std::ifstream in(exr, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  for (size_t keep = 0; keep < bytes.size(); ++keep) {
    INFO(keep);
    CHECK_THROWS_WITH_AS(decode_image(std::string_view(bytes).substr(0, keep), "cut.exr"),
                         doctest::Contains("cut.exr"), std::runtime_error);
  }
  std::remove(exr.c_str());
}

TEST_CASE("lib_image: 8-bit formats round-trip the tone-mapped bytes") {
  const Image image = test_image(0.9f);
  for (const char* ext : {".png", ".tga", ".ppm", ".PNG"}) {
    const std::string path = temp_path(std::string("b") + ext);
    write_image(path, image);
    const Image back = read_image(path);
    REQUIRE(back.width == image.width);
    REQUIRE(back.height == image.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c)
        CHECK(back.pixels[i][c] == ToneMap{}.to_8bit(image.pixels[i][c]) / 255.0f);
    std::remove(path.c_str());
  }
  // With a gamma, the file holds the corrected values.
  const std::string path = temp_path("g.png");
  write_image(path, image, ToneMap{2.2f});
  CHECK(read_image(path).at(4, 2).r == ToneMap{2.2f}.to_8bit(image.at(4, 2).r) / 255.0f);
  std::remove(path.c_str());
}

TEST_CASE("lib_image: bad paths and extensions fail with a clear message") {
  const Image image = test_image(1.0f);
  try {
    write_image(temp_path("c.tiff"), image);
    FAIL("no exception");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()).find(".tiff") != std::string::npos);
    CHECK(std::string(e.what()).find(".exr") != std::string::npos);
    CHECK(std::string(e.what()).find(".png") != std::string::npos);
  }
  CHECK_THROWS_AS(write_image(temp_path("noextension"), image), std::invalid_argument);
  try {
    write_image("/nonexistent_dir_rtk/x.png", image);
    FAIL("no exception");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()).find("/nonexistent_dir_rtk/x.png") != std::string::npos);
  }
  CHECK_THROWS_AS(write_image(temp_path("d.png"), Image()), std::invalid_argument);
  CHECK_THROWS_AS(read_image("/nonexistent_dir_rtk/y.png"), std::runtime_error);
  CHECK_THROWS_AS(read_image("/nonexistent_dir_rtk/y.pfm"), std::runtime_error);
  // A file that is not an image.
  const std::string junk = temp_path("junk.png");
  std::ofstream(junk) << "not a png";
  CHECK_THROWS_AS(read_image(junk), std::runtime_error);
  std::remove(junk.c_str());
  const std::string bad_pfm = temp_path("junk.pfm");
  std::ofstream(bad_pfm) << "PF\n2 2\n-1.0\n1234";
  CHECK_THROWS_AS(read_image(bad_pfm), std::runtime_error);
  std::remove(bad_pfm.c_str());
  CHECK(image_format_from_path("dir.v2/out.Tga") == ImageFormat::tga);
  CHECK_THROWS_AS(image_format_from_path("dir.png/out"), std::invalid_argument);
}

TEST_CASE("lib_image: the relative RMS error against a reference") {
  const Image reference = test_image(1.0f);
  CHECK(relative_rms_error(reference, reference) == 0.0);
  // An image off by a factor (1 + e) everywhere is off by exactly e, whatever the scene.
  CHECK(relative_rms_error(test_image(1.25f), reference) == doctest::Approx(0.25).epsilon(1e-6));
  CHECK(relative_rms_error(test_image(0.0f), reference) == doctest::Approx(1.0));
  // One value changed: sqrt(d^2 / sum r^2), summed by hand.
  double norm = 0;
  for (const Color& c : reference.pixels) norm += double(c.r) * c.r + double(c.g) * c.g + double(c.b) * c.b;
  Image one = reference;
  one.at(4, 2).g += 0.5f;
  CHECK(relative_rms_error(one, reference) == doctest::Approx(std::sqrt(0.25 / norm)));
  // What has no meaning is refused: another size, values that are not finite, a black reference.
  CHECK_THROWS_WITH_AS(relative_rms_error(Image(4, 3), reference), "the image is 4 x 3, the reference 5 x 3",
                       std::invalid_argument);
  Image nan = reference;
  nan.at(1, 2).b = std::nanf("");
  CHECK_THROWS_AS(relative_rms_error(nan, reference), std::invalid_argument);
  CHECK_THROWS_AS(relative_rms_error(reference, nan), std::invalid_argument);
  CHECK_THROWS_WITH_AS(relative_rms_error(reference, test_image(0.0f)), "the reference is black",
                       std::invalid_argument);
}
