// Chapter 15 benchmarks: what the device adds to a frame (the copy of the committed scene that
// carries the frame's camera, and the renderer set up per frame) against chapter 14's renderer
// called directly on the same scene, and what a scene commit costs (merging the shapes and
// building the acceleration structure). A small frame on a large scene is the worst case for
// the per-frame copy.
// Run: build/chapters/15_device/ch15_bench
#include <benchmark/benchmark.h>

#include <array>
#include <vector>

#include "14_pathtracer/render.h"
#include "13_lights/area_light.h"
#include "15_device/device.h"
#include "15_device/sphere_mesh.h"
#include "14_pathtracer/accel_kernels.h"

namespace {

using rtk::Device;
using rtk::Handle;

// A sphere of 2 * 512 * 255 triangles over a floor quad, under a quad light; 64 x 64 pixels,
// 1 sample, depth 2.
struct DeviceScene {
  Device d;
  Handle sphere, floor, light, scene, camera, renderer, framebuffer;
  DeviceScene() {
    sphere = d.new_shape("sphere");
    d.set(sphere, "numTheta", 256);
    d.set(sphere, "numPhi", 512);
    d.commit(sphere);
    floor = d.new_shape("trianglemesh");
    d.set(floor, "positions", std::vector<float>{-3, -1, -3, 3, -1, -3, 3, -1, 3, -3, -1, 3});
    d.set(floor, "indices", std::vector<int>{0, 2, 1, 0, 3, 2});
    d.commit(floor);
    light = d.new_light("quad");
    d.set(light, "P", rtk::Vec3f{-0.5f, 3, -0.5f});
    d.set(light, "U", rtk::Vec3f{1, 0, 0});
    d.set(light, "V", rtk::Vec3f{0, 0, 1});
    d.set(light, "L", rtk::Vec3f{10, 10, 10});
    d.commit(light);
    scene = d.new_scene();
    d.set(scene, "shapes", std::vector<Handle>{sphere, floor});
    d.set(scene, "lights", std::vector<Handle>{light});
    d.commit(scene);
    camera = d.new_camera("pinhole");
    d.set(camera, "position", rtk::Vec3f{0, 1, -4});
    d.set(camera, "lookAt", rtk::Vec3f{0, 0, 0});
    d.commit(camera);
    renderer = d.new_renderer("pathtracer");
    d.set(renderer, "maxDepth", 2);
    d.set(renderer, "threads", 2);
    d.commit(renderer);
    framebuffer = d.new_framebuffer();
    d.set(framebuffer, "width", 64);
    d.set(framebuffer, "height", 64);
    d.commit(framebuffer);
  }
};

// Frames through the device.
void BM_frame_device(benchmark::State& state) {
  DeviceScene s;
  for (auto _ : state) s.d.render_frame(s.renderer, s.camera, s.scene, s.framebuffer);
  state.SetItemsProcessed(state.iterations() * 64 * 64);  // pixels per second
}
BENCHMARK(BM_frame_device)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same frames with chapter 14's renderer on the same scene built by hand once: only the
// renderer's own per-frame set-up remains.
void BM_frame_direct(benchmark::State& state) {
  rtk::RenderScene scene;
  const rtk::SphereMesh sphere = rtk::tessellate_sphere({0, 0, 0}, 1.0f, 256, 512);
  const uint32_t grey = scene.add_material(rtk::Material{});
  scene.mesh.vertices = sphere.vertices;
  scene.normals = sphere.normals;
  for (const auto& t : sphere.triangles) {
    scene.mesh.triangles.push_back(t);
    scene.triangle_material.push_back(grey);
    scene.triangle_light.push_back(rtk::kNoLight);
  }
  const auto first = static_cast<uint32_t>(scene.mesh.vertices.size());
  for (rtk::Vec3f v : {rtk::Vec3f{-3, -1, -3}, rtk::Vec3f{3, -1, -3}, rtk::Vec3f{3, -1, 3}, rtk::Vec3f{-3, -1, 3}}) {
    scene.mesh.vertices.push_back(v);
    scene.normals.push_back({0, 0, 0});
  }
  for (std::array<uint32_t, 3> t : {std::array<uint32_t, 3>{0, 2, 1}, std::array<uint32_t, 3>{0, 3, 2}}) {
    scene.mesh.triangles.push_back({first + t[0], first + t[1], first + t[2]});
    scene.triangle_material.push_back(grey);
    scene.triangle_light.push_back(rtk::kNoLight);
  }
  rtk::Material lamp;
  lamp.prototype = rtk::Lambertian{rtk::Color(0.0f)};
  lamp.emission = rtk::Color(10.0f);
  const uint32_t lm = scene.add_material(lamp);
  for (auto& t : rtk::make_quad_light({-0.5f, 3, -0.5f}, {1, 0, 0}, {0, 0, 1}, rtk::Color(10.0f)))
    scene.add_triangle_light(t, lm);
  scene.camera.position = {0, 1, -4};
  scene.camera.look_at = {0, 0, 0};
  const rtk::AccelKernels kernels(scene, rtk::AccelConfig{});
  rtk::RenderOptions options;
  options.width = options.height = 64;
  options.max_depth = 2;
  options.threads = 2;
  rtk::Framebuffer fb(64, 64);
  for (auto _ : state) {
    const rtk::Renderer renderer(scene, kernels, options);  // as the device does per frame
    fb.clear();
    renderer.render(fb);
  }
  state.SetItemsProcessed(state.iterations() * 64 * 64);
  state.counters["triangles"] = double(scene.mesh.triangles.size());
}
BENCHMARK(BM_frame_direct)->Unit(benchmark::kMillisecond)->UseRealTime();

// A scene commit: merging the shapes' versions and building the acceleration structure.
void BM_commit_scene(benchmark::State& state) {
  DeviceScene s;
  for (auto _ : state) s.d.commit(s.scene);
  state.SetItemsProcessed(state.iterations() * (2 * 512 * 255 + 2 + 2));  // triangles per second
}
BENCHMARK(BM_commit_scene)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
