// libFuzzer target for lib/image's reader (image/image_decode.h): any bytes are an image or a
// FileError, never a hang, a crash, a read past the buffer or a sanitizer report; an image
// that decodes has the size it says and no more pixels than the limits allow. The name ends in
// .tga so that bytes without a signature reach the TGA reader too.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "image/image_decode.h"
#include "io/file_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    const rtk::DecodedImage d = rtk::decode_image(bytes, "fuzz.tga");
    const rtk::Image& image = d.image;
    if (image.width < 1 || image.height < 1 || image.width > rtk::kMaxImageSide ||
        image.height > rtk::kMaxImageSide ||
        image.pixels.size() != static_cast<size_t>(image.width) * static_cast<size_t>(image.height))
      std::abort();
  } catch (const rtk::FileError&) {
    // a clear refusal is a correct answer
  }
  return 0;
}
