// RTK against Embree 3 on the same rays: for each scene and ray kind, single-threaded tracing
// speed (Mrays/s) of Embree's rtcIntersect1/rtcOccluded1 and of RTK's variants through the
// public API, their ratio, the agreement of their answers, and build speed and memory.
//
//   build/bench/embree/bench_embree [--rays=N] [--threads=N] [--scenes=A.obj,B.obj|DIR]
//                                   [--procedural=0|1|NAME] [--size=F] [--rtk=default|all]
//                                   [--embree-isa=sse4.2|avx2|...] [--builds-only | --scaling]
//                                   [benchmark options]
//   RTK_SCENES=../shared/scenes/bunny_stanford_full build/bench/embree/bench_embree
//
// Benchmark names: build/SCENE/BUILDER and trace/SCENE/KIND/TRACER, where BUILDER is "embree"
// or "rtk:ACCEL:TRI" (RTK's builders are the same for every ISA) and TRACER "embree" or
// "rtk:ISA:ACCEL:TRI" (RTK's default, which sorts large incoherent batches as chapter 9 does;
// ":given" appended: the best ISA's default tracing every batch as given), and
// trace/SCENE/KIND/embree:rtk-order pairs Embree on the rays as given with Embree on the same
// rays sorted in RTK's order (counter order_gain). Each scene's Embree benchmarks run before RTK's and keep Embree's
// answers, against which RTK's are checked. RTK's ratio to Embree (the counter rtk_vs_embree)
// is measured in pairs: every iteration of an RTK benchmark runs Embree's build or trace of
// the same input too, right before RTK's, and the ratio is that of the two sums of times. The
// machine is shared and noisy, and whatever slows it at a given moment then slows both.
// bench/embree/make_table.sh turns the JSON output into the markdown table. --builds-only runs
// nothing but RTK's default build paired with Embree's, per scene (scripts/measure.sh
// embree_build runs it on one and two threads, on the real meshes and on terrains of 1M, 4M
// and 16M triangles). --scaling runs nothing but the default build with one thread and with
// --threads, back to back in every iteration, and Embree's likewise: each one's gain from the
// threads, measured in pairs (counters rtk_scaling and embree_scaling).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "01_base/timer.h"
#include "10_kernel_api/accel.h"
#include "embree/embree_scene.h"
#include "io/obj_loader.h"
#include "replay/compare.h"
#include "replay/ray_generator.h"
#include "testing/scenes.h"

namespace {

using namespace rtk;

// Step 1: what to measure, from the command line.
struct Settings {
  size_t rays = size_t(1) << 18;
  int threads = 1;  // build threads of both; tracing is always one thread
  std::string procedural = "1";  // "1": every generated scene, "0": none, else only the one named
  bool all_rtk = false;
  std::string embree_isa;  // empty: Embree's best for the CPU; else its max_isa option
  double size = 1.0;       // scale of the procedural scenes' triangle counts
  bool builds_only = false;  // only RTK's default build, paired with Embree's
  bool scaling = false;      // only the default build's gain from --threads, paired as above

