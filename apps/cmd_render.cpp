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

namespace {
int render_output(SceneScript& script, std::span<const ScriptOutput> outputs);
}  // namespace

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
    throw UsageError("no -o FILE given: rtk render writes images (.png .tga .ppm .hdr .pfm .exr); "
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
  // As in Embree 1.1, each -o renders the state set up before it; what follows the last one
  // changes no image.
  if (!script.after_last_output.empty())
    std::fprintf(stderr,
                 "rtk render: warning: %s: options after the last -o change no image (each -o "
                 "renders what was set up before it)\n",
                 script.after_last_output.c_str());
  // Outputs named one after the other, with nothing between them, are one image.
  int status = 0;
  for (size_t first = 0; first < script.output_states.size() && status == 0;) {
    size_t last = first + 1;
    while (last < script.output_states.size() &&
           script.output_states[last].state == script.output_states[first].state)
      ++last;
    status = render_output(script, {script.output_states.data() + first, last - first});
    first = last;
  }
  return status;
}

namespace {

// Renders one image, the state of `outputs.front()`, and writes it to every file of `outputs`.
int render_output(SceneScript& script, std::span<const ScriptOutput> outputs) {
  const ScriptOutput& at = outputs.front();
  // The state at this -o; the script's given_at still names where options were given.
  SceneScript state;
  state.given_at = script.given_at;
  state.accel = at.accel;
  state.kernels = at.kernels;
  const RenderScene& scene_at = at.scene ? *at.scene : script.scene;
  RenderOptions options = at.options;
  if (options.threads == 0) options.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

  if (scene_at.lights.empty() && !options.eye_light)
    std::fprintf(stderr, "rtk render: warning: the scene has no light; the image will be black "
                         "(add one, e.g. -ambientlight 1 1 1, or use -renderer debug)\n");

  // Step 2: the device (chapter 14), whose scenes are traced by the kernels -kernels names,
  // and the script's scene imported into it: the commit builds what the scene needs (RTK's
  // motion structure only if it moves).
  Device device([](const std::string& w) { std::fprintf(stderr, "rtk render: warning: %s\n", w.c_str()); },
                kernel_factory(at.kernels));
  // What the device refuses names the place where the option was given (-accel, -tri, and
  // the camera's -vp, -vi, -vu, ...).
  const Handle scene = at_given_place(script, {"-kernels", "-isa", "-accel", "-tri"}, [&] {
    return commit_scene(device, scene_at, state, options.threads);
  });
  std::printf("scene: %zu triangles, %zu materials, %zu lights%s\n", scene_at.mesh.size(),
              scene_at.materials.size(), scene_at.lights.size(),
              scene_at.has_motion() ? ", moving" : "");
  std::printf("kernels: %s\n", device.kernels_summary(scene).c_str());
  flush_stdout();

  // Step 3: the camera, the renderer and the framebuffer as device objects, and the frame.
  const Handle camera =
      at_given_place(script, {"-vi", "-vp", "-vu", "-fov", "-radius", "-focaldistance"},
                     [&] { return commit_camera(device, at.camera); });
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
  for (const ScriptOutput& out : outputs) {
    device.write_image(framebuffer, out.path.string(), at.tone);
    std::printf("wrote %s\n", out.path.string().c_str());
  }
  return stats.stopped() ? interrupt.exit_status() : 0;
}

}  // namespace

void print_render_options(std::FILE* out) {
  std::fputs("usage: rtk render [-c SCENE.ecs] [options] -o IMAGE   (or rtk -c SCENE.ecs [options] "
             "[-o IMAGE])\n"
             "options of the scripts and of the command line, read left to right (one dash or "
             "two):\n",
             out);
  for (const ScriptOptionHelp& o : script_option_help())
    std::fprintf(out, "  %-18s %-26s %s\n", std::string(o.name).c_str(), std::string(o.arguments).c_str(),
                 std::string(o.meaning).c_str());
  std::fputs("the viewer's own (rtk view, or rtk -c SCENE.ecs without -o):\n"
             "  -frames            N                          close the window after N frames\n"
             "  -screenshot        FILE.png                   with -frames: save the window then\n"
             "  -help                                         this list\n",
             out);
}

}  // namespace rtk::cli
