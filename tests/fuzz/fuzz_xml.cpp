// libFuzzer target for XML scenes (scene/xml_scene.h): any bytes are a scene or a FileError,
// never a crash (a nesting 12,000 deep once overflowed the stack), a hang, an allocation past
// the limits or a sanitizer report; the scene of a file that reads is consistent
// (RenderScene::validate). Included files are relative to a folder that does not exist.
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "io/file_error.h"
#include "scene/xml_scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  rtk::RenderScene scene;
  try {
    rtk::read_xml_scene_text(text, "fuzz_xml_folder/scene.xml", scene);
  } catch (const rtk::FileError&) {
    return 0;
  }
  try {
    scene.validate();
  } catch (const std::invalid_argument&) {
    std::abort();
  }
  return 0;
}
