// PNG and JPEG through libpng and libjpeg(-turbo): maintained, fuzzed decoders with bounds
// checks of their own. RTK checks the dimensions before it asks them for the pixels, and turns
// their errors (and libjpeg's warnings, which would otherwise patch a damaged file with grey)
// into FileError.
// jpeglib.h uses size_t and FILE without including what declares them.
// clang-format off
#include <cstddef>
#include <cstdio>
#include <jpeglib.h>
// clang-format on
#include <png.h>

#include <csetjmp>
#include <cstdint>
#include <vector>

#include "image/image_decoders.h"

namespace rtk::image_detail {

namespace {

// A compressed format stores at most this many pixel bytes per byte of file: deflate's bound
// is 1032, and a JPEG needs at least two bits per 8 x 8 block of each component.
constexpr uint64_t kMaxExpansion = 1100;

void check_expansion(const std::string& name, uint64_t width, uint64_t height, size_t file_bytes) {
  if (width * height > kMaxExpansion * file_bytes + 4096)
    fail(name, "truncated or corrupt: " + std::to_string(file_bytes) + " bytes cannot hold a " +
                   std::to_string(width) + " x " + std::to_string(height) + " image");
}

DecodedImage from_rgb8(const std::vector<unsigned char>& rgb, int width, int height, int channels) {
  DecodedImage out{Image(width, height), false};
  for (size_t i = 0; i < out.image.pixels.size(); ++i) {
    const unsigned char* p = &rgb[i * channels];
    out.image.pixels[i] = channels == 3 ? Color(p[0], p[1], p[2]) / 255.0f : Color(p[0] / 255.0f);
  }
  return out;
}

// libjpeg reports errors through a callback that must not return: it jumps back to decode_jpeg
// with the message (C code cannot be unwound by a C++ exception).
struct JpegErrors {
  jpeg_error_mgr manager;
  std::jmp_buf back;
  char message[JMSG_LENGTH_MAX] = "";
};

void jpeg_error_exit(j_common_ptr info) {
  auto* errors = reinterpret_cast<JpegErrors*>(info->err);
  info->err->format_message(info, errors->message);
  std::longjmp(errors->back, 1);
}

// A warning (a premature end of the data, corrupt data that libjpeg would skip) is an error
// here: the decoder would otherwise fill what is missing with grey.
void jpeg_emit_message(j_common_ptr info, int level) {
  if (level < 0) jpeg_error_exit(info);
}

// A progressive JPEG may hold any number of scans, each a pass over the whole image; a file
// of a few kilobytes could keep the decoder busy for minutes.
constexpr int kMaxJpegScans = 1000;

struct JpegProgress {
  jpeg_progress_mgr manager;
};

void jpeg_count_scans(j_common_ptr info) {
  const auto* d = reinterpret_cast<j_decompress_ptr>(info);
  if (d->is_decompressor && d->input_scan_number > kMaxJpegScans) {
    auto* errors = reinterpret_cast<JpegErrors*>(info->err);
    std::snprintf(errors->message, sizeof errors->message, "more than %d progressive scans",
                  kMaxJpegScans);
    std::longjmp(errors->back, 1);
  }
}

}  // namespace

// libpng's simplified reader, released on every way out (the fuzzer found a dimension check
// that threw past a png_image_free).
struct PngReader {
  png_image png{};
  PngReader() { png.version = PNG_IMAGE_VERSION; }
  ~PngReader() { png_image_free(&png); }
  PngReader(const PngReader&) = delete;
  PngReader& operator=(const PngReader&) = delete;
};

DecodedImage decode_png(std::string_view bytes, const std::string& name) {
  // libpng stops reading after the last pixel; a file cut after it (its IEND chunk missing)
  // is still a truncated file.
  if (bytes.find(std::string_view("\0\0\0\0IEND\xae\x42\x60\x82", 12)) == std::string_view::npos)
    fail(name, "truncated: the PNG file has no IEND chunk");
  PngReader reader;
  png_image& png = reader.png;
  if (!png_image_begin_read_from_memory(&png, bytes.data(), bytes.size()))
    fail(name, std::string("not a valid PNG file: ") + png.message);
  check_dimensions(name, png.width, png.height);
  check_expansion(name, png.width, png.height, bytes.size());
  // 8-bit RGB out; 16-bit files without colour-space chunks are taken as sRGB, as 8-bit ones.
  png.format = PNG_FORMAT_RGB;
  png.flags |= PNG_IMAGE_FLAG_16BIT_sRGB;
  std::vector<unsigned char> rgb(PNG_IMAGE_SIZE(png));
  if (!png_image_finish_read(&png, nullptr, rgb.data(), 0, nullptr))
    fail(name, std::string("corrupt or truncated PNG data: ") + png.message);
  return from_rgb8(rgb, static_cast<int>(png.width), static_cast<int>(png.height), 3);
}

namespace {

// The pixels of a JPEG, or false with errors.message set. Every value this function changes
// after setjmp lives in the caller's frame (reached through references), so none is left
// undefined by the jump back.
struct JpegPixels {
  std::vector<unsigned char> bytes;
  int width = 0, height = 0, channels = 0;
};

bool read_jpeg_pixels(jpeg_decompress_struct& info, JpegErrors& errors, JpegProgress& progress,
                      std::string_view file, JpegPixels& out) {
  if (setjmp(errors.back)) return false;
  jpeg_create_decompress(&info);
  progress.manager.progress_monitor = jpeg_count_scans;
  info.progress = &progress.manager;
  jpeg_mem_src(&info, reinterpret_cast<const unsigned char*>(file.data()),
               static_cast<unsigned long>(file.size()));
  jpeg_read_header(&info, TRUE);
  const uint64_t w = info.image_width, h = info.image_height;
  if (w == 0 || h == 0 || w > unsigned(kMaxImageSide) || h > unsigned(kMaxImageSide) ||
      w * h > kMaxImagePixels || w * h > kMaxExpansion * file.size() + 4096) {
    std::snprintf(errors.message, sizeof errors.message,
                  "%u x %u pixels are more than the file or the limits allow", info.image_width,
                  info.image_height);
    return false;
  }
  // Grey stays grey; every colour space libjpeg knows becomes RGB.
  info.out_color_space = info.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
  jpeg_start_decompress(&info);
  out.width = static_cast<int>(info.output_width);
  out.height = static_cast<int>(info.output_height);
  out.channels = info.output_components;
  out.bytes.resize(static_cast<size_t>(out.width) * out.height * out.channels);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = &out.bytes[static_cast<size_t>(info.output_scanline) * out.width * out.channels];
    jpeg_read_scanlines(&info, &row, 1);
  }
  jpeg_finish_decompress(&info);
  return true;
}

}  // namespace

DecodedImage decode_jpeg(std::string_view bytes, const std::string& name) {
  jpeg_decompress_struct info{};
  JpegErrors errors;
  JpegProgress progress{};
  info.err = jpeg_std_error(&errors.manager);
  errors.manager.error_exit = jpeg_error_exit;
  errors.manager.emit_message = jpeg_emit_message;
  JpegPixels pixels;
  const bool ok = read_jpeg_pixels(info, errors, progress, bytes, pixels);
  jpeg_destroy_decompress(&info);
  if (!ok) fail(name, std::string("corrupt or truncated JPEG: ") + errors.message);
  return from_rgb8(pixels.bytes, pixels.width, pixels.height, pixels.channels);
}

}  // namespace rtk::image_detail
