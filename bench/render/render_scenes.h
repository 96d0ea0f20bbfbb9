// Scenes that the renderer's benchmarks share: the project's Cornell box, and a real mesh from
// the shared scenes folder ($RTK_SCENES) made neutral (every triangle white-ish matte, lit by a
// uniform sky, the camera framing its bounding box), so that the mesh's geometry, not its
// materials, sets the workload.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <memory>
#include <optional>

#include "13_lights/distant_light.h"
#include "scene/obj_scene.h"
#include "scene/scene_script.h"

namespace rtk::bench {

/// scenes/cornell_box/cornell_box.ecs, read once.
inline const SceneScript& cornell_box_script() {
  static const SceneScript script = [] {
    SceneScript s;
    read_script_file(std::filesystem::path(RTK_SOURCE_DIR) / "scenes/cornell_box/cornell_box.ecs",
                     s);
    return s;
  }();
  return script;
}

/// $RTK_SCENES/<relative>, or nothing when the variable is unset or the file is absent.
inline std::optional<std::filesystem::path> shared_scene(const char* relative) {
  const char* root = std::getenv("RTK_SCENES");
  if (!root) return std::nullopt;
  const std::filesystem::path path = std::filesystem::path(root) / relative;
  if (!std::filesystem::exists(path)) return std::nullopt;
  return path;
}

/// The mesh at `path` in 0.8 grey matte under a sky of radiance 1, seen from `view` (a
/// direction from the box's centre, in units of the box's diagonal) with a 40 degree field.
inline RenderScene grey_mesh_under_sky(const std::filesystem::path& path, Vec3f view) {
  RenderScene s;
  load_obj_scene(path, s);
  Material grey;
  grey.prototype = Lambertian{Color(0.8f)};
  const uint32_t m = s.add_material(grey);
  for (auto& t : s.triangle_material) t = m;
  for (auto& l : s.triangle_light) l = kNoLight;
  s.lights.clear();
  s.add_light(std::make_shared<AmbientLight>(Color(1.0f)));
  const Box3f box = s.mesh.bounds();
  const Vec3f centre = (box.lower + box.upper) * 0.5f;
  const float size = length(box.upper - box.lower);
  s.camera.look_at = centre;
  s.camera.position = centre + view * size;
  s.camera.fov_degrees = 40.0f;
  return s;
}

}  // namespace rtk::bench