  std::vector<std::filesystem::path> scene_files;
};
Settings settings;

struct Scene {
  std::string name;
  TriangleMesh mesh;
  std::unique_ptr<EmbreeScene> embree;                  // built on first use
  std::map<std::string, std::unique_ptr<Accel>> rtk;          // by tracer name
  std::map<RayKind, std::vector<Ray>> rays;                    // made on first use
  std::map<RayKind, std::vector<Hit>> embree_hits;             // Embree's answers, for agreement
  std::map<RayKind, std::vector<uint8_t>> embree_occluded;
};
std::vector<std::unique_ptr<Scene>> scenes;

// The kinds of ray and the query each one makes: shadow rays ask for occlusion.
constexpr RayKind kKinds[] = {RayKind::primary, RayKind::diffuse, RayKind::shadow};
bool is_occlusion(RayKind kind) { return kind == RayKind::shadow; }

const std::vector<Ray>& rays_for(Scene& s, RayKind kind) {
  auto& rays = s.rays[kind];
  if (rays.empty()) rays = generate_rays(s.mesh, kind, settings.rays, 1);
  return rays;
}

EmbreeScene& embree_for(Scene& s) {
  if (!s.embree) s.embree = std::make_unique<EmbreeScene>(s.mesh, settings.threads, settings.embree_isa);
  return *s.embree;
}

/// A builder's name: RTK's builders are the same for every ISA.
std::string builder_name(const AccelInfo& info) { return "rtk:" + info.accel + ":" + info.tri; }

std::string tracer_name(const AccelInfo& info) {
  return "rtk:" + std::string(isa_name(info.isa)) + ":" + info.accel + ":" + info.tri;
}
// The default traces large incoherent batches sorted (chapter 9); ":given" marks a
// configuration that traces every batch as given, the kernels alone.
std::string tracer_name(const AccelConfig& config) {
  return tracer_name(resolve_config(config)) + (config.order == RayOrderPolicy::Mode::never ? ":given" : "");
}

// The RTK configurations to compare: the default one of every ISA the CPU runs and, on the
// best ISA, every other structure (--rtk=all: every structure and layout on every ISA).
std::vector<AccelConfig> rtk_configs() {
  std::vector<AccelConfig> configs;
  std::vector<std::string> seen;
  auto add = [&](AccelConfig c) {
    try {
      const std::string name = tracer_name(c);
      const AccelInfo info = resolve_config(c);
      if (std::find(seen.begin(), seen.end(), name) != seen.end()) return;
      seen.push_back(name);
      c.accel = info.accel;
      c.tri = info.tri;
      configs.push_back(c);
    } catch (const std::invalid_argument&) {
      // not built into this RTK yet
    }
  };
  for (Isa isa : supported_isas()) add({.accel = "", .tri = "", .isa = isa, .threads = settings.threads});
  add({.accel = "", .tri = "", .isa = best_isa(), .threads = settings.threads, .order = RayOrderPolicy::Mode::never});
  for (Isa isa : supported_isas()) {
    if (!settings.all_rtk && isa != best_isa()) continue;
    for (const std::string& accel : supported_accels()) {
      if (settings.all_rtk) {
        for (const std::string& tri : supported_tris(accel))
          add({.accel = accel, .tri = tri, .isa = isa, .threads = settings.threads});
      } else {
        add({.accel = accel, .tri = "", .isa = isa, .threads = settings.threads});
      }
    }
  }
  return configs;
}

void set_rate(benchmark::State& state, double count, const char* name) {
  state.counters[name] = benchmark::Counter(count * 1e-6, benchmark::Counter::kIsIterationInvariantRate);
}

// Step 2: the benchmarks.
void build_embree(benchmark::State& state, Scene* s) {
  size_t bytes = 0, bvh_bytes = 0;
  for (auto _ : state) {
    Timer timer;
    EmbreeScene scene(s->mesh, settings.threads);
    state.SetIterationTime(timer.seconds());
    bytes = scene.total_bytes();
    bvh_bytes = scene.bvh_bytes();
  }
  set_rate(state, double(s->mesh.size()), "Mtris_per_s");
  state.counters["bytes_per_tri"] = double(bytes) / double(s->mesh.size());
  state.counters["bvh_bytes_per_tri"] = double(bvh_bytes) / double(s->mesh.size());
  state.counters["triangles"] = double(s->mesh.size());
  state.counters["threads"] = settings.threads;
}

// [bench-paired]
/// Runs `embree` and then `rtk` once per iteration, timing each, and reports RTK's time as the
/// iteration's. Returns RTK's speed relative to Embree's, the ratio of the sums of their times:
/// above 1, RTK is faster.
template <class Embree, class Rtk>
double paired_ratio(benchmark::State& state, const Embree& embree, const Rtk& rtk) {
  double embree_total = 0, rtk_total = 0;
  for (auto _ : state) {
    Timer embree_timer;
    embree();
    embree_total += embree_timer.seconds();
    Timer rtk_timer;
    rtk();
    const double seconds = rtk_timer.seconds();
    state.SetIterationTime(seconds);
    rtk_total += seconds;
  }
  return rtk_total > 0 ? embree_total / rtk_total : 0.0;
}
// [bench-paired]

void build_rtk(benchmark::State& state, Scene* s, AccelConfig config) {
  size_t bytes = 0, embree_bytes = 0;
  state.counters["rtk_vs_embree"] = paired_ratio(
      state, [&] { embree_bytes = EmbreeScene(s->mesh, settings.threads).total_bytes(); },
      [&] { bytes = Accel(s->mesh, config).info().bytes; });
  set_rate(state, double(s->mesh.size()), "Mtris_per_s");
  state.counters["bytes_per_tri"] = double(bytes) / double(s->mesh.size());
  state.counters["embree_bytes_per_tri"] = double(embree_bytes) / double(s->mesh.size());
  state.counters["triangles"] = double(s->mesh.size());
  state.counters["threads"] = settings.threads;
}

// [bench-scaling]
/// What a second thread (or more) gains, measured in pairs as rtk_vs_embree is: every iteration
/// builds the scene with one thread and then with settings.threads, Embree's build before RTK's
/// each time, and each program's gain is the ratio of its two sums of times. Timed back to back,
/// the one-thread and the many-thread builds share whatever the machine is doing, where runs of
/// their own minutes apart do not.
void scaling_rtk(benchmark::State& state, Scene* s, AccelConfig config) {
  double embree_one = 0, embree_many = 0, rtk_one = 0, rtk_many = 0;
  AccelConfig one = config;
  one.threads = 1;
  auto time = [](double& total, const auto& build) {
    Timer timer;
    build();
    const double seconds = timer.seconds();
    total += seconds;
    return seconds;
  };
  for (auto _ : state) {
    time(embree_one, [&] { EmbreeScene(s->mesh, 1); });
    time(rtk_one, [&] { Accel(s->mesh, one); });
    time(embree_many, [&] { EmbreeScene(s->mesh, settings.threads); });
    state.SetIterationTime(time(rtk_many, [&] { Accel(s->mesh, config); }));
  }
  state.counters["rtk_scaling"] = rtk_many > 0 ? rtk_one / rtk_many : 0.0;
  state.counters["embree_scaling"] = embree_many > 0 ? embree_one / embree_many : 0.0;
  state.counters["rtk_vs_embree"] = rtk_many > 0 ? embree_many / rtk_many : 0.0;
  set_rate(state, double(s->mesh.size()), "Mtris_per_s");
  state.counters["triangles"] = double(s->mesh.size());
  state.counters["threads"] = settings.threads;
}
// [bench-scaling]

/// Times every iteration itself (manual time) and reports the rate of rays.
template <class Trace>
void timed_trace(benchmark::State& state, size_t rays, const Trace& trace) {
  for (auto _ : state) {
    Timer timer;
    trace();
    state.SetIterationTime(timer.seconds());
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays));
  set_rate(state, double(rays), "Mrays_per_s");
}

