// Chapter 11 benchmarks: the cost of a sample dimension (independent vs Owen-scrambled Sobol),
// of a bin drawn from a table, and of a camera ray. Run: build/chapters/11_sampling/ch11_bench
#include <benchmark/benchmark.h>

#include <vector>

#include "11_sampling/camera.h"
#include "11_sampling/distribution.h"
#include "11_sampling/rng.h"
#include "11_sampling/sampler.h"
#include "11_sampling/sobol.h"

using namespace rtk;

namespace {

// One pixel sample = start_pixel_sample + the film position + 7 more 2D dimensions, about
// what a path of three bounces with light sampling consumes.
void BM_pixel_sample(benchmark::State& state) {
  Sampler sampler(static_cast<SamplerType>(state.range(0)), 7);
  uint32_t index = 0;
  float sink = 0;
  for (auto _ : state) {
    sampler.start_pixel_sample(static_cast<int>(index & 63), static_cast<int>(index >> 6 & 63),
                               index);
    ++index;
    for (int d = 0; d < 8; ++d) {
      const Vec2f u = sampler.get_2d();
      sink += u.x + u.y;
    }
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations() * 8);  // 2D points
  state.SetLabel(state.range(0) == 0 ? "independent" : "sobol");
}
BENCHMARK(BM_pixel_sample)
    ->Arg(static_cast<int>(SamplerType::independent))
    ->Arg(static_cast<int>(SamplerType::sobol));

// One Sobol 2D point alone, as the definition computes it (sobol_owen_reference) and as the
// sampler does (sobol_owen), on the same indices and seeds.
void BM_sobol_point(benchmark::State& state) {
  const bool fast = state.range(0) == 1;
  uint32_t index = 0, sink = 0;
  Pcg32 rng(3);
  SobolSeeds seeds{rng.next_u32(), rng.next_u32(), rng.next_u32()};
  for (auto _ : state) {
    const uint32_t i = index++ & 255u;
    seeds.shuffle += 0x9e3779b9u;  // another dimension each time
    const std::array<uint32_t, 2> p =
        fast ? sobol_owen(reverse_bits(i), seeds) : sobol_owen_reference(i, seeds);
    sink += p[0] ^ p[1];
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(fast ? "fast" : "definition");
}
BENCHMARK(BM_sobol_point)->Arg(0)->Arg(1);

// A bin drawn from a table of N values, as a renderer chooses one of N lights per bounce: the
// sample points are random, so a search whose comparisons branch guesses half of them wrong.
void BM_discrete_sample(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Pcg32 rng(5);
  std::vector<float> values(n);
  for (float& v : values) v = 0.5f + rng.next_float();
  const Distribution1D table(values);
  float pmf_sum = 0;
  int bin_sum = 0;
  for (auto _ : state) {
    float pmf;
    bin_sum += table.sample_discrete(rng.next_float(), &pmf);
    pmf_sum += pmf;
  }
  benchmark::DoNotOptimize(bin_sum);
  benchmark::DoNotOptimize(pmf_sum);
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_discrete_sample)->Arg(2)->Arg(16)->Arg(1024);

void BM_camera_ray(benchmark::State& state) {
  CameraParams p;
  p.position = {278, 273, -800};
  p.look_at = {278, 273, 0};
  p.fov_degrees = 37;
  p.lens_radius = static_cast<float>(state.range(0));
  const Camera camera(p);
  float x = 0, sink = 0;
  for (auto _ : state) {
    x += 0.618034f;
    if (x > 1) x -= 1;
    const Ray r = camera.generate_ray({x, 1 - x}, {x, x}, x);
    sink += r.dir.x;
  }
  benchmark::DoNotOptimize(sink);
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(state.range(0) == 0 ? "pinhole" : "thin lens");
}
BENCHMARK(BM_camera_ray)->Arg(0)->Arg(10);

}  // namespace
