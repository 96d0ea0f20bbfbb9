// libFuzzer target for scene scripts (scene/scene_script.h): any bytes are a script or a
// FileError, never a crash, a hang (the tokenizer once looped on a form feed) or a sanitizer
// report; the scene of a script that reads is consistent (RenderScene::validate). The files a
// script names are relative to a folder that does not exist, so -i, -c and -hdrilight fail
// cleanly; -o only checks its folder, and nothing is written.
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "io/file_error.h"
#include "scene/scene_script.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  rtk::SceneScript script;
  try {
    rtk::read_script_text(text, "fuzz_script_folder/scene.ecs", script);
  } catch (const rtk::FileError&) {
    return 0;
  }
  try {
    script.scene.validate();
  } catch (const std::invalid_argument&) {
    std::abort();
  }
  return 0;
}
