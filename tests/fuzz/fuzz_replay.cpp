// libFuzzer target for the replay file readers (lib/io/replay_files.h): any bytes are a
// .rays, .hits or .occl file, or a FileError; records read back unchanged.
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string_view>

#include "io/file_error.h"
#include "io/replay_files.h"

namespace {

template <class Parse, class Format>
void check(std::string_view bytes, Parse parse, Format format) {
  try {
    const auto records = parse(bytes, "fuzz");
    // A file that reads must be exactly the file its records write.
    if (format(records) != bytes) std::abort();
  } catch (const rtk::FileError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  check(bytes, rtk::parse_rays, [](const auto& r) { return rtk::format_rays(r); });
  check(bytes, rtk::parse_hits, [](const auto& r) { return rtk::format_hits(r); });
  check(bytes, rtk::parse_occlusion, [](const auto& r) { return rtk::format_occlusion(r); });
  return 0;
}