void trace_embree(benchmark::State& state, Scene* s, RayKind kind) {
  const std::vector<Ray>& rays = rays_for(*s, kind);
  const EmbreeScene& embree = embree_for(*s);
  if (is_occlusion(kind)) {
    std::vector<uint8_t>& out = s->embree_occluded[kind];
    out.assign(rays.size(), 0);
    timed_trace(state, rays.size(), [&] { embree.occluded(rays, out); });
  } else {
    std::vector<Hit>& out = s->embree_hits[kind];
    out.assign(rays.size(), Hit{});
    timed_trace(state, rays.size(), [&] { embree.intersect(rays, out); });
  }
}

// Embree on the batch as given and on a copy sorted in RTK's order (chapter 9; the sort is not
// timed): how much of RTK's lead on a kind of ray the order alone would give Embree.
// order_gain = time as given / time in RTK's order.
void trace_embree_in_rtk_order(benchmark::State& state, Scene* s, RayKind kind) {
  const std::vector<Ray>& rays = rays_for(*s, kind);
  const EmbreeScene& embree = embree_for(*s);
  RayOrderPolicy always;
  always.mode = RayOrderPolicy::Mode::always;
  SortedRays sorted;
  sort_rays(rays, RayOrderKey(s->mesh.bounds()), always, sorted);
  std::vector<Hit> hits(rays.size());
  std::vector<uint8_t> occluded(rays.size());
  const double gain = paired_ratio(
      state,
      [&] { is_occlusion(kind) ? embree.occluded(rays, occluded) : embree.intersect(rays, hits); },
      [&] { is_occlusion(kind) ? embree.occluded(sorted.rays, occluded) : embree.intersect(sorted.rays, hits); });
  state.counters["order_gain"] = gain;
  set_rate(state, double(rays.size()), "Mrays_per_s");
}

