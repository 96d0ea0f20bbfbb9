// Chapter 14 benchmarks: the path tracer's throughput (camera samples and rays per second)
// and the share of its time spent in the ray kernels, on the Cornell box with each ISA's
// kernels and with each sampler, and on real meshes (the Stanford bunny and the Happy Buddha
// from $RTK_SCENES, skipped without it).
// Run: RTK_SCENES=<shared/scenes> build/bench/bench_render (bash scripts/measure.sh ch14)
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "01_base/cpu_features.h"
#include "14_pathtracer/render.h"
#include "14_pathtracer/accel_kernels.h"
#include "render_scenes.h"

using namespace rtk;

namespace {

void run(benchmark::State& state, const RenderScene& scene, RenderOptions options, const AccelConfig& config) {
  const AccelKernels kernels(scene, config);
  const Renderer renderer(scene, kernels, options);
  Framebuffer fb(options.width, options.height);
  RenderStats total;
  uint32_t pass = 0;
  for (auto _ : state) {
    total += renderer.render_pass(fb, pass, static_cast<uint32_t>(options.spp));
    pass += static_cast<uint32_t>(options.spp);
  }
  state.SetItemsProcessed(static_cast<int64_t>(total.samples));  // camera samples per second
  state.counters["Mrays/s"] = benchmark::Counter(double(total.rays) * 1e-6, benchmark::Counter::kIsRate);
  state.counters["rays/sample"] = double(total.rays) / double(total.samples);
  state.counters["kernel_share"] = total.kernel_share();
  state.SetLabel(kernels.name());
}

// The Cornell box, 128 x 128, 4 samples per pixel per iteration, depth 8; argument: the ISA
// (0 scalar .. 3 avx512), second argument: threads.
void BM_cornell_box(benchmark::State& state) {
  const Isa isa = static_cast<Isa>(state.range(0));
  if (!isa_supported(isa)) {
    state.SkipWithError("ISA not supported by this CPU");
    return;
  }
  const SceneScript& script = bench::cornell_box_script();
  RenderOptions options = script.options;
  options.width = options.height = 128;
  options.spp = 4;
  options.threads = static_cast<int>(state.range(1));
  AccelConfig config;
  config.isa = isa;
  run(state, script.scene, options, config);
}
BENCHMARK(BM_cornell_box)
    ->ArgsProduct({{0, 1, 2, 3}, {1}})
    ->Args({3, 2})
    ->ArgNames({"isa", "threads"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The Stanford bunny (69,451 triangles), grey matte under a uniform sky, which makes every
// path bounce in its folds; 128 x 128, 2 samples per pixel per iteration, one thread.
// A real mesh, grey matte under a uniform sky, seen from `view`: 128 x 128, 2 samples per pixel
// per iteration, one thread.
void render_mesh(benchmark::State& state, const char* file, Vec3f view) {
  const auto path = bench::shared_scene(file);
  if (!path) {
    state.SkipWithError("set RTK_SCENES to the shared scenes folder to render the real meshes");
    return;
  }
  // Loaded once: Google Benchmark calls a benchmark more than once to size its runs.
  static std::map<std::string, RenderScene> loaded;
  auto it = loaded.find(file);
  if (it == loaded.end()) it = loaded.emplace(file, bench::grey_mesh_under_sky(*path, view)).first;
  const RenderScene& scene = it->second;
  RenderOptions options;
  options.width = options.height = 128;
  options.spp = 2;
  options.max_depth = 8;
  options.threads = 1;
  run(state, scene, options, {});
}

void BM_bunny(benchmark::State& state) {
  render_mesh(state, "bunny_stanford_full/stanford-bunny.obj", {0.0f, 0.2f, -1.2f});
}
BENCHMARK(BM_bunny)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same Cornell box with the best ISA on one thread and each sampler of chapter 11
// (0 independent, 1 Sobol): what the sample generator costs the whole render.
void BM_cornell_box_sampler(benchmark::State& state) {
  const SceneScript& script = bench::cornell_box_script();
  RenderOptions options = script.options;
  options.width = options.height = 128;
  options.spp = 4;
  options.threads = 1;
  options.sampler = static_cast<SamplerType>(state.range(0));
  run(state, script.scene, options, {});
}
BENCHMARK(BM_cornell_box_sampler)->Arg(0)->Arg(1)->ArgName("sampler")->Unit(benchmark::kMillisecond)->UseRealTime();

// The Happy Buddha (100,000 triangles), as the bunny.
void BM_buddha(benchmark::State& state) {
  render_mesh(state, "happy_buddha_100k/buddha.obj", {0.0f, 0.0f, 1.1f});
}
BENCHMARK(BM_buddha)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
