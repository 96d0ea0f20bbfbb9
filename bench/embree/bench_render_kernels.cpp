// The guide's second way to compare: RTK's path tracer on RTK's kernels and on Embree 3's
// (`rtk render -kernels rtk|embree`), same scene, camera, seed and samples, one thread, in one
// run. Besides the renderer's samples/s and rays/s, the counters say how long the kernels
// themselves took: kernel_share (their share of the tile tasks' time) and kernel_Mrays/s (rays
// per second of time inside the ray queries alone), which is where the two differ.
// Run: RTK_SCENES=<shared/scenes> build/bench/bench_render_kernels
// --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include "14_pathtracer/render.h"
#include "render_kernels/choose_kernels.h"
#include "render_scenes.h"

using namespace rtk;

namespace {

constexpr const char* kKernels[] = {"rtk", "embree"};

// 128 x 128 pixels, `spp` samples per pixel per iteration, one thread for the build and the
// render; argument 0: the kernels (0 RTK's default for the CPU, 1 Embree).
void render(benchmark::State& state, const RenderScene& scene, RenderOptions options, int spp) {
  options.width = options.height = 128;
  options.spp = spp;
  options.threads = 1;
  AccelConfig config;
  config.threads = 1;
  const RenderKernels kernels = make_render_kernels(scene, config, kKernels[state.range(0)]);
  const Renderer renderer(scene, *kernels.kernels, options);
  Framebuffer fb(options.width, options.height);
  RenderStats total;
  uint32_t pass = 0;
  for (auto _ : state) {
    total += renderer.render_pass(fb, pass, static_cast<uint32_t>(spp));
    pass += static_cast<uint32_t>(spp);
  }
  state.SetItemsProcessed(static_cast<int64_t>(total.samples));  // camera samples per second
  state.counters["Mrays/s"] =
      benchmark::Counter(double(total.rays) * 1e-6, benchmark::Counter::kIsRate);
  state.counters["kernel_share"] = total.kernel_share();
  state.counters["kernel_Mrays/s"] =
      total.kernel_seconds > 0 ? double(total.rays) * 1e-6 / total.kernel_seconds : 0;
  state.counters["rays/sample"] = double(total.rays) / double(total.samples);
  state.SetLabel(kernels.kernels->name());
}

void BM_cornell_box(benchmark::State& state) {
  const SceneScript& script = bench::cornell_box_script();
  render(state, script.scene, script.options, 4);
}

// A real mesh, grey under a sky: argument 1 picks it.
void BM_mesh(benchmark::State& state) {
  struct Shared {
    const char* file;
    Vec3f view;
  };
  static const Shared meshes[] = {{"bunny_stanford_full/stanford-bunny.obj", {0.0f, 0.2f, -1.2f}},
                                  {"sponza_dabrovic/sponza.obj", {-0.35f, -0.11f, 0.0f}}};
  const Shared& mesh = meshes[state.range(1)];
  const auto path = bench::shared_scene(mesh.file);
  if (!path) {
    state.SkipWithError("set RTK_SCENES to the shared scenes folder");
    return;
  }
  static std::optional<RenderScene> scenes[2];
  if (!scenes[state.range(1)])
    scenes[state.range(1)] = bench::grey_mesh_under_sky(*path, mesh.view);
  RenderOptions options;
  options.max_depth = 8;
  render(state, *scenes[state.range(1)], options, 2);
}

BENCHMARK(BM_cornell_box)
    ->DenseRange(0, 1)
    ->ArgName("kernels")
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_mesh)
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->ArgNames({"kernels", "mesh"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
