// libFuzzer target for MTL libraries (scene/mtl_file.h): any bytes give materials or a
// FileError with a line, never a crash, a hang or a sanitizer report; every material read is
// named and in the scene.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "io/file_error.h"
#include "scene/mtl_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  rtk::RenderScene scene;
  try {
    const auto names = rtk::read_mtl_text(text, "fuzz_mtl/lib.mtl", scene);
    for (const auto& [name, index] : names)
      if (index >= scene.materials.size()) std::abort();
  } catch (const rtk::FileError& e) {
    if (e.line() == 0) std::abort();  // every MTL error has a line
  }
  return 0;
}
