// `rtk render`: reads the guide's options (command scripts with -c, then the command line
// itself, left to right), hands the scene to chapter 14's device, which builds the kernels the
// scene needs, renders a frame with chapter 13's path tracer and writes every -o image. Also
// the guide's short form `rtk -c scene.ecs -o out.png`.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <string>
#include <thread>

#include "14_device/device.h"
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

// [ch13-time]
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
// [ch13-time]

}  // namespace

int run_render(std::span<const std::string_view> args, bool viewer_without_output) {
  // Step 1: the scene and options, scripts and command line read left to right.
  SceneScript script;
  script.options.progress = true;
  ViewerOptions viewer;  // -frames, -screenshot: the viewer's own (chapter 15)
  const std::vector<std::string_view> script_args = take_viewer_options(args, viewer);
  read_script_args(script_args, script, [](const std::string& w) { std::fprintf(stderr, "rtk render: warning: %s\n", w.c_str()); });
  // No -o: the guide's interactive mode, the viewer (chapter 15), for `rtk -c` and `rtk view`.
  if (script.outputs.empty() && viewer_without_output) {
    if (script.time_limit > 0 || !script.reference.empty())
      throw UsageError("-time and -reference are for rendering to a file (-o), not the viewer");
    return run_viewer(script, viewer);
  }
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
  // -reference: the converged image is read now, so that an unreadable one stops the command
  // before any work; its size is checked against -size here too.
  Image reference;
  if (!script.reference.empty()) {
    try {
      reference = read_image(script.reference.string());
    } catch (const std::exception& e) {
      throw UsageError(std::string("-reference: ") + e.what());
    }
    if (reference.width != options.width || reference.height != options.height)
      throw UsageError("-reference: " + script.reference.string() + " is " +
                       std::to_string(reference.width) + " x " + std::to_string(reference.height) +
                       ", the render " + std::to_string(options.width) + " x " +
                       std::to_string(options.height));
    try {
      relative_rms_error(reference, reference);  // refuses a black reference, or one not finite
    } catch (const std::invalid_argument& e) {
      throw UsageError("-reference: " + script.reference.string() + ": " + e.what());
    }
  }
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
  for (const auto& out : script.outputs) {
    device.write_image(framebuffer, out.string(), script.tone);
    std::printf("wrote %s\n", out.string().c_str());
  }
  return stats.stopped() ? interrupt.exit_status() : 0;
}

}  // namespace rtk::cli
