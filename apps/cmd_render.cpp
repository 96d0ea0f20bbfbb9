// `rtk render`: reads the guide's options (command scripts with -c, then the command line
// itself, left to right), hands the scene to chapter 14's device, which builds the kernels the
// scene needs, renders a frame with chapter 13's path tracer and writes every -o image. Also
// the guide's short form `rtk -c scene.ecs -o out.png`.
#include <cstdio>
#include <string>
#include <thread>

#include "14_device/device.h"
#include "commands.h"
#include "device_objects.h"
#include "image/image_io.h"
#include "interrupt.h"
#include "options.h"
#include "output_checks.h"
#include "render_kernels/choose_kernels.h"
#include "scene/scene_script.h"
#include "viewer.h"

namespace rtk::cli {

int run_render(std::span<const std::string_view> args, bool viewer_without_output) {
  // Step 1: the scene and options, scripts and command line read left to right.
  SceneScript script;
  script.options.progress = true;
  ViewerOptions viewer;  // -frames, -screenshot: the viewer's own (chapter 15)
  const std::vector<std::string_view> script_args = take_viewer_options(args, viewer);
  read_script_args(script_args, script, [](const std::string& w) { std::fprintf(stderr, "rtk render: warning: %s\n", w.c_str()); });
  // No -o: the guide's interactive mode, the viewer (chapter 15), for `rtk -c` and `rtk view`.
  if (script.outputs.empty() && viewer_without_output) return run_viewer(script, viewer);
  if (script.outputs.empty())
    throw UsageError("no -o FILE given: rtk render writes images (.png .tga .ppm .hdr .pfm); "
                     "`rtk -c SCENE.ecs` or `rtk view` without -o opens the interactive viewer");
  if (viewer.frames > 0) throw UsageError("-frames and -screenshot belong to the viewer (no -o)");
  // Every -o was checked where it was read (its folder exists and may be written); its format
  // is checked here, before any work.
  for (const auto& out : script.outputs) {
    try {
      image_format_from_path(out.string());
    } catch (const std::exception& e) {
      throw UsageError(std::string("-o: ") + e.what());
    }
  }
  RenderOptions& options = script.options;
  if (options.threads == 0) options.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

  if (script.scene.lights.empty() && !options.eye_light)
    std::fprintf(stderr, "rtk render: warning: the scene has no light; the image will be black "
                         "(add one, e.g. -ambientlight 1 1 1, or use -renderer debug)\n");

  // Step 2: the device (chapter 14), whose scenes are traced by the kernels -kernels names,
  // and the script's scene imported into it: the commit builds what the scene needs (RTK's
  // motion structure only if it moves).
  Device device([](const std::string& w) { std::fprintf(stderr, "rtk render: warning: %s\n", w.c_str()); },
                kernel_factory(script.kernels));
  // What the device refuses names the place where the option was given (-accel, -tri, and
  // the camera's -vp, -vi, -vu, ...).
  const Handle scene = at_given_place(script, {"-kernels", "-isa", "-accel", "-tri"}, [&] {
    return commit_scene(device, script, options.threads);
  });
  std::printf("scene: %zu triangles, %zu materials, %zu lights%s\n", script.scene.mesh.size(),
              script.scene.materials.size(), script.scene.lights.size(),
              script.scene.has_motion() ? ", moving" : "");
  std::printf("kernels: %s\n", device.kernels_summary(scene).c_str());
  flush_stdout();

  // Step 3: the camera, the renderer and the framebuffer as device objects, and the frame.
  const Handle camera =
      at_given_place(script, {"-vi", "-vp", "-vu", "-fov", "-radius", "-focaldistance"},
                     [&] { return commit_camera(device, script.scene.camera); });
  const Handle renderer = commit_renderer(device, options);
  const Handle framebuffer = commit_framebuffer(device, options.width, options.height);
  // SIGINT or SIGTERM from here on stops the render at the next tile (chapter 13), and what
  // was rendered is written.
  const Interrupt interrupt;
  const RenderStats stats =
      device.render_frame(renderer, camera, scene, framebuffer, interrupt.flag());
  if (stats.stopped())
    std::fprintf(stderr,
                 "rtk render: interrupted by %s: %llu of %llu tiles rendered; writing them\n",
                 interrupt.signal_name(), static_cast<unsigned long long>(stats.tiles_done),
                 static_cast<unsigned long long>(stats.tiles));
  std::printf("render: %dx%d, %d spp, depth %d, %d threads, seed %u: %.3f s, %.3g samples/s, "
              "%.3g Mrays/s, %.0f%% of thread time in ray queries\n",
              options.width, options.height, options.spp, options.max_depth, options.threads,
              options.seed, stats.seconds, stats.samples_per_second(), stats.rays_per_second() * 1e-6,
              100.0 * stats.kernel_share());
  if (stats.invalid_samples > 0)
    std::fprintf(stderr, "rtk render: warning: %llu samples were not finite and were dropped\n",
                 static_cast<unsigned long long>(stats.invalid_samples));
  for (const auto& out : script.outputs) {
    device.write_image(framebuffer, out.string(), script.tone);
    std::printf("wrote %s\n", out.string().c_str());
  }
  return stats.stopped() ? interrupt.exit_status() : 0;
}

}  // namespace rtk::cli
