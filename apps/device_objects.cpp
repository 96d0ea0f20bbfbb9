#include "device_objects.h"

namespace rtk::cli {

Handle commit_scene(Device& device, const SceneScript& script, int threads) {
  return commit_scene(device, script.scene, script, threads);
}

Handle commit_scene(Device& device, const RenderScene& render_scene, const SceneScript& script, int threads) {
  Handle scene = device.import_scene(render_scene);
  if (!script.accel.accel.empty()) device.set(scene, "accel", script.accel.accel);
  if (!script.accel.tri.empty()) device.set(scene, "tri", script.accel.tri);
  if (script.accel.isa) device.set(scene, "isa", std::string(isa_name(*script.accel.isa)));
  device.set(scene, "threads", threads);
  device.commit(scene);
  return scene;
}

Handle commit_camera(Device& device, const CameraParams& params) {
  Handle camera = device.new_camera(params.lens_radius > 0.0f ? "thinlens" : "pinhole");
  commit_camera(device, camera, params);
  return camera;
}

void commit_camera(Device& device, const Handle& camera, const CameraParams& params) {
  device.set(camera, "position", params.position);
  device.set(camera, "lookAt", params.look_at);
  device.set(camera, "up", params.up);
  device.set(camera, "fov", params.fov_degrees);
  device.set(camera, "rightHanded", params.right_handed ? 1 : 0);
  device.set(camera, "vignetting", params.vignetting ? 1 : 0);
  if (camera.type() == "thinlens") {
    device.set(camera, "radius", params.lens_radius);
    device.set(camera, "focalDistance", params.focal_distance);
  }
  device.commit(camera);
}

Handle commit_renderer(Device& device, const RenderOptions& options) {
  Handle renderer = device.new_renderer(options.eye_light ? "debug" : "pathtracer");
  device.set(renderer, "spp", options.spp);
  device.set(renderer, "seed", static_cast<int>(options.seed));
  device.set(renderer, "threads", options.threads);
  device.set(renderer, "tileSize", options.tile_size);
  device.set(renderer, "sampler",
             options.sampler == SamplerType::independent ? "independent" : "sobol");
  device.set(renderer, "filter", options.filter == FilterType::tent      ? "tent"
                                 : options.filter == FilterType::bspline ? "bspline"
                                                                         : "box");
  device.set(renderer, "filterRadius", options.filter_radius);
  device.set(renderer, "progress", options.progress ? 1 : 0);
  if (!options.eye_light) {
    device.set(renderer, "maxDepth", options.max_depth);
    device.set(renderer, "rrDepth", options.rr_depth);
    device.set(renderer, "minContribution", options.min_contribution);
  }
  device.commit(renderer);
  return renderer;
}

Handle commit_framebuffer(Device& device, int width, int height) {
  Handle framebuffer = device.new_framebuffer();
  commit_framebuffer(device, framebuffer, width, height);
  return framebuffer;
}

void commit_framebuffer(Device& device, const Handle& framebuffer, int width, int height) {
  device.set(framebuffer, "width", width);
  device.set(framebuffer, "height", height);
  device.commit(framebuffer);
}

}  // namespace rtk::cli
