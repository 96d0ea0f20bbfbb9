// `rtk trace`: builds RTK's structure for a scene and traces a .rays file through it, writing
// .hits (closest hits) or .occl (occlusion) and one JSON line per step on stdout
// (shared/ray-replay.md). Times are the median of -repeat runs.
#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "01_base/timer.h"
#include "10_kernel_api/accel.h"
#include "10_kernel_api/motion_accel.h"
#include "commands.h"
#include "io/obj_loader.h"
#include "io/replay_files.h"
#include "json_line.h"
#include "options.h"
#include "output_checks.h"

namespace rtk::cli {

namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double per_second_millions(size_t count, double seconds) {
  return seconds > 0 ? double(count) / seconds * 1e-6 : 0.0;
}

}  // namespace

int run_trace(std::span<const std::string_view> args) {
  const Options options(
      "trace", args,
      {.with_value = {"i", "motion", "rays", "hits", "occl", "accel", "tri", "isa", "order", "packets", "threads", "repeat"}, .flags = {}});
  // Step 1: the command line, all of it checked before any file is read.
  const std::string scene = options.required("i");
  // -motion: the same scene at shutter time 1 (chapter 8); each ray's time picks the moment.
  const std::string motion_scene = options.get("motion", "");
  if (options.has("motion") && motion_scene.empty()) throw options.error("-motion: empty file name");
  const std::string rays_file = options.required("rays");
  const bool want_hits = options.has("hits"), want_occl = options.has("occl");
  if (want_hits == want_occl)
    throw options.error(want_hits ? "options -hits and -occl exclude each other"
                                  : "missing option -hits or -occl (what to write)");
  const std::string output = want_hits ? options.required("hits") : options.required("occl");
  check_output_option(want_hits ? "hits" : "occl", output);
  const std::pair<const char*, std::string> inputs[] = {{"the input of -i", scene},
                                                        {"the input of -motion", motion_scene},
                                                        {"the input of -rays", rays_file}};
  for (const auto& [role, input] : inputs)
    if (!input.empty()) check_not_an_input(want_hits ? "hits" : "occl", output, role, input);
  AccelConfig config;
  config.accel = options.get("accel", "");
  config.tri = options.get("tri", "");
  if (options.has("isa")) config.isa = choose_isa(options.required("isa"));
  config.threads = int(options.get_count("threads", 1, 1, 1024));
  // -order: whether a batch is traced sorted (chapter 9); the answers are the same.
  const std::string order = options.get("order", "auto");
  if (order == "auto") config.order = RayOrderPolicy::Mode::automatic;
  else if (order == "sorted") config.order = RayOrderPolicy::Mode::always;
  else if (order == "given") config.order = RayOrderPolicy::Mode::never;
  else throw options.error("-order: '" + order + "' is not auto, sorted or given");
  // -packets: whether a batch traced as given goes in packets where its rays allow (chapter 9).
  const std::string packets = options.get("packets", "on");
  if (packets == "on" || packets == "off") config.packets = packets == "on";
  else throw options.error("-packets: '" + packets + "' is not on or off");
  const size_t repeat = options.get_count("repeat", 1, 1, 1000);
  // Refuses an unknown -accel or -tri before a large scene is loaded (with -motion, the motion
  // structure's strings are checked when it is built).
  const bool motion_accel = config.accel == kMotionAccel || config.accel.starts_with(std::string(kMotionAccel) + ".");
  if (motion_scene.empty() && !motion_accel) {
    resolve_config(config);
  } else {
    AccelConfig checked = config;
    checked.accel.clear(), checked.tri.clear();
    resolve_config(checked);
  }

  // Step 2: the rays (a damaged file is refused before the scene is read) and the scene.
  const std::vector<Ray> rays = read_rays(rays_file);
  // Each scene file is loaded and reported as one JSON line.
  auto load = [](const std::string& file) {
    Timer timer;
    TriangleMesh mesh = load_obj(file);
    JsonLine()
        .add("op", "load")
        .add("file", file)
        .add("vertices", mesh.vertices.size())
        .add("triangles", mesh.size())
        .add("seconds", timer.seconds())
        .print();
    return mesh;
  };
  const TriangleMesh mesh = load(scene);
  TriangleMesh mesh1;
  if (!motion_scene.empty()) {
    mesh1 = load(motion_scene);
    check_motion_meshes(mesh, mesh1, scene, motion_scene);
  }

  // Step 3: build, -repeat times; the last structure is kept.
  std::vector<double> build_seconds;
  std::optional<Accel> accel;
  for (size_t r = 0; r < repeat; ++r) {
    accel.reset();
    if (motion_scene.empty()) accel.emplace(mesh, config);
    else accel.emplace(mesh, mesh1, config);
    build_seconds.push_back(accel->info().build_seconds);
  }
  const AccelInfo& info = accel->info();
  const double build = median(build_seconds);
  JsonLine()
      .add("op", "build")
      .add("accel", info.accel)
      .add("tri", info.tri)
      .add("isa", isa_name(info.isa))
      .add("triangles", info.triangles)
      .add("seconds", build)
      .add("mtris_per_s", per_second_millions(info.triangles, build))
      .add("bytes", info.bytes)
      .add("threads", info.threads)
      .print();

  // Step 4: trace, -repeat times; every run writes the same answers.
  std::vector<double> trace_seconds;
  std::vector<Hit> hits(want_hits ? rays.size() : 0);
  std::vector<uint8_t> occluded(want_occl ? rays.size() : 0);
  for (size_t r = 0; r < repeat; ++r) {
    const Timer timer;
    if (want_hits) accel->intersect(rays, hits);
    else accel->occluded(rays, occluded);
    trace_seconds.push_back(timer.seconds());
  }
  const double seconds = median(trace_seconds);
  JsonLine line;
  line.add("op", want_hits ? "intersect" : "occluded")
      .add("rays", rays.size())
      .add("seconds", seconds)
      .add("mrays_per_s", per_second_millions(rays.size(), seconds))
      .add("threads", info.threads);
  if (want_hits) {
    line.add("hits", size_t(std::count_if(hits.begin(), hits.end(), [](const Hit& h) { return h.found(); })));
    write_hits(output, hits);
  } else {
    line.add("occluded", size_t(std::count(occluded.begin(), occluded.end(), uint8_t(1))));
    write_occlusion(output, occluded);
  }
  line.add("repeat", repeat).add("output", output).print();
  return 0;
}

}  // namespace rtk::cli