void trace_rtk(benchmark::State& state, Scene* s, RayKind kind, AccelConfig config) {
  const std::vector<Ray>& rays = rays_for(*s, kind);
  const std::string name = tracer_name(config);
  auto& accel = s->rtk[name];
  if (!accel) accel = std::make_unique<Accel>(s->mesh, config);
  const EmbreeScene& embree = embree_for(*s);
  double agree = -1;
  if (is_occlusion(kind)) {
    std::vector<uint8_t> out(rays.size()), embree_out(rays.size());
    state.counters["rtk_vs_embree"] = paired_ratio(
        state, [&] { embree.occluded(rays, embree_out); }, [&] { accel->occluded(rays, out); });
    const auto& ref = s->embree_occluded[kind];
    if (ref.size() == out.size()) agree = compare_occlusion_arrays(out, ref).agree_percent();
  } else {
    std::vector<Hit> out(rays.size()), embree_out(rays.size());
    state.counters["rtk_vs_embree"] = paired_ratio(
        state, [&] { embree.intersect(rays, embree_out); }, [&] { accel->intersect(rays, out); });
    const auto& ref = s->embree_hits[kind];
    if (ref.size() == out.size()) agree = compare_hit_arrays(out, ref, 1e-4, 0, rays).agree_percent();
  }
  state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(rays.size()));
  set_rate(state, double(rays.size()), "Mrays_per_s");
  if (agree >= 0) state.counters["agree_pct"] = agree;
}

// Step 3: the scenes: procedural ones made here, real ones read from OBJ files.
void add_scene(std::string name, TriangleMesh mesh) {
  auto s = std::make_unique<Scene>();
  s->name = std::move(name);
  s->mesh = std::move(mesh);
  scenes.push_back(std::move(s));
}

void add_scene_files(const std::string& list) {
  size_t start = 0;
  while (start <= list.size()) {
    const size_t end = std::min(list.find_first_of(",:", start), list.size());
    const std::filesystem::path path = list.substr(start, end - start);
    start = end + 1;
    if (path.empty()) continue;
    if (std::filesystem::is_directory(path)) {
      std::vector<std::filesystem::path> found;
      for (const auto& entry : std::filesystem::recursive_directory_iterator(path))
        if (entry.path().extension() == ".obj") found.push_back(entry.path());
      std::sort(found.begin(), found.end());
      settings.scene_files.insert(settings.scene_files.end(), found.begin(), found.end());
    } else {
      settings.scene_files.push_back(path);
    }
  }
}

/// Exits with a message naming the option unless `text` is a whole number in [1, max].
size_t count_option(const char* option, const char* text, size_t max) {
  size_t n = 0;
  const char* end = text + std::strlen(text);
  const auto [rest, error] = std::from_chars(text, end, n);
  if (error != std::errc() || rest != end || n < 1 || n > max) {
    std::fprintf(stderr, "bench_embree: %s wants a whole number from 1 to %zu, not '%s'\n", option, max, text);
    std::exit(2);
  }
  return n;
}

// Reads and removes this program's own options from argv, leaving Google Benchmark's.
void parse_settings(int& argc, char** argv) {
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&](const char* prefix) -> const char* {
      return arg.rfind(prefix, 0) == 0 ? argv[i] + std::string(prefix).size() : nullptr;
    };
    if (const char* v = value("--rays=")) settings.rays = count_option("--rays", v, size_t(1) << 30);
    else if (const char* v = value("--threads=")) settings.threads = int(count_option("--threads", v, 1024));
    else if (const char* v = value("--scenes=")) add_scene_files(v);
    else if (const char* v = value("--procedural=")) settings.procedural = v;
    else if (const char* v = value("--rtk=")) {
      if (std::strcmp(v, "all") != 0 && std::strcmp(v, "default") != 0) {
        std::fprintf(stderr, "bench_embree: --rtk must be default or all\n");
        std::exit(2);
      }
      settings.all_rtk = std::strcmp(v, "all") == 0;
    }
    else if (const char* v = value("--embree-isa=")) settings.embree_isa = v;
    else if (const char* v = value("--size=")) settings.size = std::strtod(v, nullptr);
    else if (arg == "--builds-only") settings.builds_only = true;
    else if (arg == "--scaling") settings.scaling = true;
    else argv[kept++] = argv[i];
  }
  argc = kept;
  if (!(settings.size > 0.0) || settings.size > 1e4) {
    std::fprintf(stderr, "bench_embree: --size must be a scale factor in (0, 10000]\n");
    std::exit(2);
  }
  const char* generated[] = {"0", "1", "sphere", "soup", "terrain", "slivers"};
  if (std::find(std::begin(generated), std::end(generated), settings.procedural) == std::end(generated)) {
    std::fprintf(stderr, "bench_embree: --procedural must be 0, 1, sphere, soup, terrain or slivers\n");
    std::exit(2);
  }
  if (const char* env = std::getenv("RTK_SCENES")) add_scene_files(env);
}

}  // namespace

