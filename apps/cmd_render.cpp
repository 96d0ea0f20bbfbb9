// `rtk render`: reads the guide's options (command scripts with -c, then the command line
// itself, left to right), hands the scene to chapter 15's device, which builds the kernels the
// scene needs, renders a frame with chapter 14's path tracer and writes every -o image. Also
// the guide's short form `rtk -c scene.ecs -o out.png`.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include "15_device/device.h"
#include "commands.h"
#include "device_objects.h"
#include "image/image_error.h"
#include "image/image_io.h"
#include "interrupt.h"
#include "options.h"
#include "output_checks.h"
#include "render_kernels/choose_kernels.h"
#include "scene/scene_script.h"
#include "viewer.h"

namespace rtk::cli {

namespace {
int render_output(SceneScript& script, std::span<const ScriptOutput> outputs, const Image& reference);

// [ch14-time]
// -time: progressive passes until the time is spent. The first pass is one sample per pixel;
// each later pass takes as many samples as the time per sample so far says will fit in what is
// left, but at most as many as were done (so that a wrong first estimate is corrected before
// it costs much). The render ends when not one more sample fits. Passes over consecutive
// sample ranges add up to exactly the image of one pass over all of them, so the result is the
// image `-spp N` gives, N being the samples reached (written back into options.spp).
RenderStats render_for(Device& device, const Handle& renderer, const Handle& camera,
                       const Handle& scene, const Handle& framebuffer, double seconds,
                       RenderOptions& options, const std::atomic<bool>* stop) {
  constexpr uint32_t kMaxSamples = 1u << 24;
  RenderStats total;
  uint32_t done = 0;
  while (done < kMaxSamples) {
    uint32_t count = 1;
    if (done > 0) {
      const double per_sample = total.seconds / done;
      const double fit = per_sample > 0 ? (seconds - total.seconds) / per_sample : done;
      if (!(fit >= 1.0)) break;
      count = static_cast<uint32_t>(std::min<double>({fit, double(done), double(kMaxSamples - done)}));
    }
    const RenderStats pass = device.render_samples(renderer, camera, scene, framebuffer, done, count, stop);
    total += pass;
    if (pass.stopped()) break;
    done += count;
  }
  options.spp = static_cast<int>(done);
  return total;
}
// [ch14-time]

}  // namespace

int run_render(std::span<const std::string_view> args, bool viewer_without_output) {
  // Step 1: the scene and options, scripts and command line read left to right.
  SceneScript script;
  script.options.progress = true;
  ViewerOptions viewer;  // -frames, -screenshot: the viewer's own (chapter 16)
  const std::vector<std::string_view> script_args = take_viewer_options(args, viewer);
  read_script_args(script_args, script, [](const std::string& w) { std::fprintf(stderr, "rtk render: warning: %s\n", w.c_str()); });
  // No image may be written over a file the command reads: a script, a mesh, an image the
  // scene shows, the reference.
  auto check_not_read = [&](const char* option, const std::string& output) {
    for (const std::filesystem::path& input : script.files)
      check_not_an_input(option, output, "a file the scene reads", input);
    if (!script.reference.empty())
      check_not_an_input(option, output, "the image of -reference", script.reference);
  };
  // No -o: the guide's interactive mode, the viewer (chapter 16), for `rtk -c` and `rtk view`.
  if (script.output_states.empty() && viewer_without_output) {
    if (script.time_limit > 0 || !script.reference.empty())
      throw UsageError("-time and -reference are for rendering to a file (-o), not the viewer");
    if (!viewer.screenshot.empty()) check_not_read("screenshot", viewer.screenshot);
    return run_viewer(script, viewer);
  }
  if (script.output_states.empty())
    throw UsageError("no -o FILE given: rtk render writes images (.png .tga .ppm .hdr .pfm .exr); "
                     "`rtk -c SCENE.ecs` or `rtk view` without -o opens the interactive viewer");
  if (viewer.frames > 0) throw UsageError("-frames and -screenshot belong to the viewer (no -o)");
  // Every -o was checked where it was read (its folder exists and may be written); its format
  // is checked here, before any work.
  for (const ScriptOutput& out : script.output_states) {
    try {
      image_format_from_path(out.path.string());
    } catch (const std::exception& e) {
      throw UsageError(std::string("-o: ") + e.what());
    }
    check_not_read("o", out.path.string());
  }
  // -reference: the converged image is read before any work, so that an unreadable one stops
  // the command at once, and its size is checked against every image the script renders.
  Image reference;
  if (!script.reference.empty()) {
    try {
      reference = read_image(script.reference.string());
    } catch (const std::exception& e) {
      throw UsageError(std::string("-reference: ") + e.what());
    }
    for (const ScriptOutput& out : script.output_states)
      if (reference.width != out.options.width || reference.height != out.options.height)
        throw UsageError("-reference: " + script.reference.string() + " is " +
                         std::to_string(reference.width) + " x " + std::to_string(reference.height) +
                         ", the render " + std::to_string(out.options.width) + " x " +
                         std::to_string(out.options.height));
    try {
      relative_rms_error(reference, reference);  // refuses a black reference, or one not finite
    } catch (const std::invalid_argument& e) {
      throw UsageError("-reference: " + script.reference.string() + ": " + e.what());
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
    status = render_output(script, {script.output_states.data() + first, last - first}, reference);
    first = last;
  }
  return status;
}

namespace {

// Renders one image, the state of `outputs.front()`, and writes it to every file of `outputs`.
int render_output(SceneScript& script, std::span<const ScriptOutput> outputs, const Image& reference) {
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

  // Step 2: the device (chapter 15), whose scenes are traced by the kernels -kernels names,
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
  // SIGINT or SIGTERM from here on stops the render at the next tile (chapter 14), and what
  // was rendered is written.
  const Interrupt interrupt;
  const RenderStats stats =
      script.time_limit > 0
          ? render_for(device, renderer, camera, scene, framebuffer, script.time_limit, options, interrupt.flag())
          : device.render_frame(renderer, camera, scene, framebuffer, interrupt.flag());
  if (stats.stopped())
    std::fprintf(stderr,
                 "rtk render: interrupted by %s: %llu of %llu tiles rendered; writing them\n",
                 interrupt.signal_name(), static_cast<unsigned long long>(stats.tiles_done),
                 static_cast<unsigned long long>(stats.tiles));
  std::printf("render: %dx%d, %d spp%s, depth %d, %d threads, seed %u: %.3f s, %.3g samples/s, "
              "%.3g Mrays/s, %.0f%% of thread time in ray queries\n",
              options.width, options.height, options.spp,
              script.time_limit > 0 ? " reached in the time given" : "", options.max_depth, options.threads,
              options.seed, stats.seconds, stats.samples_per_second(), stats.rays_per_second() * 1e-6,
              100.0 * stats.kernel_share());
  if (stats.invalid_samples > 0)
    std::fprintf(stderr, "rtk render: warning: %llu samples were not finite and were dropped\n",
                 static_cast<unsigned long long>(stats.invalid_samples));
  if (!script.reference.empty()) {
    double error = 0;
    try {
      error = relative_rms_error(device.read_image(framebuffer), reference);
    } catch (const std::invalid_argument& e) {
      throw UsageError("-reference: " + script.reference.string() + ": " + e.what());
    }
    std::printf("error: %.6g relative RMS against %s\n", error, script.reference.string().c_str());
  }
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
