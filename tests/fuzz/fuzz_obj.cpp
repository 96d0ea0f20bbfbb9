// libFuzzer target for the OBJ loader (lib/io/obj_loader.h): any bytes either load or throw
// rtk::FileError, never crash, hang or trip a sanitizer; and what loads is a sound mesh that
// survives a write and a reload unchanged. Built with clang only (RTK_FUZZ, tests/fuzz/run.sh).
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "io/file_error.h"
#include "io/obj_loader.h"
#include "io/obj_writer.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  rtk::TriangleMesh mesh;
  try {
    mesh = rtk::parse_obj(text, "fuzz.obj");
  } catch (const rtk::FileError&) {
    return 0;  // a clear refusal is a correct answer
  }
  // Whatever loads must be usable: indices in range, coordinates finite.
  for (const auto& tri : mesh.triangles)
    for (uint32_t index : tri)
      if (index >= mesh.vertices.size()) std::abort();
  for (const rtk::Vec3f& v : mesh.vertices)
    if (!rtk::is_finite(v)) std::abort();
  // And it must mean the same after a round trip through our own writer.
  const rtk::TriangleMesh again = rtk::parse_obj(rtk::format_obj(mesh), "again.obj");
  if (!(again.vertices == mesh.vertices) || again.triangles != mesh.triangles) std::abort();
  return 0;
}
