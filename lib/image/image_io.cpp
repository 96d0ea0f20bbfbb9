#include "image/image_io.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

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

// A file opened for writing that reports the system's reason when it fails.
struct File {
  std::FILE* f = nullptr;
  std::string path;
  File(const std::string& p, const char* mode) : f(std::fopen(p.c_str(), mode)), path(p) {
    if (!f)
      throw std::runtime_error("cannot open '" + p + "' for " +
                               (mode[0] == 'w' ? "writing" : "reading") + ": " +
                               std::strerror(errno));
  }
  ~File() {
    if (f) std::fclose(f);
  }
  File(const File&) = delete;
  File& operator=(const File&) = delete;
  void close() {
    const bool failed = std::ferror(f) != 0;
    const int rc = std::fclose(f);
    f = nullptr;
    if (failed || rc != 0) throw std::runtime_error("error while writing '" + path + "'");
  }
};

// stb_image_write's callback: append to our FILE.
void write_to_file(void* context, void* data, int size) {
  std::fwrite(data, 1, static_cast<std::size_t>(size), static_cast<std::FILE*>(context));
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
void write_pfm(File& file, const Image& image) {
  std::fprintf(file.f, "PF\n%d %d\n-1.0\n", image.width, image.height);
  std::vector<uint32_t> row(static_cast<std::size_t>(image.width) * 3);
  for (int y = image.height - 1; y >= 0; --y) {
    for (int x = 0; x < image.width; ++x) {
      const Color& c = image.at(x, y);
      const float channels[3] = {c.r, c.g, c.b};
      for (int k = 0; k < 3; ++k)
        row[3 * x + k] = to_little_endian(std::bit_cast<uint32_t>(channels[k]));
    }
    std::fwrite(row.data(), sizeof(uint32_t), row.size(), file.f);
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
  throw std::invalid_argument("cannot tell the image format of '" + path +
                              "' from its extension '" + ext +
                              "' (supported: .png .tga .ppm .hdr .pfm)");
}

void write_image(const std::string& path, const Image& image, const ToneMap& tone) {
  const ImageFormat format = image_format_from_path(path);
  if (image.width <= 0 || image.height <= 0 ||
      image.pixels.size() !=
          static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height))
    throw std::invalid_argument("cannot write '" + path +
                                "': the image is empty or its size does not match its pixels");
  File file(path, "wb");
  int ok = 1;
  switch (format) {
    case ImageFormat::png: {
      const auto bytes = to_8bit(image, tone);
      ok = stbi_write_png_to_func(write_to_file, file.f, image.width, image.height, 3, bytes.data(),
                                  image.width * 3);
      break;
    }
    case ImageFormat::tga: {
      const auto bytes = to_8bit(image, tone);
      ok =
          stbi_write_tga_to_func(write_to_file, file.f, image.width, image.height, 3, bytes.data());
      break;
    }
    case ImageFormat::ppm: {
      const auto bytes = to_8bit(image, tone);
      std::fprintf(file.f, "P6\n%d %d\n255\n", image.width, image.height);
      std::fwrite(bytes.data(), 1, bytes.size(), file.f);
      break;
    }
    case ImageFormat::hdr:
      ok = stbi_write_hdr_to_func(write_to_file, file.f, image.width, image.height, 3,
                                  &image.pixels[0].r);
      break;
    case ImageFormat::pfm:
      write_pfm(file, image);
      break;
  }
  if (!ok) throw std::runtime_error("stb_image_write failed to encode '" + path + "'");
  file.close();
}

namespace {

Image read_pfm(const std::string& path) {
  File file(path, "rb");
  char kind[3] = {0, 0, 0};
  int width = 0, height = 0;
  double scale = 0;
  if (std::fscanf(file.f, "%2s %d %d %lf", kind, &width, &height, &scale) != 4 ||
      (std::strcmp(kind, "PF") != 0 && std::strcmp(kind, "Pf") != 0) || width <= 0 || height <= 0 ||
      width > 32768 || height > 32768 || scale == 0.0)
    throw std::runtime_error("'" + path + "' is not a PFM file (bad header)");
  std::fgetc(file.f);  // the single whitespace character that ends the header
  const int channels = kind[1] == 'F' ? 3 : 1;
  const bool little = scale < 0;
  std::vector<uint32_t> data(static_cast<std::size_t>(width) * height * channels);
  if (std::fread(data.data(), sizeof(uint32_t), data.size(), file.f) != data.size())
    throw std::runtime_error("'" + path + "' is truncated");
  const bool swap = little != (std::endian::native == std::endian::little);
  Image image(width, height);
  for (int row = 0; row < height; ++row)
    for (int x = 0; x < width; ++x) {
      float v[3];
      for (int k = 0; k < channels; ++k) {
        uint32_t bits = data[(static_cast<std::size_t>(row) * width + x) * channels + k];
        v[k] = std::bit_cast<float>(swap ? byteswap32(bits) : bits);
      }
      // Rows are stored bottom-up.
      image.at(x, height - 1 - row) = channels == 3 ? Color(v[0], v[1], v[2]) : Color(v[0]);
    }
  return image;
}

}  // namespace

Image read_image(const std::string& path) {
  const std::string ext = extension_of(path);
  if (ext == ".pfm") return read_pfm(path);
  File file(path, "rb");  // for the system's reason when the file is missing
  int w = 0, h = 0, n = 0;
  if (stbi_is_hdr_from_file(file.f)) {
    std::unique_ptr<float, void (*)(void*)> data(stbi_loadf_from_file(file.f, &w, &h, &n, 3),
                                                 stbi_image_free);
    if (!data) throw std::runtime_error("cannot read '" + path + "': " + stbi_failure_reason());
    Image image(w, h);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
      image.pixels[i] = {data.get()[3 * i], data.get()[3 * i + 1], data.get()[3 * i + 2]};
    return image;
  }
  std::unique_ptr<unsigned char, void (*)(void*)> data(stbi_load_from_file(file.f, &w, &h, &n, 3),
                                                       stbi_image_free);
  if (!data) throw std::runtime_error("cannot read '" + path + "': " + stbi_failure_reason());
  Image image(w, h);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] =
        Color(data.get()[3 * i], data.get()[3 * i + 1], data.get()[3 * i + 2]) / 255.0f;
  return image;
}

}  // namespace rtk