int main(int argc, char** argv) {
  parse_settings(argc, argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  {
    // --size=F scales every procedural scene's triangle count by about F (1: the default sizes).
    const double f = settings.size;
    auto scaled = [f](double n) { return std::max(2, int(std::lround(n))); };
    auto wanted = [](const char* name) { return settings.procedural == "1" || settings.procedural == name; };
    if (wanted("sphere")) add_scene("sphere", test::make_sphere(scaled(256 * std::sqrt(f)), scaled(512 * std::sqrt(f))));
    if (wanted("soup")) add_scene("soup", test::make_random_soup(scaled(100000 * f), 1, float(0.05 / std::sqrt(f))));
    if (wanted("terrain")) add_scene("terrain", test::make_terrain(scaled(256 * std::sqrt(f)), 1));
    if (wanted("slivers")) add_scene("slivers", test::make_slivers(scaled(2000 * f), 1));
  }
  for (const auto& file : settings.scene_files) {
    try {
      add_scene(file.stem().string(), load_obj(file));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_embree: skipping %s\n", e.what());
    }
  }

  const std::vector<AccelConfig> configs = rtk_configs();
  for (auto& owned : scenes) {
    Scene* s = owned.get();
    if (settings.scaling || settings.builds_only) {
      const AccelConfig c{.accel = "", .tri = "", .isa = best_isa(), .threads = settings.threads};
      const std::string name = std::string(settings.scaling ? "scaling/" : "build/") + s->name +
                               "/" + builder_name(resolve_config(c));
      benchmark::RegisterBenchmark(name.c_str(), settings.scaling ? scaling_rtk : build_rtk, s, c)
          ->UseManualTime()->Unit(benchmark::kMillisecond);
      continue;
    }
    benchmark::RegisterBenchmark(("build/" + s->name + "/embree").c_str(), build_embree, s)
        ->UseManualTime()->Unit(benchmark::kMillisecond);
    // The builders are not compiled per ISA: one build benchmark per structure and layout.
    std::vector<std::string> built;
    for (const AccelConfig& c : configs) {
      const std::string name = builder_name(resolve_config(c));
      if (std::find(built.begin(), built.end(), name) != built.end()) continue;
      built.push_back(name);
      benchmark::RegisterBenchmark(("build/" + s->name + "/" + name).c_str(), build_rtk, s, c)
          ->UseManualTime()->Unit(benchmark::kMillisecond);
    }
    for (RayKind kind : kKinds) {
      const std::string prefix = "trace/" + s->name + "/" + std::string(ray_kind_name(kind)) + "/";
      benchmark::RegisterBenchmark((prefix + "embree").c_str(), trace_embree, s, kind)
          ->UseManualTime()->Unit(benchmark::kMillisecond);
      for (const AccelConfig& c : configs)
        benchmark::RegisterBenchmark((prefix + tracer_name(c)).c_str(), trace_rtk, s, kind, c)
            ->UseManualTime()->Unit(benchmark::kMillisecond);
      benchmark::RegisterBenchmark((prefix + "embree:rtk-order").c_str(), trace_embree_in_rtk_order, s, kind)
          ->UseManualTime()->Unit(benchmark::kMillisecond);
    }
  }

  benchmark::AddCustomContext("embree", EmbreeScene::version() + ", RTC_BUILD_QUALITY_MEDIUM" +
                                            (settings.embree_isa.empty() ? std::string(", its best ISA for the CPU")
                                                                         : ", max_isa=" + settings.embree_isa));
  benchmark::AddCustomContext("build_threads", std::to_string(settings.threads));
  benchmark::AddCustomContext("trace_threads", "1");
  benchmark::AddCustomContext("rays_per_benchmark", std::to_string(settings.rays));
  benchmark::AddCustomContext("rtk_best_isa", std::string(isa_name(best_isa())));
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
