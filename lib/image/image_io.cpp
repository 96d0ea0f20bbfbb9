#include "image/image_io.h"

#include <stb/stb_image_write.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "image/image_decode.h"
#include "image/image_exr.h"
#include "io/read_file.h"

namespace rtk {

namespace {

std::string extension_of(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\"), dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

// stb_image_write's callback: append to the file's bytes in memory.
void append_to(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

std::vector<unsigned char> to_8bit(const Image& image, const ToneMap& tone) {
  std::vector<unsigned char> bytes(image.pixels.size() * 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i) {
    bytes[3 * i + 0] = tone.to_8bit(image.pixels[i].r);
    bytes[3 * i + 1] = tone.to_8bit(image.pixels[i].g);
    bytes[3 * i + 2] = tone.to_8bit(image.pixels[i].b);
  }
  return bytes;
}

uint32_t byteswap32(uint32_t v) {
  return (v >> 24) | ((v >> 8) & 0xff00u) | ((v << 8) & 0xff0000u) | (v << 24);
}
uint32_t to_little_endian(uint32_t v) {
  return std::endian::native == std::endian::little ? v : byteswap32(v);
}

// [image-pfm]
// PFM: a text header ("PF", "width height", and a scale whose sign gives the byte order: -1
// for little-endian), then float RGB triples, the bottom row first.
void write_pfm(std::string& file, const Image& image) {
  file += "PF\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n-1.0\n";
  std::vector<uint32_t> row(static_cast<std::size_t>(image.width) * 3);
  for (int y = image.height - 1; y >= 0; --y) {
    for (int x = 0; x < image.width; ++x) {
      const Color& c = image.at(x, y);
      const float channels[3] = {c.r, c.g, c.b};
      for (int k = 0; k < 3; ++k)
        row[3 * x + k] = to_little_endian(std::bit_cast<uint32_t>(channels[k]));
    }
    file.append(reinterpret_cast<const char*>(row.data()), row.size() * sizeof(uint32_t));
  }
}
// [image-pfm]

}  // namespace

ImageFormat image_format_from_path(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == ".png") return ImageFormat::png;
  if (ext == ".tga") return ImageFormat::tga;
  if (ext == ".ppm") return ImageFormat::ppm;
  if (ext == ".hdr") return ImageFormat::hdr;
  if (ext == ".pfm") return ImageFormat::pfm;
  if (ext == ".exr") return ImageFormat::exr;
  throw std::invalid_argument("cannot tell the image format of '" + path +
                              "' from its extension '" + ext +
                              "' (supported: .png .tga .ppm .hdr .pfm .exr)");
}

void write_image(const std::string& path, const Image& image, const ToneMap& tone) {
  const ImageFormat format = image_format_from_path(path);
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() !=
          static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw std::invalid_argument("cannot write '" + path +
                                "': the image is empty or its size does not match its pixels");
  // The file is made in memory and written all at once (lib/io's write_file): a reader never
  // sees half an image, and a failed write leaves what was there before.
  std::string file;
  int ok = 1;
  switch (format) {
    case ImageFormat::png: {
      const auto bytes = to_8bit(image, tone);
      ok = stbi_write_png_to_func(append_to, &file, image.width, image.height, 3, bytes.data(),
                                  image.width * 3);
      break;
    }
    case ImageFormat::tga: {
      const auto bytes = to_8bit(image, tone);
      ok = stbi_write_tga_to_func(append_to, &file, image.width, image.height, 3, bytes.data());
      break;
    }
    case ImageFormat::ppm: {
      const auto bytes = to_8bit(image, tone);
      file += "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
      file.append(bytes.begin(), bytes.end());
      break;
    }
    case ImageFormat::hdr:
      ok = stbi_write_hdr_to_func(append_to, &file, image.width, image.height, 3,
                                  &image.pixels[0].r);
      break;
    case ImageFormat::pfm:
      write_pfm(file, image);
      break;
    case ImageFormat::exr:
      file = encode_exr(image);
      break;
  }
  if (!ok) throw std::runtime_error("stb_image_write failed to encode '" + path + "'");
  write_file(path, file);
}

Image read_image(const std::string& path) { return read_image_file(path).image; }

}  // namespace rtk
