// Scenes and helpers shared by the renderer's tests.
#pragma once

#include <cmath>
#include <filesystem>
#include <string>

#include "11_sampling/warp.h"
#include "14_pathtracer/render.h"
#include "14_pathtracer/scene.h"
#include "image/image.h"
#include "14_pathtracer/accel_kernels.h"
#include "scene/scene_script.h"

namespace rtk::test {

// The Cornell box shipped with RTK (scenes/cornell_box), through its .ecs script.
inline SceneScript cornell_box() {
  SceneScript script;
  read_script_file(std::filesystem::path(RTK_SOURCE_DIR) / "scenes/cornell_box/cornell_box.ecs", script);
  return script;
}

// A white (reflectance 1) Lambertian material.
inline uint32_t white_material(RenderScene& scene) {
  Material m;
  m.name = "white";
  m.prototype = Lambertian{Color(1.0f)};
  return scene.add_material(m);
}

// Adds a latitude-longitude sphere (convex: every face sees only the outside).
inline void add_sphere(RenderScene& scene, Vec3f c, float r, int rings, int segments, uint32_t material) {
  const uint32_t base = static_cast<uint32_t>(scene.mesh.vertices.size());
  for (int i = 0; i <= rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const float theta = i * kPi / rings, phi = j * 2 * kPi / segments;
      scene.mesh.vertices.push_back(c + Vec3f(std::sin(theta) * std::cos(phi), std::cos(theta),
                                              std::sin(theta) * std::sin(phi)) * r);
    }
  auto at = [&](int i, int j) { return base + static_cast<uint32_t>(i * segments + j % segments); };
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      for (const auto& tri : {std::array<uint32_t, 3>{at(i, j), at(i + 1, j), at(i + 1, j + 1)},
                              std::array<uint32_t, 3>{at(i, j), at(i + 1, j + 1), at(i, j + 1)}}) {
        scene.mesh.triangles.push_back(tri);
        scene.triangle_material.push_back(material);
        scene.triangle_light.push_back(kNoLight);
      }
    }
}

// Adds the quad p, p+u, p+u+v, p+v as two triangles.
inline void add_quad(RenderScene& scene, Vec3f p, Vec3f u, Vec3f v, uint32_t material) {
  const uint32_t b = static_cast<uint32_t>(scene.mesh.vertices.size());
  for (Vec3f q : {p, p + u, p + u + v, p + v}) scene.mesh.vertices.push_back(q);
  for (const auto& tri : {std::array<uint32_t, 3>{b, b + 1, b + 2}, std::array<uint32_t, 3>{b, b + 2, b + 3}}) {
    scene.mesh.triangles.push_back(tri);
    scene.triangle_material.push_back(material);
    scene.triangle_light.push_back(kNoLight);
  }
}

// Renders samples [0, spp) of a scene.
inline Image render_image(const RenderScene& scene, const RenderOptions& options, const AccelConfig& config = {}) {
  const AccelKernels kernels(scene, config);
  const Renderer renderer(scene, kernels, options);
  Framebuffer fb(options.width, options.height);
  renderer.render(fb);
  return fb.resolve();
}

}  // namespace rtk::test
